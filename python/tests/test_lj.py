"""model="lj" (the smooth Lennard-Jones model) in trace_branch, load_path, gap_path and
critical_forces: the values of the Fortran bem suite, the error estimates, n= and
profile=, and the errors. Small grids (n = 256) except where the automatic grid is the
point; each cycle at the automatic grid (N = 512 at alpha 0.3, mu 3) takes about a second.
"""
import math
import os

import numpy as np
import pytest

import wavyadhesion as wa

# The Fortran bem suite's values at alpha = 0.3, mu = 3, automatic grid
P_FC_REF = 0.99600001838
P_PF_REF = -0.40595099926


@pytest.fixture(scope="module")
def path_auto():
    return wa.load_path("lj", 0.3, 3.0)


def test_load_path_matches_the_fortran_suite(path_auto):
    p = path_auto
    assert isinstance(p, wa.LJLoadPath)
    assert p.N == 512
    # 1e-11: the rounding of the quoted reference values
    assert abs(p.P_fc - P_FC_REF) <= p.P_fc_err + 1e-11
    assert abs(p.P_pf - P_PF_REF) <= p.P_pf_err + 1e-11
    assert 0 < p.P_fc_err < 1e-8 and 0 < p.P_pf_err < 1e-8
    assert p.event[-1] == 7 and p.P_star[-1] == p.P_pf
    assert p.pf_by_jump
    assert "P_fc_err" in repr(p)


def test_critical_forces_unpacks_with_error_estimates():
    c = wa.critical_forces("lj", 0.3, [3.0, 2.5], n=256)
    assert isinstance(c, wa.LJCriticalForces)
    p_fc, p_pf = c
    assert p_fc.shape == (2,) and np.all(c.N == 256) and np.all(c.ok)
    # n = 256 is resolved at these mu: within the estimate of the reference at N = 512
    assert abs(p_fc[0] - P_FC_REF) <= c.P_fc_err[0] + 1e-10
    assert abs(p_pf[0] - P_PF_REF) <= c.P_pf_err[0] + 1e-10
    assert np.all(c.P_fc_err > 0) and np.all(c.W_star_err > 0)


def test_critical_forces_errors_nan_names_the_failed_point():
    c = wa.critical_forces("lj", 0.3, [3.0, 0.0], n=256, errors="nan")
    assert math.isnan(c.P_fc[1]) and c.status[1] == 1
    assert "mu must be > 0" in c.messages[(1,)]
    with pytest.raises(wa.InvalidArgumentError, match="mu must be > 0"):
        wa.critical_forces("lj", 0.3, 0.0, n=256)


def test_gap_path_w_star_and_jumps_at_constant_gap():
    g = wa.gap_path("lj", 0.3, 3.0, n=256)   # W* needs N/2 = 128 resolved
    assert isinstance(g, wa.LJGapPath)
    assert g.W_fraction == pytest.approx(g.W_star / (math.pi * 0.3**2 / 2), rel=1e-12)
    assert 0 < g.W_star_err < 0.01 * g.W_star
    # W* at the automatic grid (N = 512, the CLI's path --model lj --control gap)
    assert abs(g.W_star - 9.1305609826e-3) <= g.W_star_err + 1e-12
    starts = np.flatnonzero(g.event == 3)
    assert starts.size >= 2
    np.testing.assert_allclose(g.gbar[starts + 1], g.gbar[starts], rtol=1e-9)
    # the load and gap paths of one cycle share the trace: full contact at P_fc
    p = wa.load_path("lj", 0.3, 3.0, n=256)
    assert g.P_star[g.event == 5][0] == pytest.approx(p.P_fc, abs=1e-12)


def test_branch_events_and_stability():
    b = wa.trace_branch("lj", 0.3, 1.0, n=256)
    assert isinstance(b, wa.LJBranch) and b.N == 256
    assert b.event[0] == 8 and b.event[-1] == 8 and b.a_star[-1] == 0.5
    assert np.all(b.a_star <= b.b_star) and np.all(b.h_min <= b.gbar)
    # far apart: stable under gap control, not under load control (the attraction decays)
    assert b.stable_gap[0] and not b.stable[0]
    # the paths on this curve, with the estimates of the cycle at N/2 (as load_path's)
    p = wa.load_path("lj", 0.3, 1.0, n=256)
    assert (b.P_fc, b.P_pf, b.P_fc_err, b.P_pf_err) == (p.P_fc, p.P_pf, p.P_fc_err,
                                                        p.P_pf_err)
    assert b.W_star == wa.gap_path("lj", 0.3, 1.0, n=256).W_star


def test_profile_samples_of_the_sinusoid_and_a_shifted_wave():
    """The samples of 1 - cos(2 pi x) give the default; the same wave shifted by a third
    of a grid step (an uneven profile: solved on the whole period, not the half) gives the
    same critical loads, to the error estimate. (N = 256: at N = 128 the interaction zone
    is unresolved, and the spurious folds of the uneven grid exceed the path's jump cap,
    which the library reports instead of returning a cut path.)"""
    base = wa.critical_forces("lj", 0.3, 3.0, n=256)
    x = np.arange(64) / 64
    same = wa.critical_forces("lj", 0.3, 3.0, n=256, profile=1 - np.cos(2 * np.pi * x))
    assert same.P_fc == pytest.approx(base.P_fc, abs=1e-11)
    assert same.P_pf == pytest.approx(base.P_pf, abs=1e-11)
    with pytest.raises(wa.ConvergenceError, match="raise n"):
        wa.critical_forces("lj", 0.3, 3.0, n=128, profile=1 - np.cos(2 * np.pi * (x + 1 / 192)))
    shifted = wa.critical_forces("lj", 0.3, 3.0, n=256,
                                 profile=1 - np.cos(2 * np.pi * (x + 1 / 192)))
    assert abs(shifted.P_fc - base.P_fc) <= base.P_fc_err + shifted.P_fc_err + 1e-9
    assert abs(shifted.P_pf - base.P_pf) <= base.P_pf_err + shifted.P_pf_err + 1e-9


def test_to_si_carries_the_error_estimates():
    params = wa.Params.from_dimensional(Estar=1e9, period=1e-4, amplitude=1e-6,
                                        work_of_adhesion=0.05, peak_stress=3e6)
    p = wa.load_path("lj", params.alpha, params.mu, n=256)
    si = p.to_si(params)
    assert si.units["P_fc_err"] == "Pa"
    assert si.P_fc_err == pytest.approx(p.P_fc_err * params.scales.pressure)


@pytest.mark.parametrize("kwargs, exc, needle", [
    (dict(model="lj", n=7), wa.InvalidArgumentError, "even and >= 8"),
    (dict(model="lj", n=2.5), wa.InvalidArgumentError, "n = 2.5"),
    (dict(model="lj", profile=[0.0, 1.0]), wa.InvalidArgumentError, "at least 4"),
    (dict(model="lj", profile=np.zeros((2, 4))), wa.InvalidArgumentError, "1-D"),
    (dict(model="dw", n=64), wa.InvalidArgumentError, "only for model='lj'"),
    (dict(model="md", profile=[0, 1, 2, 1]), wa.InvalidArgumentError, "only for model='lj'"),
])
def test_bad_lj_arguments(kwargs, exc, needle):
    model = kwargs.pop("model")
    for func in (wa.trace_branch, wa.load_path, wa.gap_path, wa.critical_forces):
        with pytest.raises(exc, match=needle.replace("(", r"\(").replace(")", r"\)")):
            func(model, 0.3, 3.0, **kwargs)


def test_profile_of_a_traced_state():
    """The state with a* nearest 0.2 at n = 64: its mean traction is P* and its mean gap
    gbar* (independent of how the state was chosen); the CLI draws the same state."""
    p = wa.profile("lj", 0.3, 1.0, 0.2, n=64)
    assert p.N == 64 and p.x.size == 64 and p.x[0] == -0.5
    assert abs(p.a_star - 0.2) < 0.02
    assert np.mean(p.traction) == pytest.approx(p.P_star, abs=1e-12)
    assert np.mean(p.gap) == pytest.approx(p.gbar, abs=1e-12)
    b = wa.trace_branch("lj", 0.3, 1.0, n=64)
    k = np.flatnonzero(b.P_star == p.P_star)
    assert k.size == 1 and b.stable[k[0]] and b.b_star[k[0]] == p.b_star
    with pytest.raises(wa.InvalidArgumentError, match="c_star and x do not apply"):
        wa.profile("lj", 0.3, 1.0, 0.2, c_star=0.3, n=64)
    with pytest.raises(wa.InvalidArgumentError, match="only for model='lj'"):
        wa.profile("dw", 0.3, 1.0, 0.2, n=64)


def test_profile_with_a_sample_not_finite_is_refused():
    """A NaN or infinite sample is an invalid argument, named (it crashed the solver)."""
    for bad in (np.nan, np.inf):
        with pytest.raises(wa.InvalidArgumentError, match="profile"):
            wa.critical_forces("lj", 0.3, 3.0, n=16, profile=[0.0, bad, 2.0, 1.0])


def _same_sweep(a, b):
    for name in ("P_fc", "P_pf", "P_fc_err", "P_pf_err", "P_snap", "P_snap_err", "W_star",
                 "W_star_err", "P_fc_peak", "P_fc_peak_err", "N", "status", "alpha", "mu"):
        x, y = np.asarray(getattr(a, name)), np.asarray(getattr(b, name))
        assert x.shape == y.shape and x.dtype == y.dtype and x.tobytes() == y.tobytes(), name
    assert a.messages == b.messages


def test_sweep_on_executors_equals_serial():
    """One task per point on a thread pool and a process pool: the serial sweep bit for
    bit, a failed point (mu = 0: no LJ law) included, in the broadcast shape."""
    from concurrent.futures import ProcessPoolExecutor, ThreadPoolExecutor
    import multiprocessing
    alpha, mu = [[0.3], [0.5]], [1.0, 0.0, 2.0]
    serial = wa.critical_forces("lj", alpha, mu, n=64, errors="nan")
    assert serial.P_fc.shape == (2, 3) and list(np.unique(serial.status)) == [0, 1]
    with ThreadPoolExecutor(max_workers=2) as threads:
        _same_sweep(serial, wa.critical_forces("lj", alpha, mu, n=64, errors="nan",
                                               executor=threads))
    with ProcessPoolExecutor(max_workers=2,
                             mp_context=multiprocessing.get_context("spawn")) as processes:
        _same_sweep(serial, wa.critical_forces("lj", alpha, mu, n=64, errors="nan",
                                               executor=processes))
        with pytest.raises(wa.InvalidArgumentError, match="mu must be > 0"):
            wa.critical_forces("lj", alpha, mu, n=64, executor=processes)


def test_sweep_reports_progress_per_point():
    seen = []
    wa.critical_forces("lj", 0.3, [1.0, 1.5, 2.0], n=64,
                       progress=lambda done, total: seen.append((done, total)))
    assert seen == [(0, 3), (1, 3), (2, 3), (3, 3)]
    with pytest.raises(wa.InvalidTypeError, match="progress"):
        wa.critical_forces("lj", 0.3, 1.0, n=64, progress="yes")
    with pytest.raises(wa.InvalidArgumentError, match="chunk_size"):
        wa.critical_forces("lj", 0.3, 1.0, n=64, chunk_size=0)


def test_one_point_is_the_facade_cycle():
    """critical_forces("lj", scalar, scalar, errors="nan") (model_error_map's cell): the
    values of one direct facade cycle, bit for bit, and its message on failure."""
    from wavyadhesion import _wa_f2py as _f
    r = wa.critical_forces("lj", 0.3, 1.0, n=64, errors="nan")
    out = _f.fa_lj_cycle(64, 0.3, 1.0, 64, 0, np.zeros(1), 1, 0)
    v, n_period, status = out[12], out[13], out[14]
    assert status == 0 and int(r.N) == n_period and int(r.status) == 0
    got = [r.P_fc, r.P_pf, r.P_snap, r.W_star, r.P_fc_err, r.P_pf_err, r.P_snap_err,
           r.W_star_err, r.P_fc_peak, r.P_fc_peak_err]
    assert np.array(got).tobytes() == v[[0, 1, 2, 3, 5, 6, 7, 8, 11, 12]].tobytes()
    bad = wa.critical_forces("lj", 0.3, 0.0, n=64, errors="nan")
    assert int(bad.status) == 1 and "mu must be > 0" in bad.messages[()]
    assert math.isnan(float(bad.P_fc)) and int(bad.N) == 0


@pytest.mark.skipif(os.name != "posix", reason="resource.RLIMIT_AS: POSIX")
def test_profile_with_a_huge_n_allocates_nothing():
    """n = 2^30 (even) is refused by the grid's cap before anything of its size is
    allocated: the output arrays were sized by n (24 GB) and the grid allocated its N
    points (4 GB: an abort under a memory limit). Run in a child under a 2 GB limit."""
    import subprocess
    import sys
    code = ("import resource, wavyadhesion as wa\n"
            "resource.setrlimit(resource.RLIMIT_AS, (2 << 30, 2 << 30))\n"
            "for n in (2**30, 2**31 - 2, 16386):\n"
            "    try:\n"
            "        wa.profile('lj', 0.3, 1.0, 0.2, n=n)\n"
            "    except wa.WavyAdhesionError as e:\n"
            "        assert '16384' in str(e), e\n"
            "    else:\n"
            "        raise SystemExit('accepted')\n"
            "print('refused')\n")
    res = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         timeout=120)
    assert res.returncode == 0 and res.stdout.strip() == "refused", res.stderr[-2000:]

def test_p_fc_peak_is_the_snap_where_dw_jumps(path_auto):
    """alpha 0.3, mu 3: DW reaches full contact by a jump; LJ's snap lands with every gap
    within the peak tension's 3^(1/6) eps, so P_fc_peak (b* = 1/2) is its snap load, by a
    jump, and within 0.2 % of DW's and MD's P_fc (the paper's Fig. 5 comparison), while
    LJ's P_fc (a* = 1/2) is 0.996."""
    p = path_auto
    assert wa.load_path("dw", 0.3, 3.0).fc_mechanism != "gradual"
    assert p.fc_peak_by_jump and p.P_fc_peak == p.P_snap and 0 < p.P_fc_peak_err < 1e-4
    for model in ("dw", "md"):
        assert p.P_fc_peak == pytest.approx(float(wa.critical_forces(model, 0.3, 3.0).P_fc),
                                            rel=2e-3)
    c = wa.critical_forces("lj", 0.3, 3.0)
    assert c.P_fc_peak == p.P_fc_peak and c.P_fc_peak_err == p.P_fc_peak_err


def test_p_fc_peak_without_a_jump_lies_on_the_traced_curve():
    """alpha 0.3, mu 1: the snap (0.3988) lands short of b* = 1/2, which loading then
    reaches gradually: P_fc_peak lies in the load-stable interval of the traced curve where
    the largest gap falls to 3^(1/6) eps (found here from the branch), near its linear
    interpolation."""
    p = wa.load_path("lj", 0.3, 1.0)
    assert not p.fc_peak_by_jump and p.P_snap < p.P_fc_peak < p.P_fc
    b = wa.trace_branch("lj", 0.3, 1.0, n=p.N)
    h_peak = 3 ** (1 / 6) * (4 * 0.3**4) ** (1 / 3) / 1.0
    i = next(k for k in range(len(b) - 1)
             if b.stable[k] and b.stable[k + 1] and b.P_star[k] >= p.P_snap
             and b.h_max[k] > h_peak >= b.h_max[k + 1])
    lo, hi = sorted((b.P_star[i], b.P_star[i + 1]))
    assert lo <= p.P_fc_peak <= hi
    t = (b.h_max[i] - h_peak) / (b.h_max[i] - b.h_max[i + 1])
    assert p.P_fc_peak == pytest.approx(b.P_star[i] + t * (b.P_star[i + 1] - b.P_star[i]),
                                        abs=0.1 * (hi - lo) + 1e-12)


