"""wavyadhesion.adhesion_map (issue 13): boundaries agree with the CLI/Fortran, region
grids, forces and model-choice masks, executors give the serial result, errors."""

from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import wavyadhesion as wa


@pytest.fixture(scope="module")
def small_map():
    return wa.adhesion_map("dw", [0.3, 0.31], (1e-3, 1e3, 30), forces=True)


def test_boundaries_and_meanings(small_map):
    codes = {b.code for b in small_map.boundaries}
    assert {101, 212}.issubset(codes)
    b101 = [b for b in small_map.boundaries if b.code == 101][0]
    assert b101.meaning == "full contact: gradual -> jump case 1"
    assert np.all(np.diff(b101.alpha) > 0)
    # mechanism_change's value at alpha = 0.3 (CLI critical header), to 1e-8
    assert b101.mu[b101.alpha == 0.3][0] == pytest.approx(2.7732638945721502, rel=1e-8)
    assert wa.boundary_meaning(1113).endswith("(as alpha grows, at fixed mu)")
    assert wa.boundary_meaning(7) == "unknown"


def test_regions_and_forces(small_map):
    m = small_map
    assert m.fc_region.shape == m.pf_region.shape == m.P_fc.shape == (30, 2)
    ref = wa.critical_forces("dw", 0.3, m.mu)
    np.testing.assert_array_equal(m.P_fc[:, 0], ref.P_fc)
    np.testing.assert_array_equal(m.fc_region[:, 0], ref.fc_mechanism)
    # Westergaard within 1 % at the smallest mu, never at the largest
    assert m.westergaard[0].all() and not m.westergaard[-1].any()
    assert m.jkr_fc.dtype == bool


def test_executor_equals_serial(small_map):
    with ThreadPoolExecutor(2) as pool:
        par = wa.adhesion_map("dw", [0.3, 0.31], (1e-3, 1e3, 30), forces=True,
                              executor=pool)
    np.testing.assert_array_equal(par.P_pf, small_map.P_pf)
    np.testing.assert_array_equal(par.fc_region, small_map.fc_region)
    assert len(par.boundaries) == len(small_map.boundaries)
    for a, b in zip(par.boundaries, small_map.boundaries):
        assert a.code == b.code
        np.testing.assert_array_equal(a.mu, b.mu)


def test_errors():
    with pytest.raises(wa.InvalidArgumentError):
        wa.adhesion_map("jkr", [0.3])
    with pytest.raises(wa.InvalidArgumentError):
        wa.adhesion_map("dw", [0.3, 0.1])
    with pytest.raises(wa.InvalidArgumentError):
        wa.adhesion_map("dw", [0.3], (10.0, 1.0, 5))


def test_plotting(small_map):
    pytest.importorskip("matplotlib")
    import matplotlib
    matplotlib.use("Agg")
    from wavyadhesion import plotting
    fig = plotting.adhesion_map(small_map)
    ax = fig.axes[0]
    assert ax.get_xscale() == "log" and ax.get_yscale() == "log"


def test_special_points():
    """Where boundaries meet: DW full contact 101 meets 103 at alpha ~ 0.567, mu ~ 2.95
    (the local maximum of P* reaches 0); each point says what it is in words."""
    m = wa.adhesion_map("dw", (0.3, 1.0, 40), (0.1, 10, 30))
    meets = [p for p in m.special if p.kind == "meet" and set(p.codes) == {101, 103}]
    assert len(meets) == 1
    assert meets[0].alpha == pytest.approx(0.567, rel=1e-2)
    assert meets[0].mu == pytest.approx(2.95, rel=1e-2)
    assert meets[0].meaning == ("full contact: gradual -> jump case 1 meets full contact: "
                                "gradual -> snap at P=0")
    assert all(isinstance(p, wa.SpecialPoint) for p in m.special)


@pytest.fixture(scope="module")
def gap_map():
    return wa.adhesion_map("dw", [0.3, 0.31], (1e-2, 1e2, 20), control="both",
                           scan_every=1)


def test_gap_control(gap_map):
    """Gap control (codes 3xx, 4xx): DW has one boundary, retraction gradual -> jump-out
    (401) at mu 2.34035 for alpha 0.3 (gap_mechanism_change, to 1e-8), on top of
    the load-control ones; the approach always jumps into contact (region 1)."""
    m = gap_map
    codes = {b.code for b in m.boundaries}
    assert 401 in codes and {101, 212}.issubset(codes)
    b = [b for b in m.boundaries if b.code == 401][0]
    assert b.meaning == "gap retraction: gradual -> jump-out"
    assert b.mu[b.alpha == 0.3][0] == pytest.approx(2.3403548179, rel=1e-8)
    assert m.ga_region.shape == m.gr_region.shape == m.fc_region.shape == (20, 2)
    assert (m.ga_region == 1).all()
    i = np.searchsorted(m.mu, b.mu[0])
    assert (m.gr_region[:i, 0] == 0).all() and (m.gr_region[i:, 0] == 1).all()
    assert wa.boundary_meaning(323) == ("gap approach: gradual+inner jumps -> "
                                        "jump-in+inner jumps")
    # the load-control part equals the load-only map
    load = wa.adhesion_map("dw", [0.3, 0.31], (1e-2, 1e2, 20), scan_every=1)
    assert load.ga_region is None and load.control == "load"
    np.testing.assert_array_equal(load.fc_region, m.fc_region)
    for a in load.boundaries:
        same = [g for g in m.boundaries if g.code == a.code]
        assert same and np.array_equal(same[0].mu, a.mu)
    with pytest.raises(wa.InvalidArgumentError, match="control"):
        wa.adhesion_map("dw", [0.3], control="displacement")


def test_gap_plotting():
    pytest.importorskip("matplotlib")
    import matplotlib
    matplotlib.use("Agg")
    from wavyadhesion import plotting
    m = wa.adhesion_map("dw", [0.3, 0.31], (1e-2, 1e2, 12), control="gap", scan_every=1)
    fig = plotting.adhesion_map(m)
    ax = fig.axes[0]
    assert "gap control" in ax.get_title()
    assert any(line.get_color() == "tab:red" for line in ax.get_lines())
