"""rotlie.md at a temperature (docs/thermostats.md): the keywords reach the scene, the JSON comes back as
attributes, and misuse raises ValueError as the command line refuses it."""
import pytest

import rotlie


def test_free_water_at_a_temperature_reaches_maxwell_boltzmann():
    r = rotlie.md("free-water", "SIER2-BAOAB", h=4, T=4, runs=100, temperature=320, friction=2, seed=5)
    assert r.ensemble == "NVT" and r.table == "Strang-TV+BAOAB" and r.target_K == 320
    assert r.maxwell_boltzmann
    for mean, error in (r.translational_K, r.rotational_K):
        assert abs(mean - 320) < 4 * error


def test_chains_take_tau_and_the_same_seed_repeats():
    a = rotlie.md("free-water", "SIER4-NHC", h=8, T=2, runs=20, tau=0.2, seed=3)
    b = rotlie.md("free-water", "SIER4-NHC", h=8, T=2, runs=20, tau=0.2, seed=3)
    assert a.rotational_K == b.rotational_K


@pytest.mark.parametrize("kwargs", [dict(integrator="SIER2", temperature=300), dict(integrator="SIER2-NHC", friction=1),
                                    dict(integrator="SIER2-BAOAB", tau=0.1)])
def test_misused_keywords_raise(kwargs):
    integrator = kwargs.pop("integrator")
    with pytest.raises(ValueError):
        rotlie.md("free-water", integrator, h=4, T=1, runs=20, **kwargs)
