"""Profiles (traction, gap) and the mean gap gbar in the Python layer: values of the mpmath
tables test/data/separation_*.txt (tools/reference/make_separation_reference.py), the identities
(traction mean = P*, gap = 0 on the contact, gap mean = gbar), and the errors."""

import numpy as np
import pytest

import wavyadhesion as wa

MODELS = ("westergaard", "jkr", "dw", "md")
TABLES = {"westergaard": "westergaard", "jkr": "jkr", "dw": "dw", "md": "md",
          "md_nocontact": "md"}


def _rows(repo, name, step):
    t = np.loadtxt(repo / "test" / "data" / f"separation_{name}.txt")
    return t[::step]


def _close(got, want, rel):
    return abs(got - want) <= rel * max(abs(want), 1e-3)


@pytest.mark.parametrize("table", TABLES)
def test_profile_against_reference(repo, table):
    model = TABLES[table]
    rows = _rows(repo, table, 5)
    checked = 0
    for alpha, mu, a, c, _, p, zone, _, x, traction, gap, gbar in rows:
        if zone == 0 and c == 0.5:
            continue                                 # c* = 1/2 without contact: not one state
        alpha = alpha if alpha > 0 else 1.0          # Westergaard rows carry alpha = 0
        xs, t, h = wa.profile(model, alpha, mu, a, c, [x])
        xr = abs(x - round(x))
        near_edge = min(abs(xr - c), abs(xr - a)) < 1e-12
        assert _close(h[0], gap, 1e-10 if not near_edge else 1e-6), (table, a, c, x, h[0], gap)
        if not near_edge:
            assert _close(t[0], traction, 1e-10), (table, a, c, x, t[0], traction)
        if zone != 0:
            states = wa.roots(model, alpha, mu, a)
            s = min(states, key=lambda s: abs(s.c_star - c))
            assert _close(s.gbar, gbar, 1e-10), (table, a, c, s.gbar, gbar)
        checked += 1
    assert checked > 10


@pytest.mark.parametrize("model", MODELS)
@pytest.mark.parametrize("a", [0.1, 0.25, 0.4])
def test_profile_identities(model, a):
    n = 40000
    x = -0.5 + (np.arange(n) + 0.5) / n
    for s in wa.roots(model, 0.3, 1.0, a):
        xs, t, h = wa.profile(model, 0.3, 1.0, a, s.c_star, x)
        assert np.isfinite(t).all() and np.isfinite(h).all() and (h >= 0).all()
        assert (h[np.abs(x) < a] == 0).all()
        assert abs(h.mean() - s.gbar) < 1e-6                   # midpoint rule, smooth h
        assert abs(t.mean() - s.P_star) < (2e-2 if model == "jkr" else 1e-3)  # edges
        if model == "md" and s.zone_case == 1:
            dcod = wa.Params(0.3, 1.0).dcod
            hc = wa.profile(model, 0.3, 1.0, a, s.c_star, [s.c_star]).gap[0]
            assert hc == pytest.approx(2 * dcod, rel=1e-10)


def test_profile_default_grid_and_principal_state():
    x, t, h = wa.profile("dw", 0.3, 1.0, 0.2)
    assert x.shape == (401,) and x[0] == -0.5 and x[-1] == 0.5
    eq = wa.equilibrium("dw", 0.3, 1.0, 0.2)
    same = wa.profile("dw", 0.3, 1.0, 0.2, float(eq.c_star))
    assert np.allclose(same.traction, t, rtol=1e-10, atol=1e-14)
    assert np.allclose(same.gap, h, rtol=1e-10, atol=1e-14)
    shaped = wa.profile("md", 0.3, 1.0, 0.2, x=np.zeros((2, 3)) + 0.4)
    assert shaped.gap.shape == (2, 3) and (shaped.gap > 0).all()


def test_profile_md_without_contact():
    dcod = wa.Params(0.3, 1.0).dcod
    x, t, h = wa.profile("md", 0.3, 1.0, 0.0, 0.05, [0.0, 0.05, 0.3])
    assert t[0] < 0 and t[2] == 0
    assert h[1] == pytest.approx(2 * dcod, rel=1e-12) and 0 < h[0] < h[1] < h[2]


def test_gbar_everywhere():
    a = np.array([0.05, 0.2, 0.35, 0.5])
    eq = wa.equilibrium("westergaard", 0.3, 1.0, a)
    s2 = np.sin(np.pi * a) ** 2
    with np.errstate(divide="ignore", invalid="ignore"):
        want = np.where(s2 < 1, 1 - s2 + s2 * np.log(s2), 0.0)
    assert np.allclose(eq.gbar, want, rtol=1e-13, atol=1e-15)
    for model in ("dw", "md"):
        eq = wa.equilibrium(model, 0.3, 1.0, a)
        states = [wa.roots(model, 0.3, 1.0, v)[0] for v in a]
        assert np.allclose(eq.gbar, [s.gbar for s in states], rtol=1e-12)
        assert eq.gbar[-1] == 0.0
        b = wa.trace_branch(model, 0.3, 1.0)
        assert b.gbar.shape == b.a_star.shape and np.isfinite(b.gbar).all()
        assert (b.gbar >= 0).all() and b.gbar[-1] < 1e-6
    # Westergaard: the work to flatten the wave, int_0^1 P* d(gbar) = 1/4
    b = wa.trace_branch("westergaard", 0.3, 1.0)
    order = np.argsort(b.gbar)
    g, p = b.gbar[order], b.P_star[order]
    assert abs(np.sum(0.5 * (p[1:] + p[:-1]) * np.diff(g)) - 0.25) < 1e-3


def test_profile_errors():
    with pytest.raises(wa.NoSolutionError, match="nearest"):
        wa.profile("dw", 0.3, 1.0, 0.2, 0.49)
    with pytest.raises(wa.NoSolutionError, match="jkr"):
        wa.profile("jkr", 0.3, 1.0, 0.5)
    with pytest.raises(wa.NoSolutionError, match="dw"):
        wa.profile("dw", 0.3, 1.0, 0.0, 0.1)
    with pytest.raises(wa.InvalidArgumentError, match="c_star"):
        wa.profile("md", 0.3, 1.0, 0.0)
    with pytest.raises(ValueError, match="c_star"):
        wa.profile("dw", 0.3, 1.0, 0.2, 0.7)
    with pytest.raises(ValueError, match="a_star"):
        wa.profile("dw", 0.3, 1.0, 0.6)
    with pytest.raises(ValueError, match="alpha"):
        wa.profile("dw", -1.0, 1.0, 0.2)
    with pytest.raises(ValueError, match="x: every value"):
        wa.profile("dw", 0.3, 1.0, 0.2, x=[0.1, np.nan])
    with pytest.raises(wa.InvalidTypeError, match="c_star"):
        wa.profile("dw", 0.3, 1.0, 0.2, "0.3")
    with pytest.raises(wa.InvalidTypeError, match="x"):
        wa.profile("dw", 0.3, 1.0, 0.2, x=[0.1, None])
    with pytest.raises(wa.InvalidTypeError, match="model"):
        wa.profile(3, 0.3, 1.0, 0.2)
    with pytest.raises(ValueError, match="a_star must be a scalar"):
        wa.profile("dw", 0.3, 1.0, [0.2, 0.3])
