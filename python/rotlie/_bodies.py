"""Bodies and the numbers a user types, as the exact text the library floor reads."""
from __future__ import annotations

import numbers
from decimal import Decimal
from fractions import Fraction

from . import _rotlie


def number_text(value, what: str) -> str:
    """A number as exact text: strings as typed, Fractions as p/q, ints, and floats by their shortest
    repr (0.4 is read as 4/10, the number the user wrote, not the binary double nearest to it)."""
    if isinstance(value, bool):
        raise TypeError(f"{what} must be a number, not a bool")
    if isinstance(value, str):
        text = value.strip()
    elif isinstance(value, Fraction):
        text = f"{value.numerator}/{value.denominator}" if value.denominator != 1 else str(value.numerator)
    elif isinstance(value, numbers.Integral):
        text = str(int(value))
    elif isinstance(value, (numbers.Real, Decimal)):
        text = repr(float(value)) if not isinstance(value, Decimal) else str(value)
    else:
        raise TypeError(f"{what} must be a str, Fraction, int or float, not {type(value).__name__}")
    if "," in text:
        raise ValueError(f"{what}: '{text}' is not a number")
    return text


class Body:
    """A rigid body by its three principal moments of inertia, held exactly.

    ``Body(I1, I2, I3)`` takes strings (``"2555/7344"``, ``"0.4"``), ``fractions.Fraction``, ints or
    floats (a float is read as its shortest decimal repr). ``Body.named("water")`` takes the command
    line's names (``water``, ``sphere``). Moments that are not a rigid body's (not positive, or
    breaking a triangle inequality I_i <= I_j + I_k, eq. 77) raise ``ValueError``.
    """

    __slots__ = ("_moments",)

    def __init__(self, I1, I2, I3):
        text = ",".join(number_text(v, name) for v, name in ((I1, "I1"), (I2, "I2"), (I3, "I3")))
        self._moments = tuple(_rotlie.exact_moments(text))

    @classmethod
    def named(cls, name: str) -> "Body":
        """A body by the command line's name: ``water`` (LV section 4.3) or ``sphere``."""
        if not isinstance(name, str) or "," in name:
            raise ValueError(f"--inertia: '{name}' is not a body's name (water, sphere)")
        body = cls.__new__(cls)
        body._moments = tuple(_rotlie.exact_moments(name))
        return body

    @property
    def moments(self) -> tuple[Fraction, Fraction, Fraction]:
        """I1, I2, I3 as exact fractions."""
        return tuple(Fraction(m) for m in self._moments)

    @property
    def text(self) -> str:
        """The moments as the command line's --inertia takes them: ``"p/q,p/q,p/q"``."""
        return ",".join(self._moments)

    def __float__(self):  # pragma: no cover - a body is not a number
        raise TypeError("a Body is three numbers: use Body.moments")

    def __eq__(self, other):
        return isinstance(other, Body) and self.moments == other.moments

    def __hash__(self):
        return hash(self.moments)

    def __repr__(self):
        return "rotlie.Body(" + ", ".join(f"'{m}'" for m in self._moments) + ")"


def body_text(body) -> str:
    """The exact text of a Body, a name or "I1,I2,I3" string, or a sequence of three moments."""
    if isinstance(body, Body):
        return body.text
    if isinstance(body, str):
        return ",".join(_rotlie.exact_moments(body))
    if isinstance(body, (tuple, list)) and len(body) == 3:
        return Body(*body).text
    raise TypeError(f"body must be a rotlie.Body, a name such as 'water', or three moments, not {type(body).__name__}")
