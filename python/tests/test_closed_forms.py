"""Westergaard and JKR closed forms, through the kernels and through equilibrium()."""

import numpy as np
import pytest

import wavyadhesion as wa


def test_westergaard_values():
    a = np.linspace(0.0, 0.5, 101)
    np.testing.assert_allclose(wa.westergaard_load(a), np.sin(np.pi * a) ** 2,
                               rtol=1e-14, atol=1e-15)


def test_jkr_values():
    a = np.linspace(0.0, 0.49, 50)
    for alpha in (0.0, 0.1, 0.57, 2.0):
        want = np.sin(np.pi * a) ** 2 - alpha * np.sqrt(np.tan(np.pi * a))
        np.testing.assert_allclose(wa.jkr_load(alpha, a), want, rtol=1e-13, atol=1e-14)


def test_jkr_full_contact_is_minus_infinity():
    assert wa.jkr_load(0.3, 0.5) == -np.inf


def test_scalar_in_scalar_out():
    p = wa.westergaard_load(0.25)
    assert np.ndim(p) == 0 and isinstance(p, np.floating)
    assert abs(p - 0.5) < 1e-15


@pytest.mark.parametrize("model", ["westergaard", "jkr"])
def test_equilibrium_closed_forms(model):
    a = np.array([0.0, 0.1, 0.25, 0.4, 0.5])
    eq = wa.equilibrium(model, 0.3, 1.0, a)
    want = wa.westergaard_load(a) if model == "westergaard" else wa.jkr_load(0.3, a)
    np.testing.assert_array_equal(eq.c_star, a)
    np.testing.assert_array_equal(eq.P_star, want)
    np.testing.assert_array_equal(eq.zone_case, [1, 1, 1, 1, 3])
    states = wa.roots(model, 0.3, 1.0, 0.1)
    assert len(states) == 1 and states[0].c_star == 0.1 and states[0].gap_width == 0.0


def test_empty_inputs():
    assert wa.westergaard_load([]).shape == (0,)
    assert wa.jkr_load(0.3, np.empty((2, 0))).shape == (2, 0)
