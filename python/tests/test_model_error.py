"""The model-error map (wavyadhesion.model_error_map): shapes, statuses, the grid cap marked
"unresolved", and the relative error against the individual calls."""

import numpy as np
import pytest

import wavyadhesion as wa


@pytest.fixture(scope="module")
def small_map():
    # alpha 0.3: mu = 3 is resolved at the automatic grid (N = 512, under a second);
    # mu = 1000 needs a zone finer than the cap (refused at once)
    return wa.model_error_map([0.3], [3.0, 1000.0])


def test_shapes_and_statuses(small_map):
    m = small_map
    assert m.shape == (1, 2) and m.models == ("dw", "md")
    for model in m.models:
        assert list(m.status[model][0]) == ["ok", "unresolved"]
        for q in wa.QUANTITIES:
            for arr in (m.rel_error[model, q], m.resolved[model, q], m.values[model, q]):
                assert arr.shape == (1, 2)
            assert np.isfinite(m.rel_error[model, q][0, 0])
            assert np.isnan(m.rel_error[model, q][0, 1])      # never extrapolated
            assert not m.resolved[model, q][0, 1]
    for q in wa.QUANTITIES:
        assert m.lj_err[q].shape == (1, 2) and np.isnan(m.lj[q][0, 1])
    assert list(m.lj_status[0]) == ["ok", "unresolved"]
    assert "cap" in m.messages["lj", 0, 1]
    assert "shape=(1, 2)" in repr(m) and len(repr(m)) < 200


def test_relative_error_equals_the_individual_calls(small_map):
    m = small_map
    lj = wa.critical_forces("lj", 0.3, 3.0)
    # P_fc is compared with LJ's P_fc_peak (b* = 1/2), LJ's own P_fc kept aside
    lj_values = {"P_fc": float(lj.P_fc_peak), "P_pf": float(lj.P_pf),
                 "W_star": float(lj.W_star)}
    lj_errs = {"P_fc": float(lj.P_fc_peak_err), "P_pf": float(lj.P_pf_err),
               "W_star": float(lj.W_star_err)}
    assert m.lj["P_fc_contact"][0, 0] == float(lj.P_fc)
    assert m.lj["P_snap"][0, 0] == float(lj.P_snap) and m.lj_seconds[0, 0] > 0
    for model in ("dw", "md"):
        p_fc, p_pf = wa.critical_forces(model, 0.3, 3.0)
        w = wa.gap_path(model, 0.3, 3.0).W_star
        for q, v in (("P_fc", p_fc), ("P_pf", p_pf), ("W_star", w)):
            want = abs(float(v) - lj_values[q]) / abs(lj_values[q])
            assert m.rel_error[model, q][0, 0] == pytest.approx(want, rel=1e-12)
            assert m.lj_err[q][0, 0] == lj_errs[q]
            assert m.resolved[model, q][0, 0] == (
                lj_errs[q] <= 0.1 * abs(float(v) - lj_values[q])
                or lj_errs[q] <= 1e-3 * abs(lj_values[q]))


def test_zero_lj_value_gives_0_or_inf():
    """alpha 0.3, mu 1: LJ reaches full contact and lets go without a jump (W* = 0 to
    rounding), DW and MD jump (W* > 0): a difference in kind, inf, not a rounding ratio."""
    m = wa.model_error_map([0.3], [1.0], models=("dw",))
    lj = wa.critical_forces("lj", 0.3, 1.0)
    assert abs(float(lj.W_star)) <= max(float(lj.W_star_err), 1e-12)
    assert wa.gap_path("dw", 0.3, 1.0).W_star > 1e-6
    assert m.rel_error["dw", "W_star"][0, 0] == np.inf and m.resolved["dw", "W_star"][0, 0]
    assert np.isfinite(m.rel_error["dw", "P_pf"][0, 0])


def test_tiny_alpha_is_unresolved_not_an_exception():
    m = wa.model_error_map([1e-6], [3.0], models=("dw",))
    assert m.status["dw"][0, 0] == "unresolved"
    assert np.isnan(m.rel_error["dw", "P_pf"][0, 0])


def test_explicit_grid_and_dataframe():
    pd = pytest.importorskip("pandas")
    m = wa.model_error_map([0.3], [3.0], models=("md",), n=256)
    assert m.lj_N[0, 0] == 256 and m.status["md"][0, 0] == "ok"
    df = m.to_dataframe()
    assert isinstance(df, pd.DataFrame) and len(df) == 3
    assert set(df["quantity"]) == set(wa.QUANTITIES)


def test_executor_gives_the_serial_values(small_map):
    from concurrent.futures import ThreadPoolExecutor
    with ThreadPoolExecutor(2) as ex:
        m = wa.model_error_map([0.3], [3.0, 1000.0], executor=ex)
    for key, arr in small_map.rel_error.items():
        np.testing.assert_array_equal(m.rel_error[key], arr)


def test_bad_axes_are_refused():
    with pytest.raises(wa.InvalidArgumentError, match="alpha"):
        wa.model_error_map([[0.3]], [1.0])
    with pytest.raises(wa.InvalidArgumentError, match="mu"):
        wa.model_error_map([0.3], [0.0])
    with pytest.raises(wa.InvalidArgumentError):
        wa.model_error_map([0.3], [1.0], models=("xx",))


def test_n_max_caps_the_grid_and_names_the_n_needed():
    """alpha 0.3, mu 10 needs N = 8192: unresolved under n_max = 2048 (the message names
    the N needed and the cap; refused at once, nothing extrapolated), and n_max outside
    [128, 16384] is refused."""
    m = wa.model_error_map([0.3], [10.0], models=("dw",), n_max=2048)
    assert m.status["dw"][0, 0] == "unresolved" and m.lj_status[0, 0] == "unresolved"
    text = m.messages["lj", 0, 0]
    assert "needs N = 8192" in text and "cap of 2048" in text
    assert np.isnan(m.rel_error["dw", "P_fc"][0, 0]) and m.lj_N[0, 0] == 0
    for bad in (64, 32768, 1.5):
        with pytest.raises(wa.InvalidArgumentError, match="n_max"):
            wa.model_error_map([0.3], [10.0], n_max=bad)


def test_default_cap_is_16384():
    """mu 1000 needs far more than 16384 points: the message names both."""
    m = wa.model_error_map([0.3], [1000.0], models=("md",))
    assert "cap of 16384" in m.messages["lj", 0, 0]


def test_fc_mechanism_and_executor_order():
    """The cohesive models' fc_mechanism per cell; an executor (cells submitted costliest
    first, collected as they complete) gives the serial cells in place."""
    from concurrent.futures import ThreadPoolExecutor
    serial = wa.model_error_map([0.3], [1.0, 3.0], models=("dw",), n=128)
    assert list(serial.fc_mechanism["dw"][0]) == [
        wa.load_path("dw", 0.3, mu).fc_mechanism for mu in (1.0, 3.0)]
    with ThreadPoolExecutor(2) as ex:
        par = wa.model_error_map([0.3], [1.0, 3.0], models=("dw",), n=128, executor=ex)
    for key, arr in serial.rel_error.items():
        np.testing.assert_array_equal(par.rel_error[key], arr)
    np.testing.assert_array_equal(par.lj_N, serial.lj_N)


def test_only_the_grid_refusal_is_unresolved():
    """A cell is "unresolved" only where LJ refused the grid (beyond the cap); the same
    status from a trace that ran out of points (alpha 0.01, mu 2.5 at N = 4096: 20000
    points before full contact) is a failure (never drawn as beyond the cap)."""
    from wavyadhesion._errors import CAPACITY_TOO_SMALL, NOT_CONVERGED
    from wavyadhesion._model_error import _cell_status
    refusal = ("lj: the interaction zone (2.370E-06 of a period) needs N = 8388608 points "
               "per period, above the automatic grid's cap of 4096; pass n explicitly")
    assert _cell_status(CAPACITY_TOO_SMALL, refusal) == "unresolved"
    assert _cell_status(CAPACITY_TOO_SMALL, "lj: n gives more than 8193 unknowns") == "unresolved"
    trace = "lj_trace: more than max_points points before full contact"
    assert _cell_status(CAPACITY_TOO_SMALL, trace) == "failed"
    assert _cell_status(NOT_CONVERGED, refusal) == "failed"
    assert _cell_status(0, "") == "ok"
