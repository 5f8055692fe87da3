"""DW and MD equilibria: broadcasting, limits, roots against the principal state."""

import numpy as np
import pytest

import wavyadhesion as wa

COHESIVE = ["dw", "md"]


@pytest.mark.parametrize("model", wa.MODELS)
def test_broadcast_shapes(model):
    alpha = np.array([0.2, 0.3, 0.6]).reshape(3, 1, 1)
    mu = np.array([0.5, 2.0]).reshape(1, 2, 1)
    a = np.linspace(0.05, 0.45, 4)
    eq = wa.equilibrium(model, alpha, mu, a)
    for arr in eq:
        assert arr.shape == (3, 2, 4)
    assert eq.zone_case.dtype.kind == "i"
    # every element equals the scalar call
    for i, j, k in [(0, 0, 0), (2, 1, 3), (1, 0, 2)]:
        one = wa.equilibrium(model, alpha[i, 0, 0], mu[0, j, 0], a[k])
        assert one.c_star == eq.c_star[i, j, k]
        assert one.P_star == eq.P_star[i, j, k]
        assert one.zone_case == eq.zone_case[i, j, k]


def test_scalar_inputs_give_scalars():
    eq = wa.equilibrium("dw", 0.3, 1.0, 0.2)
    assert all(np.ndim(x) == 0 for x in eq)
    assert isinstance(eq.P_star, np.floating)


def test_non_contiguous_and_list_inputs():
    a = np.linspace(0.01, 0.49, 40)[::3]
    eq1 = wa.equilibrium("dw", 0.3, 1.0, a)
    eq2 = wa.equilibrium("dw", [0.3], 1, list(a))
    np.testing.assert_array_equal(eq1.P_star, eq2.P_star)


def test_empty_input():
    eq = wa.equilibrium("dw", 0.3, 1.0, np.empty((0, 3)))
    assert eq.P_star.shape == (0, 3)


def test_model_names_case_insensitive():
    assert wa.equilibrium("DW", 0.3, 1.0, 0.2) == wa.equilibrium("dw", 0.3, 1.0, 0.2)


@pytest.mark.parametrize("model", COHESIVE)
def test_small_mu_is_westergaard(model):
    a = np.linspace(0.02, 0.48, 24)
    eq = wa.equilibrium(model, 0.3, 0.0, a)
    np.testing.assert_allclose(eq.P_star, wa.westergaard_load(a), rtol=1e-14, atol=1e-15)


@pytest.mark.parametrize("model", COHESIVE)
def test_full_contact(model):
    eq = wa.equilibrium(model, 0.3, 1.0, 0.5)
    assert eq.zone_case == 3 and eq.c_star == 0.5


@pytest.mark.parametrize("model", COHESIVE)
def test_states_are_physical(model):
    a = np.linspace(0.01, 0.49, 49)
    eq = wa.equilibrium(model, 0.3, 1.0, a)
    assert np.all(np.isfinite(eq.P_star))
    assert np.all(eq.c_star >= a) and np.all(eq.c_star <= 0.5)
    assert set(np.unique(eq.zone_case)) <= {1, 2}


@pytest.mark.parametrize("model", COHESIVE)
def test_roots_first_is_principal(model):
    for a in (0.05, 0.2, 0.35):
        states = wa.roots(model, 0.3, 1.0, a)
        eq = wa.equilibrium(model, 0.3, 1.0, a)
        assert len(states) >= 1
        assert states[0].zone_case == eq.zone_case
        assert states[0].c_star == pytest.approx(eq.c_star, rel=1e-12)
        assert states[0].P_star == pytest.approx(eq.P_star, rel=1e-12, abs=1e-14)
        assert states[0].gap_width == pytest.approx(eq.c_star - a, rel=1e-9, abs=1e-15)
        c = [s.c_star for s in states if s.zone_case == 1]
        assert c == sorted(c)
        assert all(s.a_star == a for s in states)


def test_errors_nan_mode_marks_failed_points():
    eq = wa.equilibrium("dw", 0.3, 1.0, [0.1, 0.7, 0.2], errors="nan")
    assert np.isnan(eq.P_star[1]) and np.isnan(eq.c_star[1]) and eq.zone_case[1] == 0
    assert np.isfinite(eq.P_star[[0, 2]]).all()


@pytest.mark.parametrize("model", COHESIVE)
def test_roots_finite_on_a_grid(model):
    """Every state on a grid is finite and ordered (a* = 0.021896... at alpha = 0.1,
    mu = 3 once produced a NaN state from a scan abscissa rounded beyond s = 1)."""
    for alpha in (0.1, 0.3, 1.0):
        for mu in (0.3, 3.0):
            for a in np.linspace(0.005, 0.495, 30):
                for s in wa.roots(model, alpha, mu, a):
                    assert np.isfinite([s.c_star, s.P_star, s.gap_width]).all(), (alpha, mu, a)
                    assert a <= s.c_star <= 0.5 and s.zone_case in (1, 2)


def test_md_three_states(monkeypatch):
    """MD at (0.3, 1, 0.3) has two case-1 states and a case-2 state (test/data/md.txt);
    with a first capacity of 1, roots() must fetch the rest in a second call."""
    full = wa.roots("md", 0.3, 1.0, 0.3)
    assert [s.zone_case for s in full] == [1, 1, 2]
    assert full[0].c_star < full[1].c_star < full[2].c_star == 0.5
    from wavyadhesion import _equilibrium
    monkeypatch.setattr(_equilibrium, "_ROOTS_CAPACITY", 1)
    assert wa.roots("md", 0.3, 1.0, 0.3) == full
