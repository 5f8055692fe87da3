"""Sweeps on executors (issue 13 item 4): critical_forces(..., executor=) on a thread
pool, a process pool and a dask.distributed LocalCluster of 2 workers returns the serial
result bit for bit, failures included.

dask and distributed are test requirements (tools/setup.sh installs them): this module
imports them unconditionally, so without them the run fails instead of skipping. The
LocalCluster runs 2 worker processes (processes=True, as on a real cluster: tasks and
results cross process boundaries through dask's serialisation); it starts in ~1.3 s
here, once for the module. Should that prove flaky on a loaded CI machine,
processes=False (workers as threads of this process, ~0.05 s) still tests dask's
scheduler and `client.get_executor()`, and the process pool covers pickling.
The MPI form (mpi4py.futures.MPIPoolExecutor) is documented, not tested.
"""

import multiprocessing
import pickle
from concurrent.futures import ProcessPoolExecutor, ThreadPoolExecutor

import numpy as np
import pytest
from dask.distributed import Client, LocalCluster

import wavyadhesion as wa
from wavyadhesion import _loadpath, _wa_f2py as _f
from wavyadhesion._parallel import chunk_seconds, points_per_chunk, run_chunks

FIELDS = ("P_fc", "P_pf", "fc_mechanism", "pf_mechanism", "status")

# (model, alpha, mu, kwargs): broadcasts, several alphas, points that fail (DW at
# alpha = 1e-3, mu = 1e30 and 1e100: numerical error, status 5), an invalid mu.
CASES = {
    "dw_grid": ("dw", [[0.3], [1.0]], np.logspace(-2, 1, 24), {}),
    "dw_pairs": ("dw", np.linspace(0.2, 2.0, 12), np.linspace(0.5, 6.0, 12), {}),
    "failures": ("dw", 1e-3, [0.5, 1e30, 2.0, 1e100, 3.0], {"errors": "nan"}),
    "md": ("md", [0.3, 1.0], [[0.5], [2.0]], {}),
    "dw_nan": ("dw", 0.3, [[1.0, 0.0, 5.0], [-1.0, 2.0, 3.0]], {"errors": "nan"}),
    "closed_forms": ("jkr", [0.1, 0.5], [[0.0], [3.0]], {}),
}


@pytest.fixture(scope="module")
def executors():
    """One of each kind, shared by the module (dask's start-up is the slow part)."""
    threads = ThreadPoolExecutor(max_workers=2)
    # spawn: no fork of a process that runs threads (dask's, the thread pool's)
    processes = ProcessPoolExecutor(max_workers=2,
                                    mp_context=multiprocessing.get_context("spawn"))
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                           dashboard_address=None)
    client = Client(cluster)
    try:
        yield {"threads": threads, "processes": processes, "dask": client.get_executor()}
    finally:
        client.close()
        cluster.close()
        processes.shutdown()
        threads.shutdown()


def assert_same(serial, parallel):
    for name in FIELDS:
        a, b = getattr(serial, name), getattr(parallel, name)
        assert np.shape(a) == np.shape(b) and np.asarray(a).dtype == np.asarray(b).dtype
        # bit for bit: equal bytes, NaN included
        assert np.asarray(a).tobytes() == np.asarray(b).tobytes(), name
    assert serial.messages == parallel.messages


@pytest.mark.parametrize("kind", ["threads", "processes", "dask"])
@pytest.mark.parametrize("case", CASES)
def test_executor_equals_serial(executors, kind, case):
    model, alpha, mu, kwargs = CASES[case]
    serial = wa.critical_forces(model, alpha, mu, **kwargs)
    if kwargs:                                      # the failures are really there
        assert set(np.unique(serial.status)) == ({0, 5} if case == "failures" else {0, 1})
    # small chunks: many tasks, chunks that hold pieces of two alphas
    for chunk_size in (None, 5):
        parallel = wa.critical_forces(model, alpha, mu, executor=executors[kind],
                                      chunk_size=chunk_size, **kwargs)
        assert_same(serial, parallel)


@pytest.mark.parametrize("kind", ["threads", "processes", "dask"])
def test_executor_raises_as_serial(executors, kind):
    mu = [0.5, 1e30, 2.0, 1e100]
    with pytest.raises(wa.ConvergenceError) as serial:
        wa.critical_forces("dw", 1e-3, mu)
    with pytest.raises(wa.ConvergenceError) as parallel:
        wa.critical_forces("dw", 1e-3, mu, executor=executors[kind], chunk_size=1)
    assert str(parallel.value) == str(serial.value) and "index (1,)" in str(serial.value)
    assert parallel.value.status == serial.value.status


def test_invalid_argument_before_any_task(executors):
    class Refuse:
        def map(self, func, chunks):
            raise AssertionError("work submitted")

    with pytest.raises(wa.InvalidArgumentError, match=r"mu .*index \(2,\)"):
        wa.critical_forces("dw", 0.3, [1.0, 2.0, -1.0], executor=Refuse(), chunk_size=1)


@pytest.mark.parametrize("bad", [0, -3, 2.5, True, "4"])
def test_chunk_size_checked(bad):
    with pytest.raises(wa.InvalidArgumentError, match="chunk_size"):
        wa.critical_forces("dw", 0.3, [1.0, 2.0], chunk_size=bad)
    with pytest.raises(wa.InvalidArgumentError, match="chunk_size"):
        wa.critical_forces("dw", 0.3, 1.0, chunk_size=bad)


def test_serial_chunks_unchanged(monkeypatch):
    """Without an executor the facade is called with at most 16 mu of one alpha, as
    before (Ctrl-C between chunks); chunk_size changes the calls, not the results."""
    calls = []
    real = _f.fa_critical_sweep

    def spy(code, alpha, mu):
        calls.append((alpha, len(mu)))
        return real(code, alpha, mu)

    monkeypatch.setattr(_f, "fa_critical_sweep", spy)
    mu = np.linspace(0.5, 5.0, 40)
    first = wa.critical_forces("dw", [[0.3], [0.6]], mu)
    assert calls == [(0.3, 16), (0.3, 16), (0.3, 8), (0.6, 8), (0.6, 16), (0.6, 16)]
    calls.clear()
    assert_same(first, wa.critical_forces("dw", [[0.3], [0.6]], mu, chunk_size=80))
    assert calls == [(0.3, 40), (0.6, 40)]


def test_run_chunks_order_and_picklable_worker():
    chunks = [(2, [(0.3, np.array([1.0, 2.0]))]), (2, [(0.6, np.array([3.0]))]),
              (0, [(0.1, np.array([0.0]))])]
    serial = run_chunks(_loadpath._sweep_task, chunks)
    assert len(serial) == 3 and [len(r) for r in serial] == [1, 1, 1]
    pickle.dumps(_loadpath._sweep_task)                  # by reference: processes, dask, MPI
    with ThreadPoolExecutor(max_workers=2) as pool:
        threaded = run_chunks(_loadpath._sweep_task, chunks, pool)
    for s, t in zip(serial, threaded):
        for x, y in zip(s[0], t[0]):
            assert np.asarray(x).tobytes() == np.asarray(y).tobytes()
    assert run_chunks(abs, iter([-1, 2, -3])) == [1, 2, 3]


def test_chunk_sizes_by_executor(executors):
    assert chunk_seconds(executors["threads"]) == 0.01
    assert chunk_seconds(executors["processes"]) == 0.05
    assert chunk_seconds(executors["dask"]) == 0.2
    assert chunk_seconds(object()) == 0.05                   # MPI and anything else
    # DW: >= 50 ms of work per process chunk at the cheapest measured cost per mu
    n = points_per_chunk(executors["processes"], _loadpath._SWEEP_SECONDS[2], 16)
    assert n * _loadpath._SWEEP_SECONDS[2] >= 0.05 and n == 173
