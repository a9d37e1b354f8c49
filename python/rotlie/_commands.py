"""best, map_line, bch and md: the command line's JSON as Python objects."""
from __future__ import annotations

import json
from fractions import Fraction

from ._arguments import index_argument
from . import _rotlie
from ._bodies import body_text, number_text


def best(body, analytic_only: bool = False) -> dict:
    """The best integrator for ``body`` (LV sections 4–5), as ``rotlie best --json``: the best N, R and P
    by ||H_R5||, the reference, the gains at equal cost and, unless ``analytic_only``, the measured
    column (the LV section 4.1 protocol run for the candidates). A symmetric top raises ValueError."""
    return json.loads(_rotlie.best(body_text(body), bool(analytic_only)))


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


def map_line(family: str, s, t, grid: int, exact: bool = False) -> dict:
    """One body line of ``rotlie map --family FAMILY --grid GRID`` (LV section 5): the body at triangle
    coordinates ``s``, ``t`` (multiples of 1/grid, e.g. ``Fraction(3, 20)``), by the path the map takes
    for the family (its row computed as the map does, so the line is the map file's), or by the exact
    solver for that body alone when ``exact`` (``rotlie map --exact``). For P at grid 200 and finer
    (the screened path) it is the line of the row before the map's neighbour check, which replaces a
    line by the exact solver's where a neighbour's best beats it: ``exact=True`` gives the exact line."""
    grid = index_argument(grid, "grid")
    if grid < 2:
        raise ValueError(f"--grid must be at least 2, got {grid}")
    return json.loads(_rotlie.map_line(str(family), _grid_index(s, grid, "s"), _grid_index(t, grid, "t"), grid,
                                          bool(exact)))


def md(scene: str, integrator: str, h, T=None, **options) -> dict:
    """A scene of ``rotlie md`` (``free-water``, ``dipole-field``, ``liquid-water``) as ``rotlie md --json``.

    ``h`` is the step in fs, ``T`` the time per run in ps (the scene's default when None). Options are the
    command line's without the dashes, each scene its own: ``runs``, ``seed``, ``scalar`` (double,
    long-double, float128), ``dipole`` (D) and ``field`` (MV/m) for the dipole scene; ``molecules``,
    ``threads`` and ``state`` (a file) for liquid water. An option of another scene raises ValueError, as
    the command line refuses it; the run's warnings (a step beyond the stable range, round-off) are
    UserWarnings and are flagged in the result."""
    scenes = _rotlie.md_scenes()
    known = sorted({name[2:] for opts in scenes.values() for name in opts})
    unknown = set(options) - set(known)
    if unknown:
        raise TypeError(f"md() got unknown options {sorted(unknown)} (known: {known})")
    given = {} if T is None else {"--T": number_text(T, "--T")}
    for key, value in options.items():
        if value is None:
            continue
        given["--" + key] = value if key in ("scalar", "state") else number_text(value, "--" + key)
    return json.loads(_rotlie.md(str(scene), str(integrator), number_text(h, "--h"), {k: str(v) for k, v in given.items()}))
