"""gap_law: P* on approach and retraction against the mean gap, and W* (issue 11)."""
import math

import numpy as np
import pytest

import wavyadhesion as wa


def test_westergaard_has_no_hysteresis_and_its_approach_curve():
    g = np.linspace(0.05, 0.95, 19)
    law = wa.gap_law("westergaard", 0.3, 1.0, g)
    assert law.W_star == 0.0 and law.W_fraction == 0.0
    assert np.array_equal(law.P_approach, law.P_retract)
    p = law.P_approach
    assert np.allclose(1 - p + p * np.log(p), g, rtol=0, atol=1e-13)
    assert np.allclose(law.dPdg_approach * np.log(p), 1.0, rtol=0, atol=1e-7)


def test_md_loop_and_energy():
    g = np.linspace(0.0, 1.5, 3001)
    law = wa.gap_law("md", 0.3, 1.0, g)
    assert law.W_star == pytest.approx(7.0144396136e-3, rel=1e-9)
    assert law.W_fraction == pytest.approx(law.W_star / (math.pi * 0.3**2 / 2), rel=1e-14)
    assert law.dPdg_approach[0] == -math.inf                 # full contact
    assert law.P_approach[-1] == 0.0 and law.P_retract[-1] == 0.0
    assert np.all(law.P_approach - law.P_retract >= -1e-12)  # retraction more tensile
    # the loop area on the grid (trapezoid across the jumps) is W* to the grid error
    d = law.P_approach - law.P_retract
    area = (g[1] - g[0]) * (d.sum() - 0.5 * (d[0] + d[-1]))
    assert area == pytest.approx(law.W_star, rel=2e-2)


def test_shape_follows_gbar():
    law = wa.gap_law("dw", 0.3, 1.0, 0.5)
    assert law.P_approach.shape == () and law.dPdg_retract.shape == ()
    law = wa.gap_law("dw", 0.3, 1.0, [[0.1, 0.2], [0.3, 0.4]])
    assert law.P_retract.shape == (2, 2)


@pytest.mark.parametrize("gbar", [[-0.1], [math.nan], [], [math.inf]])
def test_bad_gbar(gbar):
    with pytest.raises(wa.InvalidArgumentError, match="gbar"):
        wa.gap_law("dw", 0.3, 1.0, gbar)


def test_bad_model_and_alpha():
    with pytest.raises(wa.InvalidArgumentError, match="model"):
        wa.gap_law("xyz", 0.3, 1.0, [0.5])
    with pytest.raises(wa.InvalidArgumentError, match="alpha"):
        wa.gap_law("dw", -1.0, 1.0, [0.5])
