"""Responsiveness of the long calls to Ctrl-C, and the cost of making them interruptible.

1. Short calls: best wall time of ``critical_forces("dw", 0.3, mu)`` on 1 and 200 values
   of mu, ``gap_critical("dw", 0.3, mu)`` on 1 and 200 values, ``gap_law`` on 100 gaps
   and a small ``adhesion_map`` (the overhead of chunking and of the waiting thread).
2. Time to interrupt: each long call runs in a child process that gets SIGINT 1 s after
   the call started; the figure is the time from SIGINT to the child's exit with
   KeyboardInterrupt (the whole call's duration is printed for comparison with --full).

Usage (after ``pip install ./python``; POSIX only for part 2)::

    python python/benchmarks/bench_interrupt.py [--repeats 7] [--full] [--short-only]

To compare with another build, run it in both virtual environments and keep the best of
several runs (the timings of a shared machine vary by 2x).
"""

import argparse
import os
import signal
import subprocess
import sys
import time
import timeit

import numpy as np

import wavyadhesion as wa

#: The long calls of part 2 (code run in the child after ``import numpy as np,
#: wavyadhesion as wa``).
LONG_CALLS = {
    "gap_critical md 20000 mu": "wa.gap_critical('md', 0.3, np.logspace(-2, 1, 20000))",
    "adhesion_map md": "wa.adhesion_map('md')",
    "critical_forces md 2000 mu": "wa.critical_forces('md', 0.3, np.logspace(-2, 1, 2000))",
}

CHILD = """
import sys, time
import numpy as np, wavyadhesion as wa
print('start', flush=True)
t0 = time.perf_counter()
try:
    {call}
except KeyboardInterrupt:
    print('interrupted', flush=True)
    sys.exit(130)
print('done %.3f' % (time.perf_counter() - t0), flush=True)
"""


def best(f, repeats, number=1):
    """Best wall time per call of `number` calls, over `repeats` timings."""
    f()
    return min(timeit.repeat(f, number=number, repeat=repeats)) / number


def time_to_interrupt(call, delay=1.0):
    """Seconds from SIGINT (sent `delay` s after the call started) to the child's exit,
    and how the child ended."""
    child = subprocess.Popen([sys.executable, "-c", CHILD.format(call=call)],
                             stdout=subprocess.PIPE, text=True)
    assert child.stdout.readline().strip() == "start"
    time.sleep(delay)
    t0 = time.perf_counter()
    child.send_signal(signal.SIGINT)
    out = child.stdout.read()
    child.wait()
    return time.perf_counter() - t0, out.strip() or f"exit {child.returncode}"


def full_time(call):
    """Wall time of the whole call in a fresh child."""
    out = subprocess.run([sys.executable, "-c", CHILD.format(call=call)],
                         capture_output=True, text=True, check=True).stdout
    return float(out.split()[-1])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=7)
    parser.add_argument("--full", action="store_true",
                        help="also time each long call to its end")
    parser.add_argument("--short-only", action="store_true", help="part 1 only")
    args = parser.parse_args()
    r = args.repeats
    mu200 = np.logspace(-2, 1, 200)
    g100 = np.linspace(0.0, 1.2, 100)
    rows = [
        ("critical_forces 1", lambda: wa.critical_forces("dw", 0.3, 1.0), 100),
        ("critical_forces 200", lambda: wa.critical_forces("dw", 0.3, mu200), 1),
        ("gap_critical 1", lambda: wa.gap_critical("dw", 0.3, 1.0), 100),
        ("gap_critical 200", lambda: wa.gap_critical("dw", 0.3, mu200), 1),
        ("gap_law 100", lambda: wa.gap_law("dw", 0.3, 1.0, g100), 20),
        ("adhesion_map dw 8x8", lambda: wa.adhesion_map("dw", (0.1, 1.0, 8),
                                                        (0.1, 10.0, 8)), 1),
    ]
    print("short calls (best wall time per call)")
    for name, f, number in rows:
        print(f"  {name:26s} {best(f, r, number) * 1e3:10.3f} ms")
    if args.short_only:
        return
    if os.name != "posix":
        print("time to interrupt: POSIX only")
        return
    print("time to interrupt (SIGINT 1 s after the start)")
    for name, call in LONG_CALLS.items():
        dt, how = time_to_interrupt(call)
        line = f"  {name:26s} {dt:8.3f} s  ({how})"
        if args.full:
            line += f"  whole call {full_time(call):.2f} s"
        print(line)


if __name__ == "__main__":
    main()
