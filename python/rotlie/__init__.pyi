# Type stub of the rotlie package (the extension rotlie._rotlie and the Python layer).
from fractions import Fraction
from os import PathLike
from collections.abc import Iterator, Mapping
from typing import Any, Literal, Sequence, TypeAlias, overload

import numpy as np
import numpy.typing as npt

__version__: str
Number: TypeAlias = str | Fraction | int | float
Scalar: TypeAlias = Literal["double", "long-double", "float128"]
ArrayLike: TypeAlias = npt.ArrayLike

class Body:
    def __init__(self, I1: Number, I2: Number, I3: Number) -> None: ...
    @classmethod
    def named(cls, name: str) -> Body: ...
    @property
    def moments(self) -> tuple[Fraction, Fraction, Fraction]: ...
    @property
    def text(self) -> str: ...

BodyLike: TypeAlias = Body | str | Sequence[Number]

class Scheme:
    @property
    def name(self) -> str: ...
    @property
    def splitting(self) -> Literal["ABC", "RS", "TV"]: ...
    @property
    def word(self) -> str: ...
    @property
    def permutation(self) -> str: ...
    @property
    def order(self) -> int: ...
    @property
    def symmetric(self) -> bool: ...
    @property
    def inertia(self) -> str: ...
    @property
    def source(self) -> str: ...
    @property
    def cost(self) -> int: ...
    @property
    def remainder_norm(self) -> float | None: ...
    @property
    def stages(self) -> list[tuple[str, str]]: ...
    @property
    def stage_names(self) -> list[str]: ...
    @property
    def coefficients(self) -> npt.NDArray[np.float64]: ...
    @property
    def text(self) -> str: ...
    def save(self, path: str | PathLike[str]) -> None: ...

def scheme(name: str, body: BodyLike | None = None, force: bool = False) -> Scheme: ...
def load_table(path: str | PathLike[str]) -> Scheme: ...
def solve(body: BodyLike, family: str = "N", perm: str | None = None, scheme: str | None = None,
          digits: int = 40, starts: int | None = None, seed: int | None = None) -> list[Scheme]: ...
@overload
def exact_flow(body: BodyLike, G0: ArrayLike, Q0: ArrayLike | None = None, t: ArrayLike = ..., scalar: Scalar = "double",
               error_estimate: Literal[False] = False) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]: ...
@overload
def exact_flow(body: BodyLike, G0: ArrayLike, Q0: ArrayLike | None = None, t: ArrayLike = ..., scalar: Scalar = "double",
               error_estimate: Literal[True] = ...) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64], Any]: ...
def integrate(scheme: Scheme | str, body: BodyLike, G0: ArrayLike, Q0: ArrayLike | None = None, h: Number = ...,
              steps: int = ..., scalar: Scalar = "double", force: bool = False
              ) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]: ...
def order(scheme: Scheme | str, body: BodyLike, G0: Sequence[Number] | str = (1, 1, 1), T: Number = 1, min_level: int = 1,
          max_level: int = 10, scalar: Scalar = "double", force: bool = False) -> OrderResult: ...

class Result(Mapping[str, Any]):
    fields: tuple[str, ...]
    def __getattr__(self, name: str) -> Any: ...
    def __getitem__(self, key: str) -> Any: ...
    def __iter__(self) -> Iterator[str]: ...
    def __len__(self) -> int: ...
    def to_dict(self) -> dict[str, Any]: ...

class MdTrajectory:
    every: int
    fields: tuple[str, ...]
    Q: npt.NDArray[np.float64]
    energy: npt.NDArray[np.float64]
    def __getattr__(self, name: str) -> npt.NDArray[np.float64]: ...  # t_ps, G, potential (md); t, omega_body (spin-orbit)

class MdResult(Result):
    integrator: str
    unstable: bool
    round_off_floor: bool
    @property
    def trajectory(self) -> MdTrajectory | None: ...

class OrderResult(Result):
    scheme: str
    scalar: str
    declared_order: int
    points: list[dict[str, float]]
    slope: float | None
    @property
    def h(self) -> npt.NDArray[np.float64]: ...
    @property
    def error(self) -> npt.NDArray[np.float64]: ...

class BestResult(Result):
    inertia: list[str]
    N: dict[str, Any]
    R: dict[str, Any]
    P: dict[str, Any]
    reference: dict[str, Any]
    recommended: str

class MapLine(Result):
    s: str
    t: str
    best: str
    remainder: float

class Remainder:
    json: dict[str, Any]
    free: list[str]
    terms: dict[int, dict[tuple[int, int, int], str]]
    def latex(self) -> str: ...
    def sympy(self) -> dict[int, dict[tuple[int, int, int], Any]]: ...
    def hamiltonian(self, order: int) -> Any: ...

def remainder(scheme_or_word: Scheme | str, order: int = 5, body: BodyLike | None = None, perm: str | None = None,
              coeffs: dict[str, Number] | None = None, split: str | None = None) -> Remainder: ...
def best(body: BodyLike, analytic_only: bool = False) -> BestResult: ...
def map_line(family: str, s: Number, t: Number, grid: int, exact: bool = False) -> MapLine: ...
def bch(series: str, degree: int) -> list[tuple[str, Fraction]]: ...
def md(scene: str, integrator: str, h: Number, T: Number | None = None, *, runs: int | None = None, seed: int | None = None,
       scalar: Scalar | None = None, dipole: Number | None = None, field: Number | None = None, molecules: int | None = None,
       threads: int | None = None, state: str | PathLike[str] | None = None, body: str | BodyLike | None = None,
       e: Number | None = None, theta0: Number | None = None, omega0: Number | None = None, obliquity: Number | None = None,
       every: int | None = None, equilibrate: Number | None = None) -> MdResult: ...

class SpinTrajectory:
    every: int
    @property
    def t(self) -> npt.NDArray[np.float64]: ...
    @property
    def Q(self) -> npt.NDArray[np.float64]: ...
    @property
    def omega_body(self) -> npt.NDArray[np.float64]: ...
    @property
    def energy(self) -> npt.NDArray[np.float64]: ...

class SpinResult:
    body: str
    integrator: str
    scalar: str
    e: float
    h: float
    T: float
    steps: int
    evaluations: int
    theta: float
    energy_start: float
    energy_end: float
    cpu_s: float
    unstable: bool
    round_off_floor: bool
    @property
    def Q(self) -> npt.NDArray[np.float64]: ...
    @property
    def omega_body(self) -> npt.NDArray[np.float64]: ...
    @property
    def conserved(self) -> dict[str, Any]: ...
    @property
    def trajectory(self) -> SpinTrajectory | None: ...
    def to_dict(self) -> dict[str, Any]: ...

def spin(body: str | BodyLike, e: Number, integrator: str, h: Number, T: Number, theta0: Number = 0, omega0: Number = 1,
         obliquity: Number = 0, scalar: Scalar = "double", every: int | None = None) -> SpinResult: ...

class SpinSimulation:
    body: str
    integrator: str
    scalar: str
    e: float
    h: float
    t: float
    steps: int
    theta: float
    energy: float
    evaluations: int
    @property
    def Q(self) -> npt.NDArray[np.float64]: ...
    @property
    def G(self) -> npt.NDArray[np.float64]: ...
    @property
    def omega_body(self) -> npt.NDArray[np.float64]: ...
    def integrate(self, t: float) -> None: ...
    def step(self) -> None: ...

def spin_simulation(body: str | BodyLike, e: Number, integrator: str, h: Number, theta0: Number = 0, omega0: Number = 1,
                    obliquity: Number = 0, scalar: Scalar = "double") -> SpinSimulation: ...

class MdSimulation:
    scene: str
    integrator: str
    scalar: str
    runs: int
    seed: int
    h: float
    t: float
    steps: int
    evaluations: int
    @property
    def q(self) -> npt.NDArray[np.float64]: ...
    @property
    def p(self) -> npt.NDArray[np.float64]: ...
    @property
    def Q(self) -> npt.NDArray[np.float64]: ...
    @property
    def G(self) -> npt.NDArray[np.float64]: ...
    @property
    def energy(self) -> npt.NDArray[np.float64]: ...
    @property
    def potential(self) -> npt.NDArray[np.float64]: ...
    def integrate(self, t: float) -> None: ...
    def step(self) -> None: ...

@overload
def md_simulation(scene: Literal["spin-orbit"], integrator: str, h: Number, *, scalar: Scalar | None = None,
                  body: str | BodyLike | None = None, e: Number | None = None, theta0: Number | None = None,
                  omega0: Number | None = None, obliquity: Number | None = None) -> SpinSimulation: ...
@overload
def md_simulation(scene: str, integrator: str, h: Number, *, runs: int | None = None, seed: int | None = None,
                  scalar: Scalar | None = None, dipole: Number | None = None, field: Number | None = None,
                  molecules: int | None = None, threads: int | None = None, state: str | PathLike[str] | None = None,
                  equilibrate: Number | None = None) -> MdSimulation: ...

class BinaryTrajectory:
    every: int
    @property
    def t(self) -> npt.NDArray[np.float64]: ...
    @property
    def r(self) -> npt.NDArray[np.float64]: ...
    @property
    def v(self) -> npt.NDArray[np.float64]: ...
    @property
    def Q1(self) -> npt.NDArray[np.float64]: ...
    @property
    def Q2(self) -> npt.NDArray[np.float64]: ...
    @property
    def omega1(self) -> npt.NDArray[np.float64]: ...
    @property
    def omega2(self) -> npt.NDArray[np.float64]: ...
    @property
    def energy(self) -> npt.NDArray[np.float64]: ...

class BinaryResult:
    system: str | None
    integrator: str
    order: int
    G: float
    h: float
    T: float
    steps: int
    evaluations: int
    t: float
    energy: float
    energy_start: float
    max_rel_energy_error: float
    max_rel_angular_momentum_error: float
    cpu_s: float
    unstable: bool
    round_off_floor: bool
    @property
    def masses(self) -> npt.NDArray[np.float64]: ...
    @property
    def moments(self) -> npt.NDArray[np.float64]: ...
    @property
    def r(self) -> npt.NDArray[np.float64]: ...
    @property
    def v(self) -> npt.NDArray[np.float64]: ...
    @property
    def Q1(self) -> npt.NDArray[np.float64]: ...
    @property
    def Q2(self) -> npt.NDArray[np.float64]: ...
    @property
    def omega1(self) -> npt.NDArray[np.float64]: ...
    @property
    def omega2(self) -> npt.NDArray[np.float64]: ...
    @property
    def angular_momentum(self) -> npt.NDArray[np.float64]: ...
    @property
    def mutual(self) -> dict[str, Any]: ...
    @property
    def trajectory(self) -> BinaryTrajectory | None: ...
    def to_dict(self) -> dict[str, Any]: ...

def binary(*, system: str | None = None, primary: str | None = None, secondary: str | None = None,
           density: Number | tuple[Number, Number] | None = None, mass: tuple[Number, Number] | None = None, order: int = 2,
           G: Number = "6.67430e-20", separation: Number | None = None, primary_period: Number | None = None,
           state: dict[str, Any] | str | None = None, integrator: str = "SIER4", h: Number | None = None, T: Number = 0,
           every: int | None = None) -> BinaryResult: ...
