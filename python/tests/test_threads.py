"""The facade releases the GIL and the library keeps no state: results computed by 4
threads at once equal the serial results bit for bit."""

from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import wavyadhesion as wa


@pytest.mark.parametrize("model", wa.MODELS)
def test_four_threads_equal_serial(model):
    rng = np.random.default_rng(7)
    jobs = [(rng.uniform(0.05, 2.0), rng.uniform(0.0, 10.0), rng.uniform(0.0, 0.5, 500))
            for _ in range(16)]
    serial = [wa.equilibrium(model, al, mu, a) for al, mu, a in jobs]
    with ThreadPoolExecutor(max_workers=4) as pool:
        threaded = list(pool.map(lambda job: wa.equilibrium(model, *job), jobs))
    for s, t in zip(serial, threaded):
        for x, y in zip(s, t):
            np.testing.assert_array_equal(x, y)


def test_threads_with_errors_and_roots():
    def work(i):
        msg = ""
        try:
            wa.equilibrium("dw", 0.3, 1.0, [0.1, 0.6 + 0.01 * i])
        except wa.InvalidArgumentError as exc:
            msg = str(exc)
        return msg, wa.roots("dw", 0.3, 1.0, 0.01 * (i + 1))

    serial = [work(i) for i in range(24)]
    with ThreadPoolExecutor(max_workers=4) as pool:
        threaded = list(pool.map(work, range(24)))
    assert serial == threaded


def test_four_threads_branches_paths_critical():
    """trace_branch, load_path and critical_forces from 4 threads at once equal the
    serial results bit for bit."""
    jobs = [(model, mu) for model in ("dw", "md", "jkr", "westergaard")
            for mu in (1.0, 3.0, 5.0)]

    def work(job):
        model, mu = job
        b = wa.trace_branch(model, 0.3, mu)
        p = wa.load_path(model, 0.3, mu)
        c = wa.critical_forces(model, [0.3, 0.6], mu)
        return ([getattr(b, k) for k in ("a_star", "c_star", "P_star", "zone_case",
                                         "stable", "event")],
                [p.stage, p.event, p.a_star, p.P_star, np.array([p.P_fc, p.P_pf])],
                [c.P_fc, c.P_pf, c.fc_mechanism, c.pf_mechanism])

    serial = [work(job) for job in jobs]
    with ThreadPoolExecutor(max_workers=4) as pool:
        threaded = list(pool.map(work, jobs * 2))
    for s, t in zip(serial * 2, threaded):
        for xs, ys in zip(s, t):
            for x, y in zip(xs, ys):
                np.testing.assert_array_equal(x, y)
