"""Params: derived quantities and the dimensional round trip (doc/theory.md, "Parameters")."""

import math

import pytest

import wavyadhesion as wa


def test_derived():
    p = wa.Params(0.3, 1.0)
    assert p.sigma0 == pytest.approx(math.pi * (0.3 ** 2 / 32) ** (1 / 3), rel=1e-15)
    assert p.dcod == pytest.approx((0.3 ** 4 / 2) ** (1 / 3), rel=1e-15)
    assert p.scales is None
    assert wa.Params(0.3, 0.0).dcod == math.inf


def test_frozen():
    p = wa.Params(0.3, 1.0)
    with pytest.raises(AttributeError):
        p.alpha = 2.0


@pytest.mark.parametrize("moduli", [
    dict(Estar=2.0e9),
    dict(E1=1.0e9, nu1=0.4, E2=2.1e11, nu2=0.3),
])
def test_dimensional_round_trip(moduli):
    L, delta, dgamma, sigma = 2.0e-4, 1.0e-6, 0.08, 3.0e7
    p = wa.Params.from_dimensional(period=L, amplitude=delta, work_of_adhesion=dgamma,
                                   peak_stress=sigma, **moduli)
    s = p.scales
    if "Estar" in moduli:
        estar = moduli["Estar"]
    else:
        estar = 1.0 / ((1 - moduli["nu1"] ** 2) / moduli["E1"]
                       + (1 - moduli["nu2"] ** 2) / moduli["E2"])
    assert s.estar == pytest.approx(estar, rel=1e-15)
    assert s.pressure == pytest.approx(math.pi * estar * delta / L, rel=1e-15)
    assert s.force == pytest.approx(s.pressure * L, rel=1e-15)
    assert s.length == L
    assert s.radius == pytest.approx(L ** 2 / (4 * math.pi ** 2 * delta), rel=1e-15)
    # back to the physical inputs: dgamma from alpha, sigma0 from Sigma0 = sigma0/p*
    assert p.alpha ** 2 * math.pi ** 2 * estar * delta ** 2 / (2 * L) == pytest.approx(
        dgamma, rel=1e-13)
    assert p.sigma0 * s.pressure == pytest.approx(sigma, rel=1e-13)
    # and mu agrees with its dimensional form 4 sigma0 (R/(pi^2 E*^2 dgamma))^(1/3)
    mu = 4 * sigma * (s.radius / (math.pi ** 2 * estar ** 2 * dgamma)) ** (1 / 3)
    assert p.mu == pytest.approx(mu, rel=1e-13)
    # a Params made from (alpha, mu) carries the same derived values
    q = wa.Params(p.alpha, p.mu)
    assert q.sigma0 == pytest.approx(p.sigma0, rel=1e-15)
    assert q.dcod == pytest.approx(p.dcod, rel=1e-15)
