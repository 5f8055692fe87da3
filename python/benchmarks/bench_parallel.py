"""critical_forces on executors: per-chunk overhead of each kind of executor, the
scheduling overhead of the default chunk sizes (1 worker against serial) and the
speed-up with 2 workers (threads, processes, a dask LocalCluster with 2 worker
processes).

Usage (after ``pip install ./python`` and ``pip install dask distributed``)::

    python python/benchmarks/bench_parallel.py [--repeats 5] [--costs]

``--costs`` also prints the cost of one critical_forces point by model over alpha 0.1 to
3 and mu 0.01 to 30 (the cheapest is ``_loadpath._SWEEP_SECONDS``). The machine is shared
with other jobs: every timing is repeated, the runs of the different executors
alternate, and the best, the median and the worst are printed. Speed-up = best serial
time / best parallel time; "per round" gives the median and range of serial / parallel
within each round (robust to the load changing between rounds). With 1 worker the
difference to serial is the scheduling overhead of the default chunk sizes.
"""

import argparse
import multiprocessing
import os
import statistics
import time
from concurrent.futures import ProcessPoolExecutor, ThreadPoolExecutor

import numpy as np

import wavyadhesion as wa
from wavyadhesion import _loadpath
from wavyadhesion._parallel import points_per_chunk, run_chunks

WORKLOADS = {
    # ~1.5 to 2 s serially each here: several chunks per worker at the default sizes
    "dw 5 alpha x 800 mu": ("dw", np.array([[0.1], [0.3], [0.6], [1.0], [3.0]]),
                            np.logspace(-2, 1.5, 800)),
    "md 4 alpha x 200 mu": ("md", np.array([[0.1], [0.3], [1.0], [3.0]]),
                            np.logspace(-2, 1, 200)),
}


def noop(chunk):
    return chunk


def timed(f):
    t = time.perf_counter()
    f()
    return time.perf_counter() - t


def costs():
    print("cost of one critical_forces point (ms), 32 mu from 0.01 to 30:")
    for model in ("westergaard", "jkr", "dw", "md"):
        row = []
        for alpha in (0.1, 0.3, 1.0, 3.0):
            mu = np.logspace(-2, 1.5, 32)
            t = min(timed(lambda: wa.critical_forces(model, alpha, mu, errors="nan"))
                    for _ in range(3))
            row.append(f"alpha {alpha}: {t / mu.size * 1e3:.3f}")
        print(f"  {model:12s}", ", ".join(row))


def make_executors(workers):
    from dask.distributed import Client, LocalCluster

    spawn = multiprocessing.get_context("spawn")
    out = {"threads": ThreadPoolExecutor(workers),
           "processes": ProcessPoolExecutor(workers, mp_context=spawn)}
    cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                           dashboard_address=None)
    client = Client(cluster)
    out["dask"] = client.get_executor()
    return out, (client, cluster)


def close(executors, dask):
    for name in ("threads", "processes"):
        executors[name].shutdown()
    dask[0].close()
    dask[1].close()


def summary(times):
    return (f"best {min(times):7.3f} s  median {statistics.median(times):7.3f}  "
            f"worst {max(times):7.3f}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--costs", action="store_true")
    args = parser.parse_args()
    print(f"{os.cpu_count()} CPUs, load average {os.getloadavg()[0]:.2f} at start")
    if args.costs:
        costs()

    for workers in (1, 2):
        executors, dask = make_executors(workers)
        try:
            # per-chunk cost of an empty task: wall time per task of 400 tasks
            payload = [(2, [(0.3, np.linspace(0.1, 5, 64))])] * 400
            print(f"\n{workers} worker(s): overhead of an empty task (us per task, best of "
                  f"{args.repeats}):")
            empty = {}
            for name, ex in executors.items():
                run_chunks(noop, payload[:8], ex)
                t = min(timed(lambda: run_chunks(noop, payload, ex))
                        for _ in range(args.repeats))
                empty[name] = t / len(payload)
                print(f"  {name:10s} {empty[name] * 1e6:8.1f}")

            for title, (model, alpha, mu) in WORKLOADS.items():
                code = wa.MODELS[model]
                kinds = [None, *executors]
                times = {k: [] for k in kinds}
                ref = wa.critical_forces(model, alpha, mu)
                for k in kinds[1:]:            # warm up; check bits
                    got = wa.critical_forces(model, alpha, mu, executor=executors[k])
                    assert ref.P_fc.tobytes() == got.P_fc.tobytes()
                    assert ref.P_pf.tobytes() == got.P_pf.tobytes()
                for _ in range(args.repeats):  # alternate the kinds
                    for k in kinds:
                        ex = None if k is None else executors[k]
                        times[k].append(timed(
                            lambda: wa.critical_forces(model, alpha, mu, executor=ex)))
                serial = min(times[None])
                sizes = ", ".join(
                    f"{k} {points_per_chunk(executors[k], _loadpath._SWEEP_SECONDS[code], 16)}"
                    for k in kinds[1:])
                print(f"{title} ({np.broadcast(alpha, mu).size} points; points per chunk: "
                      f"{sizes}), {workers} worker(s):")
                print(f"  {'serial':10s} {summary(times[None])}")
                for k in kinds[1:]:
                    b = min(times[k])
                    # overhead from the empty-task cost (less noisy than the timings):
                    # chunks x cost per chunk / (best serial time / workers)
                    n_chunks = len(_loadpath._sweep_pieces(
                        *np.unique(np.broadcast_to(alpha, np.broadcast(alpha, mu).shape)
                                   .reshape(-1), return_inverse=True),
                        points_per_chunk(executors[k], _loadpath._SWEEP_SECONDS[code], 16)))
                    est = n_chunks * empty[k] / (serial / workers)
                    # per round: serial time / this kind's time in the same round
                    ratios = [s / t for s, t in zip(times[None], times[k])]
                    rounds = (f"per round: median {statistics.median(ratios):4.2f}, "
                              f"{min(ratios):4.2f} to {max(ratios):4.2f}")
                    what = (f"overhead {100 * (b / serial - 1):+5.1f} % ({rounds})"
                            if workers == 1 else f"speed-up {serial / b:4.2f} ({rounds})")
                    print(f"  {k:10s} {summary(times[k])}  {what}; {n_chunks} chunks, "
                          f"estimated overhead {100 * est:.1f} %")
        finally:
            close(executors, dask)
    print(f"\nload average {os.getloadavg()[0]:.2f} at the end")


if __name__ == "__main__":
    main()
