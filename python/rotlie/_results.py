"""Typed results: each command's JSON object with its fields as attributes, its arrays as NumPy arrays,
and ``to_dict()`` for the JSON form. Each result is also a read-only mapping over the same fields, so
``r["slope"]`` and ``r == cli_json`` keep working as when the calls returned plain dictionaries."""
from __future__ import annotations

import copy
from collections.abc import Mapping
from typing import Any

import numpy as np


class Result(Mapping):
    """A command's JSON object: its fields as attributes (``fields`` lists those every result has)."""

    fields: tuple[str, ...] = ()

    def __init__(self, data: dict[str, Any]):
        missing = [f for f in self.fields if f not in data]
        if missing:
            raise RuntimeError(f"{type(self).__name__}: the result lacks {missing}")
        self._data = data

    def __getattr__(self, name: str) -> Any:
        data = self.__dict__.get("_data", {})
        if name in data:
            return data[name]
        raise AttributeError(f"{type(self).__name__} has no field {name!r} (fields: {sorted(data)})")

    def __getitem__(self, key: str) -> Any:
        return self._data[key]

    def __iter__(self):
        return iter(self._data)

    def __len__(self) -> int:
        return len(self._data)

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self._data))

    def to_dict(self) -> dict[str, Any]:
        """The object the command line prints with ``--json``."""
        return copy.deepcopy(self._data)

    def __repr__(self) -> str:
        shown = ", ".join(f"{f}={self._data[f]!r}" for f in self.fields[:4])
        return f"<{type(self).__name__} {shown}>"


class MdTrajectory:
    """A run's state every K steps from the start, each field of the JSON's "trajectory" as an array: for
    the md scenes ``t_ps`` (N,), ``Q`` (N, 3, 3), ``G`` (N, 3), ``energy`` and ``potential`` (N,) of body 0
    of the first run (liquid water: molecule 0, the runs in turn); for spin-orbit ``t`` (orbits), ``Q``,
    ``omega_body`` and ``energy``."""

    def __init__(self, data: dict[str, Any]):
        self.every: int = int(data["every"])
        self.fields = tuple(k for k in data if k != "every")
        for key in self.fields:
            a = np.asarray(data[key], dtype=np.float64)
            setattr(self, key, a.reshape(-1, 3, 3) if key == "Q" else a)

    def __repr__(self) -> str:
        n = len(getattr(self, self.fields[0])) if self.fields else 0
        return f"<MdTrajectory {n} samples every {self.every} steps: {', '.join(self.fields)}>"


class MdResult(Result):
    """A run of ``rotlie md`` (any scene): its JSON's fields as attributes; ``trajectory`` when ``every`` was given."""

    fields = ("integrator", "unstable", "round_off_floor")

    @property
    def trajectory(self) -> MdTrajectory | None:
        t = self._data.get("trajectory")
        return None if t is None else MdTrajectory(t)


class OrderResult(Result):
    """``rotlie order``: the scheme, its declared order, the points (h, error, …) and the fitted slope."""

    fields = ("scheme", "scalar", "declared_order", "points", "slope")

    @property
    def h(self) -> np.ndarray:
        return np.array([p["h"] for p in self._data["points"]], dtype=np.float64)

    @property
    def error(self) -> np.ndarray:
        return np.array([p["error"] for p in self._data["points"]], dtype=np.float64)


class BestResult(Result):
    """``rotlie best``: the best N, R and P for a body, the reference, the gains and the measured column."""

    fields = ("inertia", "N", "R", "P", "reference", "recommended")


class MapLine(Result):
    """One body line of a map (``rotlie map``): the body's coordinates, its best scheme and remainder."""

    fields = ("s", "t", "best", "remainder")
