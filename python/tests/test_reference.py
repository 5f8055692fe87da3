"""Agreement with the repository's mpmath reference tables test/data/*.txt (skipped when
a table is absent). Tolerances of the accuracy target (doc/accuracy-performance.md): relative 1e-12 in c* and P*, absolute
1e-12 where |P*| < 1e-3."""

from itertools import groupby

import numpy as np
import pytest

import wavyadhesion as wa

RTOL = 1e-12
P_ABS_BELOW = 1e-3


def load(repo, name):
    path = repo / "test" / "data" / f"{name}.txt"
    if not path.is_file():
        pytest.skip(f"{path} not present")
    table = np.loadtxt(path, comments="#", ndmin=2)
    if table.size == 0:
        pytest.skip(f"{path} is empty")
    return table


def scaled_error(got, want):
    got, want = np.asarray(got, float), np.asarray(want, float)
    scale = np.where(np.abs(want) >= P_ABS_BELOW, np.abs(want), 1.0)
    return np.max(np.abs(got - want) / scale)


def test_westergaard_table(repo):
    t = load(repo, "westergaard")
    assert scaled_error(wa.westergaard_load(t[:, 0]), t[:, 1]) <= 1e-14
    eq = wa.equilibrium("westergaard", 1.0, 1.0, t[:, 0])
    assert scaled_error(eq.P_star, t[:, 1]) <= 1e-14


def test_jkr_table(repo):
    t = load(repo, "jkr")
    assert scaled_error(wa.jkr_load(t[:, 0], t[:, 1]), t[:, 2]) <= 1e-14


@pytest.mark.parametrize("model", ["dw", "md"])
def test_cohesive_table(repo, model):
    """Principal states vectorised (first row of each point), then every root."""
    t = load(repo, model)
    keys = [tuple(row[:3]) for row in t]
    groups = [(k, [i for i, _ in g]) for k, g in groupby(enumerate(keys), key=lambda x: x[1])]
    first = np.array([idx[0] for _, idx in groups])
    eq = wa.equilibrium(model, t[first, 0], t[first, 1], t[first, 2], errors="nan")
    ok = eq.zone_case != 0          # points where the library reports a status
    assert ok.mean() > 0.99, f"{(~ok).sum()} points failed"
    assert np.all(eq.zone_case[ok] == t[first[ok], 6])
    rows = first[ok]
    err_c = np.abs(eq.c_star[ok] - t[rows, 3]) / t[rows, 3]
    worst = rows[np.argmax(err_c)]
    assert err_c.max() <= RTOL, f"c* rel. error {err_c.max():.2e} at {t[worst, :3]}"
    assert scaled_error(eq.P_star[ok], t[rows, 5]) <= RTOL
    mismatches = 0
    for (alpha, mu, a), idx in groups:
        try:
            states = wa.roots(model, alpha, mu, a)
        except wa.ConvergenceError:
            continue
        if len(states) != len(idx) or any(
                s.zone_case != t[i, 6] for s, i in zip(states, idx)):
            mismatches += 1
            continue
        for s, i in zip(states, idx):
            assert abs(s.c_star - t[i, 3]) <= RTOL * t[i, 3]
            assert scaled_error(s.P_star, t[i, 5]) <= RTOL
    assert mismatches == 0
