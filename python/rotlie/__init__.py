"""rotlie from Python: dedicated symplectic integrators for rigid-body rotation.

The library floor of the rotlie C++ project (the names a user types resolved once, the runs and
their measurements) and its numeric core, with NumPy arrays in and out:

- ``Body``, ``scheme``, ``load_table``, ``Scheme.save`` and ``solve``: bodies and scheme tables, the
  dedicated schemes of a family solved for a body (Laskar & Vaillant), ranked by ||H_R5||;
- ``exact_flow``, ``integrate`` and ``order``: the free rigid body, vectorised over N states;
- ``remainder``, ``best``, ``map_line``, ``bch``, ``md``, ``spin`` and ``binary``: the command line's runs with typed
  results (fields as attributes, arrays as NumPy arrays, ``to_dict()`` the command's JSON);
- ``md_simulation`` and ``spin_simulation``: those runs held, advanced by ``integrate(t)`` to an absolute time
  and continued from where they stopped.

Bad arguments raise ``ValueError`` and a failed run ``RuntimeError``, with the command line's
one-line message; long calls release the GIL and Ctrl-C interrupts them; nothing is printed.
"""
from __future__ import annotations

import json
import os
from fractions import Fraction

import numpy as np

from . import _rotlie
from ._arguments import index_argument, real_array
from ._bodies import Body, body_text, number_text
from ._results import BestResult, MapLine, MdResult, MdTrajectory, OrderResult, Result
from ._rotlie import Scheme

__all__ = [
    "Body", "Scheme", "scheme", "load_table", "solve", "exact_flow", "integrate", "order",
    "remainder", "Remainder", "best", "map_line", "bch", "md", "spin", "SpinResult", "SpinTrajectory",
    "md_simulation", "MdSimulation", "spin_simulation", "SpinSimulation", "binary", "BinaryResult", "BinaryTrajectory",
    "binary_simulation", "BinarySimulation", "integrators",
    "Result", "MdResult", "MdTrajectory", "OrderResult", "BestResult", "MapLine",
]
__version__ = "0.1.0"

SCALARS = ("double", "long-double", "float128")


def scheme(name: str, body=None, force: bool = False) -> Scheme:
    """A scheme by the command line's name.

    ``name`` is a reference scheme with an optional permutation (``"RS4-S5-McLachlan:CBA"``), a
    dedicated solution ``SCHEME:PERM:LABEL`` (``"N2:BAC:2"``, solved for ``body``, which it then
    requires), or the path of a scheme-table file (refused when it was solved for another body,
    unless ``force``; then used with a UserWarning).
    """
    if not isinstance(name, (str, os.PathLike)):
        raise TypeError("name must be a str")
    return _rotlie.scheme(os.fspath(name), "" if body is None else body_text(body), bool(force))


def load_table(path) -> Scheme:
    """The scheme table in a file (format version 1, as written by ``Scheme.save`` and ``rotlie solve --out``)."""
    return _rotlie.load_table(os.fspath(path))


def _save(self: Scheme, path) -> None:
    """Writes the scheme table to ``path``, whole or not at all (``load_table`` reads it back)."""
    _rotlie_save(self, os.fspath(path))


_rotlie_save = Scheme.save
Scheme.save = _save


def solve(body, family: str = "N", perm: str | None = None, scheme: str | None = None, digits: int = 40,
          starts: int | None = None, seed: int | None = None) -> list[Scheme]:
    """Every real solution of a dedicated family for ``body``, ranked by ||H_R5|| (eq. 64) as ``rotlie solve``.

    ``family``: N, R or P (every real solution, exact elimination), or Q or QRS (two free parameters:
    the smallest local minimum of ||H_R5|| found on each system's surface H_R3 = 0 from ``starts``
    random starts, default 40, drawn from ``seed``, default 1; systems where no minimum was polished
    are left out); ``perm``: one permutation (ABC, BCA, CAB, ACB, CBA, BAC) or all (None); ``scheme``:
    one member (N2; a word for Q, QRS) or all (None); ``digits``: 10 … 300, the coefficients' decimal
    digits. Each Scheme is named ``SCHEME:PERM:LABEL`` (``FAMILY:WORD:PERM`` for Q, QRS) and carries
    ``remainder_norm`` (||H_R5||, natural units, the body scaled to I3 = 1).
    """
    return _rotlie.solve(body_text(body), str(family), "all" if perm is None else str(perm),
                         "" if scheme is None else str(scheme), index_argument(digits, "digits"),
                         "" if starts is None else str(index_argument(starts, "starts")),
                         "" if seed is None else str(index_argument(seed, "seed")))


def _rows(G0, Q0):
    G = real_array(G0, "G0")
    single = G.ndim == 1
    if G.shape[-1:] != (3,) or G.ndim not in (1, 2):
        raise ValueError("G0 must have shape (3,) or (N, 3)")
    G = np.ascontiguousarray(G.reshape(-1, 3))
    if Q0 is None:
        Q = np.broadcast_to(np.eye(3), (G.shape[0], 3, 3))
    else:
        Q = real_array(Q0, "Q0")
        if Q.shape != ((3, 3) if single else (G.shape[0], 3, 3)):
            raise ValueError("Q0 must have shape (3, 3) or (N, 3, 3), one attitude per row of G0")
        Q = Q.reshape(-1, 3, 3)
    return G, np.ascontiguousarray(Q), single


def _unrows(single, *arrays):
    return tuple(a[0] if single else a for a in arrays)


def exact_flow(body, G0, Q0=None, t=None, scalar: str = "double", error_estimate: bool = False):
    """The exact motion of the free rigid body (models/exact_free_body.hpp), as ``rotlie exact``.

    From the attitude ``Q0`` (identity when omitted) and the body-frame angular momentum ``G0`` at time 0,
    the state at time ``t``: ``G0`` of shape (3,) or (N, 3), ``Q0`` of shape (3, 3) or (N, 3, 3), ``t`` a
    number or one per state. Returns ``(G, Q)`` of the same shapes (float64, computed in ``scalar``:
    double, long-double or float128, rounded once), and the estimated error of each state (max abs
    entry of Q and of G/|G|) when ``error_estimate``. A time beyond |omega| |t| = 2^60 rad raises ValueError.
    """
    if t is None:
        raise TypeError("exact_flow() needs the time t")
    G, Q, single = _rows(G0, Q0)
    times = np.ascontiguousarray(np.broadcast_to(real_array(t, "t"), (G.shape[0],)))
    G1, Q1, err = _rotlie.exact_flow(body_text(body), G, Q, times, str(scalar))
    if single:
        G1, Q1, err = G1[0], Q1[0], float(err[0])
    return (G1, Q1, err) if error_estimate else (G1, Q1)


def integrate(scheme, body, G0, Q0=None, h=None, steps=None, scalar: str = "double", force: bool = False):
    """``steps`` steps of size ``h`` of ``scheme`` on the free rigid ``body``, vectorised over N states.

    ``scheme``: a Scheme or a name for ``rotlie.scheme``; ``G0`` of shape (3,) or (N, 3) (body-frame
    angular momentum), ``Q0`` of shape (3, 3) or (N, 3, 3) (identity when omitted); ``h`` a number or
    exact text (``"1/64"``), read in ``scalar`` (double, long-double or float128). Returns ``(G, Q)``
    of the input shapes in float64 (rounded once at the end). Each row is stepped alone, so a
    vectorised call equals the row-by-row calls bit for bit. A table solved for another body is
    refused unless ``force``; a diverged run (NaN) raises RuntimeError.
    """
    if h is None or steps is None:
        raise TypeError("integrate() needs the step h and the number of steps")
    text = body_text(body)
    if not isinstance(scheme, Scheme):
        scheme = _rotlie.scheme(os.fspath(scheme), text, bool(force))
    G, Q, single = _rows(G0, Q0)
    G1, Q1 = _rotlie.integrate(scheme, text, G, Q, number_text(h, "--h"), index_argument(steps, "steps"), str(scalar), bool(force))
    return _unrows(single, G1, Q1)


def _vector_text(v, what):
    if isinstance(v, str):
        return v
    return ",".join(number_text(x, what) for x in v)


def order(scheme, body, G0=(1, 1, 1), T=1, min_level: int = 1, max_level: int = 10, scalar: str = "double",
          force: bool = False) -> OrderResult:
    """The measured order of ``scheme`` for ``body`` (LV section 4.1), as ``rotlie order --json``.

    Steps h = T/2^i for i = ``min_level`` … ``max_level`` from (identity, G0), the mean attitude error
    against the exact flow, and the fitted slope (``None`` when no fit). Returns an OrderResult: the
    command's JSON fields ``scheme``, ``scalar``, ``declared_order``, ``points``, ``slope`` as attributes,
    and ``h``, ``error`` as arrays.
    """
    text = body_text(body)
    if not isinstance(scheme, Scheme):
        scheme = _rotlie.scheme(os.fspath(scheme), text, bool(force))
    return OrderResult(json.loads(_rotlie.order(scheme, text, _vector_text(G0, "G0"), number_text(T, "--T"),
                                    index_argument(min_level, "min_level"), index_argument(max_level, "max_level"), str(scalar), bool(force))))


from ._remainder import Remainder, remainder  # noqa: E402
from ._commands import best, map_line, bch, md, md_simulation  # noqa: E402
from ._rotlie import spin, SpinResult, SpinTrajectory  # noqa: E402  (typed in C++: python/src/spin.cpp)
from ._rotlie import MdSimulation, SpinSimulation, spin_simulation  # noqa: E402  (python/src/*_simulation.cpp)
from ._rotlie import BinaryResult, BinaryTrajectory, BinarySimulation  # noqa: E402  (python/src/binary*.cpp)
from ._rotlie import integrators  # noqa: E402  (the method registry: python/src/md.cpp)
from ._typed import typed as _typed  # noqa: E402

binary = _typed(_rotlie.binary, _rotlie._binary_keywords(), "BinaryResult")
binary_simulation = _typed(_rotlie.binary_simulation, _rotlie._binary_simulation_keywords(), "BinarySimulation")


def __dir__():
    """dir(rotlie) lists the API only (the helpers it imports stay reachable but unlisted)."""
    return sorted([*__all__, "SCALARS", "__version__"])
