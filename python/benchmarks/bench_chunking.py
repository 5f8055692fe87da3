"""Cost of the chunked (interruptible) vectorised calls: best wall time of a 1-element
and a 10^5-element ``equilibrium("dw", 0.3, 1.0, a)``, a 1-element ``jkr_load`` and
``critical_forces("dw", 0.3, mu)`` on 1 and 200 values of mu.

Usage (after ``pip install ./python``)::

    python python/benchmarks/bench_chunking.py [--repeats 7]
"""

import argparse
import time

import numpy as np

import wavyadhesion as wa


def best(f, repeats):
    f()
    t = float("inf")
    for _ in range(repeats):
        t0 = time.perf_counter()
        f()
        t = min(t, time.perf_counter() - t0)
    return t


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=7)
    args = parser.parse_args()
    r = args.repeats
    a1 = np.array([0.2])
    a5 = 0.5 * np.arange(1, 100_001) / 100_001
    mu200 = np.logspace(-2, 1, 200)
    rows = [
        ("equilibrium 1", lambda: wa.equilibrium("dw", 0.3, 1.0, a1), r),
        ("equilibrium scalar", lambda: wa.equilibrium("dw", 0.3, 1.0, 0.2), r),
        ("equilibrium 1e5", lambda: wa.equilibrium("dw", 0.3, 1.0, a5), max(1, r // 2)),
        ("jkr_load 1", lambda: wa.jkr_load(0.3, 0.2), r),
        ("jkr_load 1e5", lambda: wa.jkr_load(0.3, a5), r),
        ("critical_forces 1", lambda: wa.critical_forces("dw", 0.3, 1.0), r),
        ("critical_forces 200", lambda: wa.critical_forces("dw", 0.3, mu200), 2),
    ]
    for name, f, n in rows:
        t = best(f, n)
        print(f"{name:22s} {t * 1e6:12.1f} us")


if __name__ == "__main__":
    main()
