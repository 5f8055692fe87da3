"""Overhead of the Python layer: ``equilibrium("dw", 0.3, 1.0, a)`` on n values of a*
against a pure-Fortran loop over the same points (benchmark/overhead/bench_overhead.f90, built and run
by fpm in release mode). Target: ratio <= 1.5.

Usage (from anywhere, after ``pip install ./python``)::

    python python/benchmarks/bench_overhead.py [--n 100000] [--repeats 5]

The repository is found through $WAVYADHESION_REPO or relative to this file; without it
(or without fpm) only the Python time is printed.
"""

import argparse
import os
import re
import shutil
import subprocess
import time
from pathlib import Path

import numpy as np

import wavyadhesion as wa


def python_seconds(a, repeats):
    """Best wall time of one vectorised call over all points."""
    wa.equilibrium("dw", 0.3, 1.0, a[:10])          # warm up (import, first-touch)
    best = float("inf")
    for _ in range(repeats):
        t0 = time.perf_counter()
        eq = wa.equilibrium("dw", 0.3, 1.0, a)
        best = min(best, time.perf_counter() - t0)
    return best, eq


def fortran_seconds(n, repeats):
    """Best time of the pure-Fortran loop, or None when it cannot be run."""
    repo = Path(os.environ.get("WAVYADHESION_REPO", Path(__file__).resolve().parents[2]))
    if not (repo / "benchmark" / "overhead" / "bench_overhead.f90").is_file() or shutil.which("fpm") is None:
        return None
    cmd = ["fpm", "run", "--profile", "release", "bench_overhead", "--",
           str(n), str(repeats)]
    out = subprocess.run(cmd, cwd=repo / "study", capture_output=True, text=True, check=True).stdout
    match = re.search(r"fortran_seconds\s+(\S+)", out)
    return float(match.group(1)) if match else None


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=100_000, help="number of a* values")
    parser.add_argument("--repeats", type=int, default=5, help="timings (best is kept)")
    args = parser.parse_args()

    n = args.n
    a = 0.5 * np.arange(1, n + 1) / (n + 1)         # the Fortran program's grid
    t_py, eq = python_seconds(a, args.repeats)
    print(f"points                {n}")
    print(f"python   equilibrium  {t_py:.4f} s  ({1e6 * t_py / n:.3f} us/point)")
    t_f = fortran_seconds(n, args.repeats)
    if t_f is None:
        print("fortran  loop         (not run: repository or fpm not found)")
        return
    print(f"fortran  loop         {t_f:.4f} s  ({1e6 * t_f / n:.3f} us/point)")
    ratio = t_py / t_f
    print(f"overhead ratio        {ratio:.3f}  (target <= 1.5: "
          f"{'met' if ratio <= 1.5 else 'NOT met'})")
    print(f"checksum              {eq.P_star.sum() + eq.c_star.sum() + eq.zone_case.sum():.5e}")


if __name__ == "__main__":
    main()
