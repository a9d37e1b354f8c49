"""exact_flow, integrate and order: the numbers of `rotlie exact` and `rotlie order`, vectorised calls
equal to row-by-row calls bit for bit, and the order of a dedicated scheme measured against the exact flow."""
import numpy as np
import pytest

import rotlie

from conftest import cli

WATER = rotlie.Body.named("water")


def random_states(n, seed=7):
    rng = np.random.default_rng(seed)
    G = rng.normal(size=(n, 3))
    Q = np.empty((n, 3, 3))
    for i in range(n):  # random attitudes: Q of a random matrix, signs fixed, a reflection turned into a rotation
        q, r = np.linalg.qr(rng.normal(size=(3, 3)))
        q = q * np.sign(np.diag(r))
        Q[i] = q if np.linalg.det(q) > 0 else q * np.array([1, 1, -1])
    return G, Q


def test_exact_flow_as_the_command_line():
    e = cli("exact", "--inertia", "0.4,0.7,1", "--T", "100", "--G0", "0.1,1,0.2", "--json")
    G, Q, err = rotlie.exact_flow(rotlie.Body("0.4", "0.7", "1"), [0.1, 1, 0.2], t=100, error_estimate=True)
    assert G.shape == (3,) and Q.shape == (3, 3)
    assert G.tolist() == e["G"] and Q.tolist() == e["Q"] and err == e["error_estimate"]


def test_exact_flow_invariants():
    G0, Q0 = random_states(50)
    G, Q = rotlie.exact_flow(WATER, G0, Q0, t=np.linspace(0.1, 30, 50))
    I = np.array([float(m) for m in WATER.moments])
    # |G| and the energy G·I⁻¹G are constants of the motion; Q stays a rotation; Q G (space frame) is fixed
    assert np.allclose(np.linalg.norm(G, axis=1), np.linalg.norm(G0, axis=1), rtol=1e-13)
    assert np.allclose((G**2 / I).sum(axis=1), (G0**2 / I).sum(axis=1), rtol=1e-12)
    assert np.allclose(Q @ np.swapaxes(Q, 1, 2), np.eye(3), atol=1e-13)
    # Q maps the body frame to space: the spatial angular momentum Q G is a constant of the motion
    assert np.allclose(np.einsum("nij,nj->ni", Q, G), np.einsum("nij,nj->ni", Q0, G0), atol=1e-12)


@pytest.mark.parametrize("scalar", ["double", "long-double", "float128"])
def test_exact_flow_vectorised_equals_row_by_row(scalar):
    G0, Q0 = random_states(40)
    t = np.linspace(0.5, 20, 40)
    G, Q = rotlie.exact_flow(WATER, G0, Q0, t=t, scalar=scalar)
    for i in range(len(G0)):
        g, q = rotlie.exact_flow(WATER, G0[i], Q0[i], t=t[i], scalar=scalar)
        assert np.array_equal(g, G[i]) and np.array_equal(q, Q[i])


@pytest.mark.parametrize("scalar", ["double", "long-double", "float128"])
def test_integrate_vectorised_equals_row_by_row(scalar):
    scheme = rotlie.scheme("RS4-S5-McLachlan:CBA")
    G0, Q0 = random_states(30)
    G, Q = rotlie.integrate(scheme, WATER, G0, Q0, h=0.01, steps=25, scalar=scalar)
    assert G.shape == (30, 3) and Q.shape == (30, 3, 3)
    for i in range(len(G0)):
        g, q = rotlie.integrate(scheme, WATER, G0[i], Q0[i], h=0.01, steps=25, scalar=scalar)
        assert np.array_equal(g, G[i]) and np.array_equal(q, Q[i])


def test_integrate_keeps_the_invariants_and_the_scalars_agree():
    G0, Q0 = random_states(20)
    scheme = rotlie.scheme("N2:BAC:2", WATER)
    G, Q = rotlie.integrate(scheme, WATER, G0, Q0, h="1/64", steps=64)
    # every stage is a rotation of G: |G| is kept to round-off
    assert np.allclose(np.linalg.norm(G, axis=1), np.linalg.norm(G0, axis=1), rtol=1e-13)
    assert np.allclose(Q @ np.swapaxes(Q, 1, 2), np.eye(3), atol=1e-13)
    G128, Q128 = rotlie.integrate(scheme, WATER, G0, Q0, h="1/64", steps=64, scalar="float128")
    assert np.max(np.abs(Q128 - Q)) < 1e-12 and not np.array_equal(Q128, Q)
    assert rotlie.integrate(scheme, WATER, G0, Q0, h=0.1, steps=0)[0].tolist() == G0.tolist()


def test_integrate_converges_at_order_four_in_float128():
    """N2 BAC (2) solved for water against the exact flow: the slope of log error on log h is 4 ± 0.1."""
    scheme = next(s for s in rotlie.solve(WATER, family="N", perm="BAC", scheme="N2") if s.name == "N2:BAC:2")
    assert scheme.order == 4
    G0, Q0 = random_states(8, seed=3)
    T = 1.0
    _, Q_exact = rotlie.exact_flow(WATER, G0, Q0, t=T, scalar="float128")
    hs, errors = [], []
    for level in range(3, 7):
        steps = 2**level
        _, Q = rotlie.integrate(scheme, WATER, G0, Q0, h=f"1/{steps}", steps=steps, scalar="float128")
        hs.append(T / steps)
        errors.append(np.max(np.abs(Q - Q_exact)))
    slope = np.polyfit(np.log(hs), np.log(errors), 1)[0]
    assert abs(slope - 4) <= 0.1, (slope, errors)


def test_order_as_the_command_line():
    e = cli("order", "--scheme", "RS4-S5-McLachlan:CBA", "--inertia", "water", "--max-level", "6", "--json")
    r = rotlie.order("RS4-S5-McLachlan:CBA", WATER, max_level=6)
    assert r["scheme"] == e["scheme"] and r["declared_order"] == e["declared_order"] and r["slope"] == e["slope"]
    assert [(p["h"], p["error"]) for p in r["points"]] == [(p["h"], p["error"]) for p in e["points"]]
    assert abs(r["slope"] - 4) < 0.3


def test_integrate_by_name_as_order_does():
    by_name = rotlie.integrate("N2:BAC:2", WATER, [1, 1, 1], h=0.01, steps=10)
    by_object = rotlie.integrate(rotlie.scheme("N2:BAC:2", WATER), WATER, [1, 1, 1], h=0.01, steps=10)
    assert np.array_equal(by_name[1], by_object[1])
