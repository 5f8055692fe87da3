"""Long calls stop on Ctrl-C (issue 6): gap_critical runs in facade calls of at most 16 mu,
the adhesion map's one Fortran call in a helper thread; results are those of one
unchunked facade call. The interruption is checked in a child process sent SIGINT, with a
generous bound far below the duration of the whole call (no timing of the library)."""

import os
import signal
import subprocess
import sys
import time

import numpy as np
import pytest

import wavyadhesion as wa
from wavyadhesion import _gap, _wa_f2py as _f
from wavyadhesion._gapcritical import GAP_CRITICAL_FIELDS
from wavyadhesion._parallel import call_interruptibly

CHILD = """
import sys
import numpy as np, wavyadhesion as wa
print('start', flush=True)
try:
    {call}
except KeyboardInterrupt:
    print('interrupted', flush=True)
    sys.exit(130)
print('finished', flush=True)
"""


def test_gap_critical_equals_one_unchunked_call():
    mu = np.concatenate([[0.0], np.logspace(-2, 1.5, 45)])      # 46 mu: three chunks
    for model, alpha in (("dw", 0.3), ("md", 0.7)):
        g = wa.gap_critical(model, alpha, mu)
        vals, rows, ifail, status, _ = _f.fa_gap_critical_sweep(wa.MODELS[model], alpha, mu)
        assert status == 0 and ifail == 0 and (rows == 0).all()
        for k, name in enumerate(GAP_CRITICAL_FIELDS):
            assert np.array_equal(getattr(g, name), vals[k], equal_nan=True), name
        assert (g.status == 0).all() and g.messages == {}


def test_gap_critical_failed_row_keeps_its_own_message():
    g = wa.gap_critical("dw", 0.3, [1.0] * 20 + [-1.0], errors="nan")
    assert list(np.flatnonzero(g.status)) == [20] and "mu" in g.messages[20]
    assert np.isfinite(g.P_min[:20]).all() and np.isnan(g.P_min[20])


def test_adhesion_map_equals_the_direct_facade_call():
    alpha = np.geomspace(0.1, 3.0, 9)
    m = wa.adhesion_map("dw", alpha, (0.01, 100.0, 12), scan_every=4)
    out = _f.fa_adhesion_map(12, 64 * (alpha.size + 64), 2, alpha, 0.01, 100.0, 4, 1)
    codes, a_out, m_out, curve, _, n_out, mu_grid, fc, pf, *_ = out
    n = int(n_out)
    assert out[12] == 0 and n > 0
    assert np.array_equal(m.mu, mu_grid) and np.array_equal(m.fc_region, fc)
    assert np.array_equal(m.pf_region, pf)
    assert np.array_equal(np.concatenate([b.alpha for b in m.boundaries]), a_out[:n])
    assert np.array_equal(np.concatenate([b.mu for b in m.boundaries]), m_out[:n])
    assert [b.code for b in m.boundaries] == [int(codes[:n][curve[:n] == c][0])
                                              for c in range(1, int(curve[:n].max()) + 1)]


def test_call_in_helper_thread_returns_or_raises_in_the_caller():
    assert call_interruptibly(divmod, 7, 2) == (3, 1)
    with pytest.raises(ValueError, match="invalid literal"):
        call_interruptibly(int, "x")


@pytest.mark.skipif(os.name != "posix" or not hasattr(signal, "SIGINT"),
                    reason="SIGINT to a child process: POSIX")
@pytest.mark.parametrize("call, bound", [
    # whole calls of over a minute and ~40 s here (20000 MD mu: 16 s; the default MD map
    # with control 'both', 200 alpha: 19 s)
    ("wa.gap_critical('md', 0.3, np.logspace(-2, 1, 100000))", 10.0),
    ("wa.adhesion_map('md', (0.01, 10.0, 400), control='both')", 10.0),
    # LJ: one task per point, each in a helper thread (~1.3 s each at the automatic grid;
    # one point at n = 2048: ~6 s)
    ("wa.critical_forces('lj', 0.3, np.linspace(2.0, 3.0, 200))", 10.0),
    ("wa.critical_forces('lj', 0.3, 2.5, n=2048)", 3.0),
])
def test_long_call_stops_on_sigint(call, bound):
    child = subprocess.Popen([sys.executable, "-c", CHILD.format(call=call)],
                             stdout=subprocess.PIPE, text=True)
    try:
        assert child.stdout.readline().strip() == "start"
        time.sleep(1.0)                              # well inside the long call
        sent = time.monotonic()
        child.send_signal(signal.SIGINT)
        out, _ = child.communicate(timeout=120)
        waited = time.monotonic() - sent
    finally:
        if child.poll() is None:
            child.kill()
            child.wait()
    assert out.strip() == "interrupted" and child.returncode == 130
    assert waited < bound, f"{waited:.1f} s from SIGINT to exit"


def test_gap_law_in_chunks_equals_one_call():
    # 70000 mean gaps: two facade calls of at most 65536, each walking the cycle again
    g = np.linspace(0.0, 1.3, 70000)
    law = wa.gap_law("md", 0.3, 1.0, g)
    *values, w, wf, status, _ = _f.fa_gap_law(wa.MODELS["md"], 0.3, 1.0, g)
    assert status == 0 and _gap._CHUNK_GAPS < g.size
    for got, want in zip(law[1:5], values):
        assert np.array_equal(got, want)
    assert (law.W_star, law.W_fraction) == (w, wf)
