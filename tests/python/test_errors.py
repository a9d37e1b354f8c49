"""Bad inputs raise ValueError with the command line's one-line message; a failed run raises RuntimeError."""
import numpy as np
import pytest

import rotlie

from conftest import cli_error

WATER = rotlie.Body.named("water")


def raises_as_cli(call, *cli_args, error=ValueError):
    with pytest.raises(error) as e:
        call()
    assert str(e.value) == cli_error(*cli_args)


def test_messages_match_the_command_line():
    raises_as_cli(lambda: rotlie.solve(WATER, family="X"), "solve", "--family", "X", "--inertia", "water")
    raises_as_cli(lambda: rotlie.solve(WATER, perm="XYZ"), "solve", "--family", "N", "--perm", "XYZ", "--inertia", "water")
    raises_as_cli(lambda: rotlie.solve(WATER, scheme="P1"), "solve", "--family", "N", "--scheme", "P1", "--inertia", "water")
    raises_as_cli(lambda: rotlie.solve(WATER, digits=5), "solve", "--family", "N", "--digits", "5", "--inertia", "water")
    raises_as_cli(lambda: rotlie.solve("1,1,3"), "solve", "--family", "N", "--inertia", "1,1,3")
    raises_as_cli(lambda: rotlie.scheme("N2:XYZ:2", WATER), "integrate", "--scheme", "N2:XYZ:2", "--inertia", "water", "--h", "0.1")
    raises_as_cli(lambda: rotlie.scheme("N2:BAC:9", WATER), "integrate", "--scheme", "N2:BAC:9", "--inertia", "water", "--h", "0.1")
    raises_as_cli(lambda: rotlie.scheme("Nope", WATER), "integrate", "--scheme", "Nope", "--inertia", "water", "--h", "0.1")
    raises_as_cli(lambda: rotlie.integrate("ABCBA2", WATER, [1, 1, 1], h=-1, steps=1),
                  "integrate", "--scheme", "ABCBA2", "--inertia", "water", "--h", "-1")
    raises_as_cli(lambda: rotlie.order("ABCBA2", WATER, scalar="float80"),
                  "order", "--scheme", "ABCBA2", "--inertia", "water", "--scalar", "float80")
    raises_as_cli(lambda: rotlie.order("ABCBA2", WATER, min_level=5, max_level=3),
                  "order", "--scheme", "ABCBA2", "--inertia", "water", "--min-level", "5", "--max-level", "3")


def test_remainder_and_two_parameter_limits_match_the_command_line():
    """The limits on a raw word (runs/remainder_run) and the Q, QRS inputs are refused as by the CLI."""
    raises_as_cli(lambda: rotlie.remainder("ABCBACBCBABCBACBA", order=7),
                  "remainder", "--scheme", "ABCBACBCBABCBACBA", "--order", "7")
    raises_as_cli(lambda: rotlie.remainder("AB" * 21 + "C", order=3), "remainder", "--scheme", "AB" * 21 + "C", "--order", "3")
    raises_as_cli(lambda: rotlie.remainder("ABABA", order=3), "remainder", "--scheme", "ABABA", "--order", "3")
    raises_as_cli(lambda: rotlie.remainder("ABCBA", order=3, coeffs={"x": 1}),
                  "remainder", "--scheme", "ABCBA", "--order", "3", "--coeffs", "x=1")
    raises_as_cli(lambda: rotlie.solve(WATER, family="Q", scheme="ABCBA"),
                  "solve", "--family", "Q", "--scheme", "ABCBA", "--inertia", "water")
    raises_as_cli(lambda: rotlie.solve(WATER, family="QRS", starts=0),
                  "solve", "--family", "QRS", "--starts", "0", "--inertia", "water")
    with pytest.raises(ValueError, match="--starts and --seed apply to"):
        rotlie.solve(WATER, family="N", seed=3)


def test_bad_arrays_and_values():
    s = rotlie.scheme("ABCBA4-SS3-Yoshida")
    with pytest.raises(ValueError):
        rotlie.integrate(s, WATER, np.ones((4, 2)), h=0.1, steps=1)
    with pytest.raises(ValueError):
        rotlie.integrate(s, WATER, np.ones((4, 3)), np.ones((3, 3, 3)), h=0.1, steps=1)
    with pytest.raises(ValueError):
        rotlie.integrate(s, WATER, [np.nan, 1, 1], h=0.1, steps=1)
    with pytest.raises(ValueError):
        rotlie.integrate(s, WATER, [1, 1, 1], h=0.1, steps=-1)
    with pytest.raises(ValueError):
        rotlie.integrate(s, WATER, [1, 1, 1], h=0.1, steps=1, scalar="half")
    with pytest.raises(ValueError):
        rotlie.integrate("Strang-TV", WATER, [1, 1, 1], h=0.1, steps=1)  # a torqued-body table
    with pytest.raises(ValueError, match="2\\^60"):
        rotlie.exact_flow(WATER, [1, 1, 1], t=1e30)
    # the limit in six significant digits: std::to_string once printed this one as "|t| ≤ 0.000000"
    with pytest.raises(ValueError, match="\\|t\\| ≤ [1-9](\\.[0-9]+)?e-12[0-9] here"):
        rotlie.exact_flow(WATER, [1e140, 1e140, 1e140], t=1.0)
    with pytest.raises(ValueError):
        rotlie.exact_flow(WATER, [1, 1, 1], t=np.inf)
    with pytest.raises(TypeError):
        rotlie.exact_flow(WATER, [1, 1, 1])


def test_missing_and_bad_table_files(tmp_path):
    with pytest.raises(ValueError, match="no scheme-table file"):
        rotlie.load_table(tmp_path / "none.scheme")
    bad = tmp_path / "bad.scheme"
    bad.write_text("format_version 1\nname x\n")
    with pytest.raises(ValueError, match="bad.scheme"):
        rotlie.load_table(bad)
    with pytest.raises(RuntimeError):
        rotlie.scheme("ABCBA2").save(tmp_path / "no-such-folder" / "x.scheme")


def test_a_table_for_another_body_is_refused_unless_forced():
    n2 = rotlie.scheme("N2:BAC:2", WATER)
    other = rotlie.Body("0.4", "0.7", "1")
    with pytest.raises(ValueError, match="force"):
        rotlie.integrate(n2, other, [1, 1, 1], h=0.1, steps=1)
    with pytest.warns(UserWarning, match="used anyway"):
        rotlie.integrate(n2, other, [1, 1, 1], h=0.1, steps=1, force=True)
    # the same body in another unit is the same body
    scaled = rotlie.Body(*(2 * m for m in WATER.moments))
    rotlie.integrate(n2, scaled, [1, 1, 1], h=0.1, steps=1)


def test_momenta_out_of_range_are_refused_as_by_the_command_line():
    with pytest.raises(ValueError, match="outside the range"):
        rotlie.integrate("ABCBA2", WATER, [[1, 1, 1], [1e308, 1e308, 1e308]], h=1, steps=3)
    with pytest.raises(ValueError, match="outside the range"):
        rotlie.exact_flow(WATER, [1e-200, 0, 0], t=1)
    G, Q = rotlie.integrate("ABCBA2", WATER, [0, 0, 0], h=1, steps=3)  # a body at rest stays so
    assert G.tolist() == [0, 0, 0] and Q.tolist() == np.eye(3).tolist()


def test_nothing_is_printed(capfd):
    rotlie.solve(WATER, perm="BAC", scheme="N2")
    rotlie.integrate("N2:BAC:2", WATER, [1, 1, 1], h=0.1, steps=10)
    rotlie.order("ABCBA2", WATER, max_level=4)
    out, _ = capfd.readouterr()
    assert out == ""
