"""Bodies, reference schemes, scheme tables on disk."""
from fractions import Fraction

import numpy as np
import pytest

import rotlie

WATER = (Fraction(10220, 29376), Fraction(19187, 29376), Fraction(1))  # LV section 4.3


def test_body_from_every_kind_of_number():
    expected = (Fraction(2, 5), Fraction(7, 10), Fraction(1))
    for args in [("0.4", "0.7", "1"), (Fraction(2, 5), Fraction(7, 10), 1), (0.4, 0.7, 1.0), ("2/5", "7/10", "1")]:
        body = rotlie.Body(*args)
        assert body.moments == expected
    assert rotlie.Body("0.4", "0.7", "1") == rotlie.Body(Fraction(2, 5), 0.7, 1)


def test_named_body():
    water = rotlie.Body.named("water")
    assert water.moments == WATER
    assert water == rotlie.Body("2555/7344", "19187/29376", 1)
    assert rotlie.Body.named("sphere").moments == (1, 1, 1)


@pytest.mark.parametrize("moments", [(1, 1, 3), (-1, 1, 1), (0, 1, 1), ("x", 1, 1), ("nan", 1, 1), (1, 2, 4)])
def test_non_physical_bodies_raise(moments):
    with pytest.raises(ValueError):
        rotlie.Body(*moments)


def test_unknown_name_raises():
    with pytest.raises(ValueError):
        rotlie.Body.named("granite")


def test_reference_scheme():
    s = rotlie.scheme("RS4-S5-McLachlan:CBA")
    assert s.name == "RS4-S5-McLachlan:CBA"
    assert s.splitting == "RS" and s.order == 4 and s.remainder_norm is None
    letters = [letter for letter, _ in s.stages]
    assert "".join(letters) == s.word
    assert s.cost == len(s.stages) + 1  # RS: the rotations about G gathered into one (LV section 4.1)
    c = s.coefficients
    assert c.dtype == np.float64 and c.shape == (len(s.stages),)
    for part in "RS":  # consistency: each part's coefficients sum to 1
        assert abs(sum(x for (letter, _), x in zip(s.stages, c) if letter == part) - 1) < 1e-15
    abc = rotlie.scheme("ABCBA2")
    assert abc.splitting == "ABC" and abc.cost == len(abc.stages) and abc.order == 2


def test_table_round_trip(tmp_path):
    water = rotlie.Body.named("water")
    s = rotlie.scheme("N2:BAC:2", water)
    assert s.name == "N2:BAC:2" and s.order == 4 and s.splitting == "ABC"
    assert all(len(value.replace("-", "").replace(".", "").lstrip("0")) >= 40 for _, value in s.stages)
    path = tmp_path / "n2.scheme"
    s.save(path)
    back = rotlie.load_table(path)
    assert back == s and back.text == s.text
    # a table file by its path, for the body it was solved for
    assert rotlie.scheme(str(path), water) == s


def test_solved_name_needs_a_body():
    with pytest.raises(ValueError, match="body"):
        rotlie.scheme("N2:BAC:2")


def test_the_stub_declares_every_public_name():
    import ast
    import pathlib

    stub = pathlib.Path(rotlie.__file__).with_name("__init__.pyi")
    declared = {n.name for n in ast.parse(stub.read_text()).body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    assert set(rotlie.__all__) <= declared
    for name in rotlie.__all__:
        assert getattr(rotlie, name).__doc__, name
