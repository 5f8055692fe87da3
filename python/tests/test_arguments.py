"""Counts and ranges of the sweeps are checked before anything is allocated, against the
library's own bounds, with errors that name the argument and its valid range (issue 3),
and the messages of issue 8 (gap_law's bad gbar, adhesion_map's alpha_range='abc')."""

import numpy as np
import pytest

import wavyadhesion as wa
from wavyadhesion import _args, _errors, _wa_f2py as _f

nan, inf = float("nan"), float("inf")
SMALL_ALPHA = (0.1, 1.0, 3)
SMALL_MU = (0.1, 10.0, 4)


def test_limits_are_the_librarys():
    # the bounds the Python layer checks are read from Fortran (fa_limits), and the
    # Fortran map refuses the first count beyond them (a small call: 2 alpha)
    assert (_args.MAP_N_MU_MAX, _args.MAP_N_ALPHA_MAX, _args.MAP_CELLS_MAX) == (
        100000, 100000, 10**7)
    alpha = np.array([0.1, 0.2])
    for n_mu in (_args.MAP_N_MU_MAX + 1, 1):
        out = _f.fa_adhesion_map(n_mu, 8, 2, alpha, 0.1, 10.0, 1, 1)
        assert out[12] == 1 and "n_mu must be in [2, 100000]" in _errors.message_text(out[13])


@pytest.mark.parametrize("n, needle", [
    (10**8, "mu_range n = 100000000 is outside [2, 100000]"),     # 5.5 GB before the fix
    (10**9, "mu_range n = 1000000000 is outside [2, 100000]"),    # did not return in 60 s
    (1, "mu_range n = 1 is outside [2, 100000]"),                 # was silently 2
    (0, "mu_range n = 0 is outside"),
    (-5, "mu_range n = -5 is outside"),
    (2.5, "mu_range n = 2.5: must be an integer in [2, 100000]"),
    (nan, "mu_range n = nan: must be an integer"),
    (inf, "mu_range n = inf: must be an integer"),
    (1e300, "mu_range n = 1e+300 is outside"),
    (True, "mu_range n = True: must be an integer"),
    ("60", "mu_range n = '60': must be an integer"),
    (None, "mu_range n = None: must be an integer"),
])
def test_map_mu_count_refused_before_allocation(n, needle):
    with pytest.raises(ValueError) as err:
        wa.adhesion_map("md", SMALL_ALPHA, (1e-3, 1e3, n))
    assert needle in str(err.value)
    assert isinstance(err.value, wa.InvalidArgumentError)


@pytest.mark.parametrize("alpha_range, needle", [
    ((0.01, 10.0, 10**9), "alpha_range n = 1000000000 is outside [2, 100000]"),   # was 8 GB
    ((0.01, 10.0, 1), "alpha_range n = 1 is outside [2, 100000]"),
    ((0.01, 10.0, 7.5), "alpha_range n = 7.5: must be an integer"),
    ((0.0, 10.0, 5), "alpha_range lo = 0.0 is outside its valid range [1e-12, 1e+12]"),
    ((0.01, 1e300, 5), "alpha_range hi = 1e+300 is outside"),
    ((0.01, nan, 5), "alpha_range hi = nan is outside"),
    ((1.0, 0.5, 5), "need lo < hi"),
    ("abc", "alpha_range = 'abc': expected (lo, hi, n)"),        # issue 8: bare float error
    (b"abc", "alpha_range = b'abc': expected (lo, hi, n)"),
    (None, "alpha_range = None: expected"),
    ([], "alpha_range holds 0 values: expected 1 to 100000"),
    (np.ones((2, 2)), "alpha_range: expected (lo, hi, n)"),
    ([0.1, nan], "alpha_range[1] = nan is outside its valid range"),
    ([0.1, -1.0], "alpha_range[1] = -1.0 is outside"),
    ([1.0, 0.5], "alpha_range[1] = 0.5 is not greater than alpha_range[0] = 1.0"),
    ([0.1, "a"], "alpha_range"),
    (np.ones(100001), "alpha_range holds 100001 values: expected 1 to 100000"),
])
def test_map_alpha_range_refused(alpha_range, needle):
    with pytest.raises(ValueError) as err:
        wa.adhesion_map("dw", alpha_range, SMALL_MU)
    assert needle in str(err.value)


@pytest.mark.parametrize("mu_range, needle", [
    ("abc", "mu_range = 'abc': expected (lo, hi, n)"),
    ((0.0, 10.0, 5), "mu_range lo = 0.0 is outside its valid range [1e-100, 1e+100]"),
    ((1.0, 1e101, 5), "mu_range hi = 1e+101 is outside"),
    ((10.0, 1.0, 5), "mu_range = (10.0, 1.0, 5): need lo < hi"),
    ((0.1, 1.0), "mu_range = (0.1, 1.0): expected"),
    (("a", 1.0, 5), "mu_range lo"),
])
def test_map_mu_range_refused(mu_range, needle):
    with pytest.raises(ValueError) as err:
        wa.adhesion_map("dw", SMALL_ALPHA, mu_range)
    assert needle in str(err.value)


def test_map_grid_cells_bounded():
    # 101 x 100000 cells: refused before the 1e7-cell grid is allocated
    with pytest.raises(wa.InvalidArgumentError, match="at most 10000000 cells"):
        wa.adhesion_map("dw", (0.01, 10.0, 100000), (1e-3, 1e3, 101))


@pytest.mark.parametrize("kwargs, needle", [
    (dict(scan_every=0), "scan_every = 0 is outside [1, 2147483647]"),
    (dict(scan_every=10**10), "scan_every = 10000000000 is outside"),
    (dict(scan_every=2.5), "scan_every = 2.5: must be an integer"),
    (dict(scan_every="x"), "scan_every = 'x'"),
    (dict(alpha_tol=nan), "alpha_tol = nan is outside its valid range [1e-15, 0.1]"),
    (dict(alpha_tol=1.0), "alpha_tol = 1.0 is outside"),
    (dict(alpha_tol="x"), "alpha_tol"),
    (dict(forces="no"), "forces = 'no': must be True or False"),
    (dict(control=["load"]), "control = ['load']: must be"),
    (dict(control="pressure"), "control = 'pressure'"),
])
def test_map_other_arguments_refused(kwargs, needle):
    with pytest.raises(ValueError) as err:
        wa.adhesion_map("dw", SMALL_ALPHA, SMALL_MU, **kwargs)
    assert needle in str(err.value)


@pytest.mark.parametrize("model", ["jkr", "westergaard"])
def test_map_model_checked_first(model):
    with pytest.raises(wa.InvalidArgumentError, match="'dw' or 'md'"):
        wa.adhesion_map(model, SMALL_ALPHA, (1e-3, 1e3, 10**9))


def test_map_integral_counts_accepted():
    # an integral float or a numpy integer is a count; a list is a (lo, hi, n) for mu
    a = wa.adhesion_map("dw", (0.2, 0.4, np.int64(3)), [0.5, 5.0, 4.0], scan_every=np.int32(1))
    b = wa.adhesion_map("dw", (0.2, 0.4, 3), (0.5, 5.0, 4), scan_every=1)
    assert a.mu.size == 4 and np.array_equal(a.fc_region, b.fc_region)


@pytest.mark.parametrize("gbar, needle", [
    ([0.1, 0.2, nan], "(gbar[2] = nan)"),
    ([[0.1, 0.2], [-1.0, 0.3]], "(gbar[1, 0] = -1.0)"),
    ([0.5, inf], "(gbar[1] = inf)"),
    (-0.5, "(gbar = -0.5)"),
])
def test_gap_law_names_the_bad_gbar(gbar, needle):
    # issue 8: the library's message with the index and the value
    with pytest.raises(wa.InvalidArgumentError) as err:
        wa.gap_law("dw", 0.3, 1.0, gbar)
    assert "gbar: must be finite and >= 0" in str(err.value) and needle in str(err.value)


def test_gap_law_bad_alpha_still_named_first():
    with pytest.raises(wa.InvalidArgumentError, match="alpha"):
        wa.gap_law("dw", nan, 1.0, [0.1, nan])


def test_gap_law_far_gap_is_zero_load():
    # 1e300 is a valid (huge) mean gap: no interaction, P* = 0, W* finite
    law = wa.gap_law("dw", 0.3, 1.0, [1e300])
    assert law.P_approach[0] == 0.0 and law.P_retract[0] == 0.0 and np.isfinite(law.W_star)


@pytest.mark.parametrize("func", [wa.critical_forces, wa.gap_critical, wa.energy_lost])
@pytest.mark.parametrize("alpha, mu, needle", [
    (0.3, [1.0, nan], "mu"), (0.3, 1e300, "mu"), (-inf, 1.0, "alpha"), (1e300, 1.0, "alpha"),
    (0.3, "x", "mu"), (0.3, [1.0, None], "mu"), (0.3, 1 + 1j, "mu"),
])
def test_sweeps_refuse_bad_points_naming_them(func, alpha, mu, needle):
    with pytest.raises(ValueError, match=needle):
        func("dw", alpha, mu)


@pytest.mark.parametrize("chunk_size", [0, -1, True, 2.0, "4", nan])
def test_chunk_size_refused(chunk_size):
    for func in (wa.critical_forces, wa.energy_lost):
        with pytest.raises(wa.InvalidArgumentError, match="chunk_size"):
            func("dw", 0.3, [1.0, 2.0], chunk_size=chunk_size)
