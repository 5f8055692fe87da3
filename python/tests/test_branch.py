"""trace_branch: shapes, events, values against the command line and the point solver,
exceptions."""

import numpy as np
import pytest

import wavyadhesion as wa

ARRAYS = ("a_star", "c_star", "P_star", "b_star", "zone_case", "stable", "event", "extremum")


@pytest.mark.parametrize("model", wa.MODELS)
def test_shapes_and_types(model):
    b = wa.trace_branch(model, 0.3, 1.0)
    n = len(b)
    assert 100 < n < 5000
    for name in ARRAYS:
        arr = getattr(b, name)
        assert isinstance(arr, np.ndarray) and arr.shape == (n,), name
    assert b.stable.dtype == bool
    assert b.zone_case.dtype.kind == b.event.dtype.kind == "i"
    assert b.model == model and b.alpha == 0.3 and b.mu == 1.0
    assert np.all(np.isfinite(b.P_star))
    contact = b.zone_case > 0                  # MD begins with its no-contact states (a* = 0)
    assert np.all(b.a_star[contact] > 0) and np.all(b.a_star <= 0.5)
    assert np.all(b.a_star[~contact] == 0)
    assert np.all((b.c_star >= b.a_star) & (b.c_star <= 0.5))
    assert set(np.unique(b.zone_case)) <= ({0, 1, 2, 3} if model == "md" else {1, 2, 3})
    assert set(np.unique(b.event)) <= {0, 1, 2, 8, 9}
    assert b.event[0] == b.event[-1] == 8
    np.testing.assert_array_equal(b.b_star, b.a_star + 0.4 * (b.c_star - b.a_star))
    assert not np.any(b.stable[b.event == 1]), "folds are not stable points"


def test_dw_paper_case_events():
    """alpha = 0.3, mu = 5 (paper Fig. 6e): exactly two folds and one switch, where
    `wavyadhesion branch --model dw --alpha 0.3 --mu 5` puts them."""
    b = wa.trace_branch("dw", 0.3, 5.0)
    assert [e.kind for e in b.events] == ["branch_end", "fold", "fold", "switch",
                                          "branch_end"]
    assert np.count_nonzero(b.event == 1) == 2
    f1, f2 = b.folds
    # folds are located to 1e-10 in a* (the accuracy target, doc/accuracy-performance.md); P* is flat there
    np.testing.assert_allclose([f1.a_star, f2.a_star],
                               [5.3308276396925647e-02, 3.7313491247966202e-01], rtol=1e-9)
    np.testing.assert_allclose([f1.P_star, f2.P_star],
                               [-9.5883008684625154e-02, 3.8750724174362783e-01], rtol=1e-12)
    (s,) = b.switches
    assert s.zone_case == 2 and s.c_star == 0.5
    np.testing.assert_allclose([s.a_star, s.P_star],
                               [4.6606802365917238e-01, -1.1995262953240982e-01], rtol=1e-12)
    assert b.extremum[f1.index] == -1 and b.extremum[f2.index] == 1
    for e in b.events:
        assert (b.a_star[e.index], b.P_star[e.index]) == (e.a_star, e.P_star)


@pytest.mark.parametrize("model, mu", [("dw", 1.0), ("dw", 3.0), ("md", 1.0), ("md", 5.0)])
def test_points_are_equilibria(model, mu):
    """Every case-1 or case-2 point is one of the roots at its a* (to 1e-9)."""
    b = wa.trace_branch(model, 0.3, mu)
    for i in range(1, len(b) - 1, 7):
        if b.event[i] == 2 or b.extremum[i] == 2:  # a switch, or a* turning back: roots merge
            continue
        if b.zone_case[i] == 0:                    # no contact: not a root at a* (a* = 0)
            continue
        loads = [s.P_star for s in wa.roots(model, 0.3, mu, b.a_star[i])]
        assert np.min(np.abs(np.subtract(loads, b.P_star[i]))) <= 1e-9 * max(
            1.0, abs(b.P_star[i])), (i, b.a_star[i])


def test_closed_forms():
    w = wa.trace_branch("westergaard", 0.3, 1.0)
    np.testing.assert_allclose(w.P_star, wa.westergaard_load(w.a_star), rtol=1e-14)
    assert w.zone_case[-1] == 3 and not w.folds
    j = wa.trace_branch("jkr", 0.6, 1.0)
    np.testing.assert_allclose(j.P_star, wa.jkr_load(0.6, j.a_star), rtol=1e-14)
    assert max(e.P_star for e in j.folds) < 0     # alpha > 0.57: the maximum is tensile
    j = wa.trace_branch("jkr", 0.3, 1.0)
    assert len(j.folds) == 2
    assert np.all(j.c_star == j.a_star)


def test_independent_of_mu_for_closed_forms():
    a = wa.trace_branch("jkr", 0.3, 0.0)
    b = wa.trace_branch("jkr", 0.3, 50.0)
    np.testing.assert_array_equal(a.P_star, b.P_star)


@pytest.mark.parametrize("model", wa.MODELS)
@pytest.mark.parametrize("alpha, mu, name", [
    (0.0, 1.0, "alpha"), (-1.0, 1.0, "alpha"), (np.nan, 1.0, "alpha"),
    (np.inf, 1.0, "alpha"), (0.3, -0.5, "mu"), (0.3, np.nan, "mu"), (0.3, np.inf, "mu"),
])
def test_invalid_arguments(model, alpha, mu, name):
    with pytest.raises(wa.InvalidArgumentError, match=name) as info:
        wa.trace_branch(model, alpha, mu)
    assert info.value.status == 1


@pytest.mark.parametrize("model", ["xyz", None, 2])
def test_unknown_model(model):
    with pytest.raises(ValueError, match="model"):
        wa.trace_branch(model, 0.3, 1.0)


def test_scalars_only():
    with pytest.raises(wa.InvalidArgumentError, match="scalar"):
        wa.trace_branch("dw", [0.3, 0.6], 1.0)


def test_capacity_retry(monkeypatch):
    """A first call with too small a capacity is repeated with the exact size."""
    from wavyadhesion import _branch
    full = wa.trace_branch("dw", 0.3, 5.0)
    monkeypatch.setattr(_branch, "_BRANCH_CAPACITY", 10)
    short = wa.trace_branch("dw", 0.3, 5.0)
    assert len(short) == len(full)
    for name in ARRAYS:
        np.testing.assert_array_equal(getattr(short, name), getattr(full, name))
