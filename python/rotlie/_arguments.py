"""Arguments checked once, with one-line errors: integers within a range (pybind11 would raise a
multi-line TypeError for one beyond C++'s long) and real arrays (NumPy would drop an imaginary part)."""
from __future__ import annotations

import operator

import numpy as np


def real_array(value, name):
    """``value`` as a float64 array; complex input is refused (NumPy would drop the imaginary part)."""
    a = np.asarray(value)
    if np.iscomplexobj(a):
        raise TypeError(f"{name} must be real, got a complex array")
    return np.asarray(a, dtype=np.float64)


def index_argument(value, name, low=-2**63, high=2**63 - 1):
    """An integer argument within [low, high], or a one-line TypeError/ValueError naming it."""
    try:
        v = operator.index(value)
    except TypeError:
        raise TypeError(f"{name} must be an integer, got {type(value).__name__}") from None
    if not low <= v <= high:
        raise ValueError(f"{name} = {v if abs(v) < 10**15 else f'{float(v):.3g}'} is outside {low} … {high}")
    return v
