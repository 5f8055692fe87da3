"""Cost of the chunked (interruptible) vectorised calls: best wall time of a 1-element
and a 10^5-element ``equilibrium("dw", 0.3, 1.0, a)``, a 1-element ``jkr_load`` and
``critical_forces("dw", 0.3, mu)`` on 1 and 200 values of mu, and one-point
``energy_lost``, ``gap_critical``, ``profile``, ``trace_branch`` (the cost of the result
types).

Usage (after ``pip install ./python``)::

    python python/benchmarks/bench_chunking.py [--repeats 9]

To compare with a build before chunking, run it alternately in two virtual environments
and keep the best of several runs (the timings of a shared machine vary by 2x).
"""

import argparse
import timeit

import numpy as np

import wavyadhesion as wa


def best(f, repeats, number=1):
    """Best wall time per call of `number` calls, over `repeats` timings."""
    f()
    return min(timeit.repeat(f, number=number, repeat=repeats)) / number


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=9)
    args = parser.parse_args()
    r = args.repeats
    a1 = np.array([0.2])
    a5 = 0.5 * np.arange(1, 100_001) / 100_001
    mu200 = np.logspace(-2, 1, 200)
    rows = [
        ("equilibrium scalar", lambda: wa.equilibrium("dw", 0.3, 1.0, 0.2), 2000),
        ("equilibrium 1", lambda: wa.equilibrium("dw", 0.3, 1.0, a1), 2000),
        ("equilibrium 1e5", lambda: wa.equilibrium("dw", 0.3, 1.0, a5), 1),
        ("jkr_load scalar", lambda: wa.jkr_load(0.3, 0.2), 2000),
        ("jkr_load 1e5", lambda: wa.jkr_load(0.3, a5), 1),
        ("critical_forces 1", lambda: wa.critical_forces("dw", 0.3, 1.0), 100),
        ("critical_forces 200", lambda: wa.critical_forces("dw", 0.3, mu200), 1),
        ("energy_lost 1", lambda: wa.energy_lost("dw", 0.3, 1.0), 100),
        ("gap_critical 1", lambda: wa.gap_critical("dw", 0.3, 1.0), 100),
        ("profile 401", lambda: wa.profile("dw", 0.3, 1.0, 0.2), 200),
        ("trace_branch", lambda: wa.trace_branch("dw", 0.3, 1.0), 100),
    ]
    for name, f, number in rows:
        t = best(f, r, number)
        print(f"{name:22s} {t * 1e6:12.2f} us")


if __name__ == "__main__":
    main()
