"""best, map_line, bch and md: the command line's runs with typed results (python/rotlie/_results.py)."""
from __future__ import annotations

import json
from fractions import Fraction

import os

from ._arguments import index_argument
from . import _rotlie
from ._bodies import body_text, number_text
from ._results import BestResult, MapLine, MdResult

Number = str | Fraction | int | float  # a number as the command line reads it (see number_text)


def best(body, analytic_only: bool = False) -> BestResult:
    """The best integrator for ``body`` (LV sections 4–5), as ``rotlie best --json``: the best N, R and P
    by ||H_R5||, the reference, the gains at equal cost and, unless ``analytic_only``, the measured
    column (the LV section 4.1 protocol run for the candidates). A symmetric top raises ValueError."""
    return BestResult(json.loads(_rotlie.best(body_text(body), bool(analytic_only))))


def bch(series: str, degree: int) -> list[tuple[str, Fraction]]:
    """A BCH-type series in the free Lie algebra (XY, XYX, SYM, XYZ) to ``degree``, as ``rotlie bch``:
    every Lyndon word of the basis with its exact coefficient."""
    r = json.loads(_rotlie.bch(str(series), index_argument(degree, "degree")))
    return [(t["word"], Fraction(t["coefficient"])) for t in r["terms"]]


def _grid_index(value, grid: int, what: str) -> int:
    x = Fraction(number_text(value, what)) * grid
    if x.denominator != 1:
        raise ValueError(f"{what} = {value} is not a multiple of 1/{grid} (a point of the grid)")
    return int(x)


def map_line(family: str, s, t, grid: int, exact: bool = False) -> MapLine:
    """One body line of ``rotlie map --family FAMILY --grid GRID`` (LV section 5): the body at triangle
    coordinates ``s``, ``t`` (multiples of 1/grid, e.g. ``Fraction(3, 20)``), by the path the map takes
    for the family (its row computed as the map does, so the line is the map file's), or by the exact
    solver for that body alone when ``exact`` (``rotlie map --exact``). For P at grid 200 and finer
    (the screened path) it is the line of the row before the map's neighbour check, which replaces a
    line by the exact solver's where a neighbour's best beats it: ``exact=True`` gives the exact line."""
    grid = index_argument(grid, "grid")
    if grid < 2:
        raise ValueError(f"--grid must be at least 2, got {grid}")
    return MapLine(json.loads(_rotlie.map_line(str(family), _grid_index(s, grid, "s"), _grid_index(t, grid, "t"), grid,
                                                  bool(exact))))


def md(scene: str, integrator: str, h: Number, T: Number | None = None, *, runs: int | None = None, seed: int | None = None,
       scalar: str | None = None, dipole: Number | None = None, field: Number | None = None, molecules: int | None = None,
       threads: int | None = None, state: str | os.PathLike | None = None, body: str | Body | None = None, e: Number | None = None,
       theta0: Number | None = None, omega0: Number | None = None, obliquity: Number | None = None,
       every: int | None = None, equilibrate: Number | None = None, temperature: Number | None = None,
       friction: Number | None = None, tau: Number | None = None) -> MdResult:
    """A scene of ``rotlie md`` (``free-water``, ``dipole-field``, ``liquid-water``, ``spin-orbit``), as ``rotlie md --json``.

    ``h`` is the step in fs, ``T`` the time per run in ps (spin-orbit: both in orbits, as ``rotlie spin``);
    every keyword left None takes the scene's default. ``runs``, ``seed``: the ensemble; ``scalar``:
    double, long-double or float128; ``dipole`` (D) and ``field`` (MV/m): the dipole scene; ``molecules``,
    ``threads``, ``state`` (a file) and ``equilibrate`` (ps, a new start's equilibration): liquid water; ``body`` (a name, "A,B,C", a Body or three moments),
    ``e``, ``theta0``, ``omega0``, ``obliquity``: spin-orbit; ``temperature`` (K), ``friction`` (per ps,
    -BAOAB/-OBABO) and ``tau`` (ps, -NHC): free water and liquid water at a temperature, with an integrator
    such as ``SIER2-BAOAB`` (docs/thermostats.md); ``every``: the trajectory every K steps
    (``MdResult.trajectory``, its fields as arrays). A keyword of another scene raises ValueError, as the
    command line refuses it; the run's warnings (a step beyond the stable range, round-off) are
    UserWarnings and are flagged in the result (``unstable``, ``round_off_floor``)."""
    given = {"T": T, "runs": runs, "seed": seed, "scalar": scalar, "dipole": dipole, "field": field,
             "molecules": molecules, "threads": threads, "state": state, "body": body, "e": e, "theta0": theta0,
             "omega0": omega0, "obliquity": obliquity, "every": every, "equilibrate": equilibrate,
             "temperature": temperature, "friction": friction, "tau": tau}
    return MdResult(json.loads(_rotlie.md(str(scene), str(integrator), number_text(h, "--h"), _scene_options(given))))


def _scene_options(given: dict) -> dict[str, str]:
    """The keywords given (not None) as the command line's options ("--T" → "5")."""
    options = {}
    for key, value in given.items():
        if value is None:
            continue
        if key in ("runs", "seed", "molecules", "threads", "every"):
            options["--" + key] = str(index_argument(value, key))
        elif key == "scalar":
            options["--scalar"] = str(value)
        elif key == "state":
            options["--state"] = os.fspath(value)
        elif key == "body":
            options["--body"] = value if isinstance(value, str) else body_text(value)
        else:
            options["--" + key] = number_text(value, "--" + key)
    return options


def md_simulation(scene: str, integrator: str, h: Number, *, runs: int | None = None, seed: int | None = None,
                  scalar: str | None = None, dipole: Number | None = None, field: Number | None = None,
                  molecules: int | None = None, threads: int | None = None, state: str | os.PathLike | None = None,
                  body: str | Body | None = None, e: Number | None = None, theta0: Number | None = None,
                  omega0: Number | None = None, obliquity: Number | None = None, equilibrate: Number | None = None):
    """The run of ``md`` held at t = 0 (its keywords but ``T`` and ``every``), checked as ``md`` checks them.

    ``integrate(t)`` advances it to the absolute time ``t`` (ps) in whole steps ``h`` (fs) and continues
    from there: ``integrate(T/2)`` then ``integrate(T)`` gives the bits of ``integrate(T)`` and of ``md``'s
    run to T. free-water and dipole-field hold every run of the ensemble (``runs``, one molecule each):
    ``q``, ``p``, ``G`` of shape (runs, 3), ``Q`` (runs, 3, 3), ``energy`` and ``potential`` (runs,).
    The spin-orbit scene returns ``spin_simulation(body, e, integrator, h, ...)`` (t in orbits); the
    liquid-water scene cannot be held yet (ValueError)."""
    given = {"runs": runs, "seed": seed, "scalar": scalar, "dipole": dipole, "field": field, "molecules": molecules,
             "threads": threads, "state": state, "body": body, "e": e, "theta0": theta0, "omega0": omega0,
             "obliquity": obliquity, "equilibrate": equilibrate}
    if scene == "spin-orbit":
        takes = _rotlie.md_scenes()["spin-orbit"]
        for key, value in given.items():
            if value is not None and "--" + key not in takes:
                raise ValueError(f"--{key} does not apply to the spin-orbit scene")
        if body is None or e is None:
            raise ValueError("--body and --e are required by the spin-orbit scene")
        spin = {"theta0": theta0, "omega0": omega0, "obliquity": obliquity, "scalar": scalar}
        return _rotlie.spin_simulation(body, e, str(integrator), h, **{k: v for k, v in spin.items() if v is not None})
    return _rotlie.md_simulation(str(scene), str(integrator), number_text(h, "--h"), _scene_options(given))


def md_keywords() -> set[str]:
    """The keywords md() takes beyond scene, integrator and h: every option of every scene."""
    return {name[2:] for options in _rotlie.md_scenes().values() for name in options}
