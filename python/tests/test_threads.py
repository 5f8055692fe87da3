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
