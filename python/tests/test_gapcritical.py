"""wavyadhesion.gap_critical: the critical values under gap control (issue 11 item 3)."""
import math

import numpy as np
import pytest

import wavyadhesion as wa


def test_fields_and_westergaard():
    assert wa.GAP_CRITICAL_FIELDS == wa.GapCritical._fields[:10]
    g = wa.gap_critical("westergaard", 0.3, 1.0)
    assert float(g.g_touch) == 1.0 and float(g.P_jump_in) == 0.0
    assert float(g.g_contact) == 1.0 and float(g.g_contact_lost) == 1.0
    assert float(g.P_min) == 0.0 and g.status == 0 and g.messages == {}


@pytest.mark.parametrize("model", ["dw", "md"])
def test_p_min_is_pull_off_and_law_agrees(model):
    mu = np.array([0.3, 1.0, 5.0])
    g = wa.gap_critical(model, 0.3, mu)
    c = wa.critical_forces(model, 0.3, mu)
    np.testing.assert_allclose(g.P_min, c.P_pf, rtol=1e-12)
    for k, m in enumerate(mu):
        law = wa.gap_law(model, 0.3, m, [g.g_P_min[k], g.g_interaction_lost[k] + 0.5])
        assert law.P_retract[0] == pytest.approx(g.P_min[k], rel=1e-9)
        assert law.P_retract[1] == 0.0 and law.P_approach[1] == 0.0
    assert np.all(g.g_contact <= g.g_touch * (1 + 1e-14))


def test_jkr_p_min_is_minus_infinity():
    g = wa.gap_critical("jkr", 0.3, 1.0)
    assert math.isinf(g.P_min) and g.P_min < 0 and float(g.g_P_min) == 0.0


def test_broadcast_shape():
    g = wa.gap_critical("dw", [0.3, 1.0], [[1.0], [5.0]])
    assert g.P_min.shape == (2, 2) and np.all(g.status == 0)


@pytest.mark.parametrize("alpha, mu, needle", [
    (0.3, -1.0, "mu"), (float("nan"), 1.0, "alpha"), (0.0, 1.0, "alpha"),
    (0.3, float("inf"), "mu"), (0.3, [], "empty")])
def test_bad_input_raises(alpha, mu, needle):
    with pytest.raises(wa.InvalidArgumentError, match=needle):
        wa.gap_critical("dw", alpha, mu)


def test_bad_points_are_nan_with_errors_nan():
    g = wa.gap_critical("dw", 0.3, [1.0, -1.0, 2.0], errors="nan")
    assert list(g.status) == [0, 1, 0]
    assert np.isnan(g.P_min[1]) and np.isfinite(g.P_min[[0, 2]]).all()
    assert "mu" in g.messages[1]
    with pytest.raises(wa.InvalidArgumentError):
        wa.gap_critical("dw", 0.3, 1.0, errors="ignore")
