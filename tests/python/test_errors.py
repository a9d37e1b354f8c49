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
    with pytest.raises(ValueError, match="starts and seed apply to"):
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


def test_save_never_replaces_a_link_fifo_or_device(tmp_path):
    """save() writes a regular file; a link is written through to its regular target; anything else is refused."""
    import os
    s = rotlie.scheme("ABCBA2")
    target = tmp_path / "target.scheme"
    target.write_text("old\n")
    link = tmp_path / "link.scheme"
    link.symlink_to("target.scheme")
    s.save(link)
    assert link.is_symlink() and rotlie.load_table(target).name == s.name
    fifo = tmp_path / "fifo.scheme"
    os.mkfifo(fifo)
    with pytest.raises(RuntimeError, match="regular files only"):
        s.save(fifo)
    assert fifo.is_fifo()
    if os.geteuid() == 0:  # a device node of the test's own: a faulty save must not replace the machine's /dev/null
        import stat
        device = tmp_path / "null"
        os.mknod(device, 0o666 | stat.S_IFCHR, os.makedev(1, 3))
        with pytest.raises(RuntimeError, match="it is a device"):
            s.save(device)
        assert stat.S_ISCHR(os.stat(device).st_mode)
    dangling = tmp_path / "dangling.scheme"
    dangling.symlink_to("missing.scheme")
    with pytest.raises(RuntimeError, match="does not exist"):
        s.save(dangling)
    assert dangling.is_symlink() and not (tmp_path / "missing.scheme").exists()


def test_table_files_are_bounded_as_on_the_command_line(tmp_path):
    big = tmp_path / "big.scheme"
    big.write_bytes(b"#" * (1 << 20) + b"\n")
    with pytest.raises(ValueError) as e:
        rotlie.load_table(big)
    assert "bytes" in str(e.value) and "\n" not in str(e.value)
    import os
    fifo = tmp_path / "fifo.scheme"
    os.mkfifo(fifo)
    with pytest.raises(ValueError, match="not a regular file"):
        rotlie.load_table(fifo)  # returns: no writer is waited for


def test_attitudes_must_be_rotations_and_arrays_real():
    with pytest.raises(ValueError, match="not a rotation"):
        rotlie.exact_flow(WATER, [1, 1, 1], 2 * np.eye(3), t=1)
    with pytest.raises(ValueError, match="not a rotation") as e:
        rotlie.integrate("ABCBA2", WATER, [1, 1, 1], np.diag([1.0, 1.0, -1.0]), h=0.1, steps=1)  # a reflection
    # the numbers shown are finite and true (issue 46: it printed inf where the gap is 0)
    assert "|QᵀQ − 1| = 0, det -1: a reflection" in str(e.value) and "inf" not in str(e.value)
    with pytest.raises(ValueError, match=r"= 74, det") as e:
        rotlie.exact_flow(WATER, [1, 1, 1], np.diag([1.0, 1.0, 75 ** 0.5 * 1.0]), t=1)
    assert "inf" not in str(e.value)
    with pytest.raises(TypeError, match="G0 must be real"):
        rotlie.exact_flow(WATER, [1 + 1j, 1, 1], t=1)
    with pytest.raises(TypeError, match="Q0 must be real"):
        rotlie.exact_flow(WATER, [1, 1, 1], np.eye(3) * (1 + 0j), t=1)
    with pytest.raises(TypeError, match="t must be real"):
        rotlie.exact_flow(WATER, [1, 1, 1], t=1j)
    # a rotation rounded to ten digits is still one
    c, s = np.cos(0.3), np.sin(0.3)
    rotlie.exact_flow(WATER, [1, 1, 1], np.round(np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]]), 10), t=1)


def test_out_of_range_integers_are_one_line_errors():
    for call in (lambda: rotlie.integrate("ABCBA2", WATER, [1, 1, 1], h=0.1, steps=10**30),
                 lambda: rotlie.solve(WATER, digits=2**70),
                 lambda: rotlie.bch("XY", 10**20)):
        with pytest.raises(ValueError) as e:
            call()
        assert "\n" not in str(e.value) and "outside" in str(e.value)
    with pytest.raises(TypeError, match="steps must be an integer"):
        rotlie.integrate("ABCBA2", WATER, [1, 1, 1], h=0.1, steps=1.5)


def test_messages_show_numbers_in_a_few_digits():
    # |G0| = 1e-200 once read "|G0| = 0.000000", and 1.7e150 a 151-digit integer
    for G in ([1e-200, 0, 0], [1.7e150, 0, 0]):
        with pytest.raises(ValueError) as e:
            rotlie.exact_flow(WATER, G, t=1)
        message = str(e.value)
        assert "0.000000" not in message and len(message) < 200, message
        assert "1e-200" in message or "1.7e+150" in message, message
