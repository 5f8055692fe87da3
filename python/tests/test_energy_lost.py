"""wavyadhesion.energy_lost (issue 13 item 2): W* and W*/(pi alpha^2/2) of gap_path over
arrays, on executors bit for bit as serially, failures as NaN with their status, bad input
refused naming the argument; the W* contours of plotting.adhesion_map."""

import multiprocessing
import pickle
from concurrent.futures import ProcessPoolExecutor, ThreadPoolExecutor

import numpy as np
import pytest

import wavyadhesion as wa
from wavyadhesion import _energy

ALPHA = np.array([0.05, 0.3, 2.0])
MU = np.array([0.0, 0.2, 1.0, 5.0, 40.0])

# DW at alpha = 1e-3 and mu = 1e30 fails in ~1 ms (numerical error, status 5: double
# precision does not resolve the zone there)
FAILING = (1e-3, 1e30)


def assert_same(a, b):
    for name in ("W_star", "W_fraction", "status", "alpha", "mu"):
        x, y = np.asarray(getattr(a, name)), np.asarray(getattr(b, name))
        assert x.shape == y.shape and x.dtype == y.dtype, name
        assert x.tobytes() == y.tobytes(), name          # bit for bit, NaN included
    assert a.messages == b.messages


@pytest.mark.parametrize("model", ["westergaard", "jkr", "dw", "md"])
def test_equals_gap_path(model):
    e = wa.energy_lost(model, ALPHA[None, :], MU[:, None])
    assert e.W_star.shape == (MU.size, ALPHA.size) and e.ok.all() and e.messages == {}
    for i, mu in enumerate(MU):
        for j, alpha in enumerate(ALPHA):
            path = wa.gap_path(model, alpha, mu)
            assert e.W_star[i, j] == path.W_star and e.W_fraction[i, j] == path.W_fraction
            assert e.alpha[i, j] == alpha and e.mu[i, j] == mu


def test_scalar_and_broadcast():
    e = wa.energy_lost("dw", 0.3, 1.0)
    assert np.ndim(e.W_star) == 0 and float(e.W_fraction) == wa.gap_path("dw", 0.3, 1.0).W_fraction
    assert e.status == 0 and e.messages == {}
    e = wa.energy_lost("dw", [0.3, 0.6], 1.0)
    assert e.W_star.shape == (2,) and np.all(e.mu == 1.0)


@pytest.mark.parametrize("chunk_size", [None, 1, 4])
def test_threads_equal_serial(chunk_size):
    alpha = np.array([0.3, FAILING[0], 1.0])[None, :]
    mu = np.array([0.5, 3.0, FAILING[1]])[:, None]
    serial = wa.energy_lost("dw", alpha, mu, errors="nan")
    assert set(np.unique(serial.status)) == {0, 5}       # the failure is really there
    with ThreadPoolExecutor(2) as pool:
        threaded = wa.energy_lost("dw", alpha, mu, errors="nan", executor=pool,
                                  chunk_size=chunk_size)
    assert_same(serial, threaded)
    assert_same(serial, wa.energy_lost("dw", alpha, mu, errors="nan", chunk_size=chunk_size))


def test_process_pool_equals_serial():
    """The worker and its tasks cross process boundaries (as with dask or MPI)."""
    pickle.dumps(_energy._energy_task)
    serial = wa.energy_lost("md", ALPHA[None, :], MU[:, None])
    with ProcessPoolExecutor(2, mp_context=multiprocessing.get_context("spawn")) as pool:
        assert_same(serial, wa.energy_lost("md", ALPHA[None, :], MU[:, None], executor=pool,
                                           chunk_size=3))


def test_dask_equals_serial():
    """dask.distributed's executor (a test requirement, tools/setup.sh); workers as
    threads of this process (~0.05 s to start; the process pool above covers pickling)."""
    distributed = pytest.importorskip("distributed")
    alpha = np.array([0.3, FAILING[0]])[None, :]
    mu = np.array([1.0, FAILING[1]])[:, None]
    serial = wa.energy_lost("dw", alpha, mu, errors="nan")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=False,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        assert_same(serial, wa.energy_lost("dw", alpha, mu, errors="nan", chunk_size=1,
                                           executor=client.get_executor()))


def test_failure_is_nan_with_status():
    e = wa.energy_lost("dw", [0.3, FAILING[0]], [1.0, FAILING[1]], errors="nan")
    assert np.isfinite(e.W_star[0]) and np.isnan(e.W_star[1]) and np.isnan(e.W_fraction[1])
    assert list(e.status) == [0, 5] and list(e.ok) == [True, False]
    assert list(e.messages) == [(1,)] and "mu is too large" in e.messages[(1,)]
    # an invalid point with errors="nan": NaN, status 1 and the library's message
    e = wa.energy_lost("dw", 0.3, [1.0, -1.0], errors="nan")
    assert list(e.status) == [0, 1] and e.messages[(1,)].startswith("mu = ")


def test_failure_raises():
    with pytest.raises(wa.ConvergenceError) as err:
        wa.energy_lost("dw", FAILING[0], [1.0, FAILING[1]])
    assert err.value.status == 5
    assert "index (1,)" in str(err.value) and "mu = 1e+30" in str(err.value)


@pytest.mark.parametrize("kwargs, name", [
    (dict(alpha=-1.0), "alpha"), (dict(alpha=np.nan), "alpha"), (dict(mu=[1.0, -2.0]), "mu"),
    (dict(mu=np.inf), "mu"), (dict(model="nope"), "model"), (dict(errors="skip"), "errors"),
    (dict(chunk_size=0), "chunk_size"), (dict(mu=[]), "empty"), (dict(alpha=None), "alpha"),
])
def test_bad_input(kwargs, name):
    args = dict(model="dw", alpha=0.3, mu=1.0)
    extra = {k: kwargs.pop(k) for k in ("errors", "chunk_size") if k in kwargs}
    args.update(kwargs)
    with pytest.raises(ValueError, match=name) as err:
        wa.energy_lost(args["model"], args["alpha"], args["mu"], **extra)
    assert isinstance(err.value, wa.InvalidArgumentError)


def test_invalid_argument_before_any_task():
    class Refuse:
        def map(self, func, chunks):
            raise AssertionError("work submitted")

    with pytest.raises(wa.InvalidArgumentError, match=r"mu .*index \(2,\)"):
        wa.energy_lost("dw", 0.3, [1.0, 2.0, -1.0], executor=Refuse(), chunk_size=1)


def test_tasks_are_strided(monkeypatch):
    """A task takes every n-th point, so cheap and costly cycles mix in every task."""
    seen = []
    real = _energy._energy_task

    def spy(task):
        seen.append(task[2].tolist())
        return real(task)

    monkeypatch.setattr(_energy, "_energy_task", spy)
    wa.energy_lost("westergaard", 0.3, [0.0, 1.0, 2.0, 3.0, 4.0], chunk_size=2)
    assert seen == [[0.0, 3.0], [1.0, 4.0], [2.0]]


def test_pchip_and_holes():
    from wavyadhesion.plotting import _pchip
    x = np.array([0.0, 1.0, 3.0, 4.0])
    y = np.array([[1.0, 2.0, 4.0, 5.0], [0.0, 1.0, np.nan, 1.0]])
    xf = np.linspace(0.0, 4.0, 17)
    out = _pchip(x, y, xf)
    np.testing.assert_allclose(out[0], 1.0 + xf, rtol=0, atol=1e-14)   # linear: exact
    # the NaN node's two cells are a hole; the cell before it stays finite
    assert np.all(np.isfinite(out[1][xf <= 1.0])) and np.all(np.isnan(out[1][(xf > 1) & (xf < 4)]))
    assert np.all((out[0][:-1] <= out[0][1:]))                          # monotone


def test_map_plot_with_energy():
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from wavyadhesion import plotting
    amap = wa.adhesion_map("dw", [0.3, 0.5, 1.0], (0.1, 100.0, 12), forces=True)
    alpha = np.array([0.3, 0.5, 1.0, 2.0])
    mu = np.geomspace(0.5, 100.0, 6)
    energy = wa.energy_lost("dw", alpha[None, :], mu[:, None], errors="nan")
    energy.W_fraction[2, 1] = np.nan                     # a hole, as a failed point leaves
    energy.status[2, 1] = 5
    fig = plotting.adhesion_map(amap, energy=energy, energy_levels=(0.2, 0.3))
    ax = fig.axes[0]
    assert ax.get_xscale() == "log"
    labels = [t.get_text() for t in ax.texts]
    assert "0.2" in labels and "0.3" in labels          # one label per level
    assert sum(t in ("0.2", "0.3") for t in labels) == 2
    legend = [t.get_text() for t in ax.get_legend().get_texts()]
    assert any("W^*" in t and "hole" in t for t in legend)
    plt.close(fig)
    with pytest.raises(ValueError, match="energy"):
        plotting.adhesion_map(amap, energy=wa.energy_lost("dw", alpha, 1.0))
