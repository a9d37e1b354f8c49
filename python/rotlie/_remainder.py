"""remainder: the modified Hamiltonian H_R2 … H_RK of a scheme (LV section 3), exact."""
from __future__ import annotations

import json
import os
from fractions import Fraction

from ._arguments import index_argument
from . import _rotlie
from ._bodies import body_text, number_text


class Remainder:
    """The terms of H_R2 … H_RK of a scheme, as ``rotlie remainder --json``.

    ``terms[k][(i, j, l)]`` is the exact coefficient (text: a rational, or an expression in the free
    coefficients a1, b1, … and I1, I2, I3 when they are left symbolic) of G1^i G2^j G3^l in H_Rk;
    ``json`` is the command's whole JSON, ``free`` the coefficients left symbolic.
    """

    def __init__(self, text: str, latex: str):
        self.json = json.loads(text)
        self.free = list(self.json.get("free", []))
        self.terms = {o["order"]: {tuple(t["G"]): t["coeff"] for t in o["terms"]} for o in self.json["orders"]}
        self._latex = latex

    def latex(self) -> str:
        """The LaTeX of ``rotlie remainder --latex``."""
        return self._latex

    def sympy(self):
        """The terms as SymPy expressions, ``{k: {(i, j, l): expr}}`` (needs SymPy)."""
        import sympy  # optional: only this method needs it

        return {k: {m: sympy.sympify(c) for m, c in ts.items()} for k, ts in self.terms.items()}

    def hamiltonian(self, order: int):
        """H_Rk as one SymPy polynomial in G1, G2, G3 (needs SymPy)."""
        import sympy

        G1, G2, G3 = sympy.symbols("G1 G2 G3")
        return sum(sympy.sympify(c) * G1**i * G2**j * G3**l for (i, j, l), c in self.terms[order].items())

    def __repr__(self):
        return f"<rotlie.Remainder of orders {sorted(self.terms)}>"


def remainder(scheme_or_word, order: int = 5, body=None, perm: str | None = None, coeffs: dict | None = None,
              split: str | None = None) -> Remainder:
    """The modified Hamiltonian of a scheme to ``order`` (1 … 9), as ``rotlie remainder``.

    ``scheme_or_word``: a paper name (N1…N7, R, P1…P15, RSRSRSR, SRSRSRS), a raw word (ABCBA), or a
    Scheme solved here (``SCHEME:PERM:LABEL``: its name, permutation, body and written coefficients).
    ``body``: exact moments (symbolic I1, I2, I3 when None); ``coeffs``: values of free coefficients,
    ``{"a1": "1/20"}``; ``split``: ABC or RS for a raw word.
    """
    coefficient_items = {} if coeffs is None else dict(coeffs)
    if isinstance(scheme_or_word, _rotlie.Scheme):
        s = scheme_or_word
        parts = s.name.split(":")
        if len(parts) != 3:
            raise ValueError(f"{s.name}: remainder takes a Scheme solved here (SCHEME:PERM:LABEL), a name or a word")
        if parts[0] in ("Q", "QRS"):  # FAMILY:WORD:PERM, a system of two free parameters
            word, perm, split = parts[1], parts[2] if perm is None else perm, "ABC" if parts[0] == "Q" else "RS"
        else:
            word, perm = parts[0], parts[1] if perm is None else perm
        if body is None and s.inertia:
            body = ",".join(s.inertia.split())
        free = set(_rotlie.free_coefficients(word, perm, "" if split is None else str(split)))
        for name, (_, value) in zip(s.stage_names, s.stages):
            if name in free:
                coefficient_items.setdefault(name, value)
    else:
        word = os.fspath(scheme_or_word)
    items = [(str(k), number_text(v, f"--coeffs {k}")) for k, v in coefficient_items.items()]
    json_text, latex = _rotlie.remainder(word, index_argument(order, "order"), "" if body is None else body_text(body),
                                         "ABC" if perm is None else str(perm), "" if split is None else str(split), items)
    return Remainder(json_text, latex)
