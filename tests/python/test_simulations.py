"""rotlie.spin_simulation and rotlie.md_simulation (issue 43): a held run continued by integrate(t) to an
absolute time equals one integrate to the end bit for bit, and equals rotlie.spin / rotlie.md's run to the
same time (their final state, or the trajectory's last sample); off-grid targets, the past refused."""
from fractions import Fraction

import numpy as np
import pytest

import rotlie


def same(a, b):
    """Bit for bit: the same shapes and the same bytes."""
    a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    return a.shape == b.shape and a.tobytes() == b.tobytes()


def spin_state(s):
    return (s.steps, s.t, s.Q.tobytes(), s.G.tobytes(), s.omega_body.tobytes(), s.theta, s.energy, s.evaluations)


@pytest.mark.parametrize("integrator, scalar", [("SIER4", "double"), ("MRDL", "long-double"), ("odeint-dopri5:1e-10", "double")])
def test_spin_simulation_continues_and_equals_spin(integrator, scalar):
    keywords = dict(body="Hyperion", e=0.1, integrator=integrator, h=Fraction(1, 64), theta0=0.3, omega0=1.5, obliquity=0.2,
                    scalar=scalar)
    halves, whole = rotlie.spin_simulation(**keywords), rotlie.spin_simulation(**keywords)
    assert isinstance(whole, rotlie.SpinSimulation) and whole.t == 0 and whole.steps == 0
    start_Q = whole.Q.copy()
    halves.integrate(1)
    assert halves.steps == 64 and halves.t == 1
    halves.integrate(2)
    whole.integrate(2)
    assert whole.steps == 128 and whole.t == 2
    assert spin_state(halves) == spin_state(whole)
    assert not same(whole.Q, start_Q)
    r = rotlie.spin(T=2, **keywords)
    assert same(whole.Q, r.Q) and same(whole.omega_body, r.omega_body)
    assert whole.theta == r.theta and whole.energy == r.energy_end and whole.evaluations == r.evaluations
    assert (whole.integrator, whole.scalar, whole.h) == (integrator, scalar, 1 / 64)


def test_spin_simulation_off_the_grid_the_past_and_steps():
    sim = rotlie.spin_simulation("Moon", e=0.0549, integrator="SIER4", h="1/100")
    sim.integrate(0.105)  # 10.5 steps: the 10 whose end is at most t
    assert sim.steps == 10
    sim.integrate(0.11)  # 11 steps of 0.01, 0.11/0.01 = 11 to round-off
    assert sim.steps == 11
    with pytest.raises(ValueError, match="before the simulation's time"):
        sim.integrate(0.05)
    assert sim.steps == 11
    stepped = rotlie.spin_simulation("Moon", e=0.0549, integrator="SIER4", h="1/100")
    for _ in range(11):
        stepped.step()
    assert spin_state(stepped) == spin_state(sim)


def test_spin_simulation_refuses_what_spin_refuses():
    with pytest.raises(ValueError, match="integrator"):
        rotlie.spin_simulation("Moon", e=0, integrator="NOPE", h="1/100")
    with pytest.raises(ValueError, match="e "):
        rotlie.spin_simulation("Moon", e=1.5, integrator="SIER4", h="1/100")
    with pytest.raises(TypeError):
        rotlie.spin_simulation("Moon", e=0, integrator="SIER4", h="1/100", T=1)


def md_state(s):
    return (s.steps, s.t, s.q.tobytes(), s.p.tobytes(), s.Q.tobytes(), s.G.tobytes(), s.energy.tobytes(), s.potential.tobytes(),
            s.evaluations)


@pytest.mark.filterwarnings("ignore:delta stays below")  # free water with an exact rotor: round-off only
@pytest.mark.parametrize("scene, integrator, extra", [("free-water", "SIER4", {}), ("dipole-field", "SIER4", {"field": 5}),
                                                      ("dipole-field", "MRDL", {"scalar": "long-double"})])
def test_md_simulation_continues_and_equals_md(scene, integrator, extra):
    keywords = dict(runs=3, seed=5, **extra)
    halves, whole = (rotlie.md_simulation(scene, integrator, 4, **keywords) for _ in range(2))
    assert isinstance(whole, rotlie.MdSimulation) and whole.runs == 3 and whole.h == 4
    assert whole.Q.shape == (3, 3, 3) and whole.G.shape == (3, 3) and whole.energy.shape == (3,)
    start = md_state(whole)
    halves.integrate(0.2)
    assert halves.steps == 50
    halves.integrate(0.4)
    whole.integrate(0.4)
    assert whole.steps == 100 and whole.t == 0.4
    assert md_state(halves) == md_state(whole)
    assert md_state(whole) != start
    tr = rotlie.md(scene, integrator, 4, T=0.4, every=100, **keywords).trajectory
    assert tr.t_ps[-1] == whole.t
    assert same(tr.Q[-1], whole.Q[0]) and same(tr.G[-1], whole.G[0])
    assert tr.energy[-1] == whole.energy[0] and tr.potential[-1] == whole.potential[0]


def test_md_simulation_spin_orbit_scene_and_refusals():
    s = rotlie.md_simulation("spin-orbit", "SIER4", "1/64", body="Moon", e=0)
    assert isinstance(s, rotlie.SpinSimulation)
    s.integrate(0.5)
    assert s.steps == 32
    with pytest.raises(ValueError):
        rotlie.md_simulation("free-water", "SIER4", 4, molecules=400)
    with pytest.raises(ValueError, match="cannot be held"):
        rotlie.md_simulation("liquid-water", "SIER4", 4)
    with pytest.raises(ValueError, match="before"):
        m = rotlie.md_simulation("free-water", "SIER2", 4, runs=1)
        m.integrate(0.04)
        m.integrate(0.02)
