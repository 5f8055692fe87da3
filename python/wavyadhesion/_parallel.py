"""Running the chunks of a sweep, serially or on any ``concurrent.futures``-style executor.

The vectorised functions split their work into chunks (one or a few facade calls each),
described by picklable tuples, and hand them to :func:`run_chunks` (or
:func:`iter_chunks`) with a module-level worker function. Without an executor the chunks
run one after the other in this thread, so Ctrl-C raises ``KeyboardInterrupt`` between
two of them, exactly as before; with one, ``executor.map`` runs them: a
``ThreadPoolExecutor`` (the facade releases the GIL), a ``ProcessPoolExecutor``, a
dask.distributed ``Client.get_executor()`` or an ``mpi4py.futures.MPIPoolExecutor``.
Results come back in the order of the chunks, so they are the serial ones bit for bit
(the library is deterministic and every chunk is computed by the same code).

Chunk sizes: an executor costs a roughly fixed time per chunk (submitting, pickling,
scheduling, collecting). :func:`chunk_seconds` gives, per kind of executor, the work a
chunk should hold so that this costs < 5 % of the run with 2 workers; the sweeps divide
it by the cheapest measured cost of one point (so a chunk holds at least that much work).
Measured here (2 cores, shared; ``python python/benchmarks/bench_parallel.py``):
per-chunk cost of an empty task, as wall time per task with 2 workers, about 17 us
(threads), 0.2 ms (processes), 0.7 ms (dask, LocalCluster processes=False) and 3.3 ms
(dask, processes=True). With 2 workers the overhead is 2 x cost / chunk work, hence the
targets 10 ms, 50 ms, 200 ms (dask) and 50 ms (MPI and any other executor).
"""

from __future__ import annotations

import math
import sys
import threading
import time

from ._errors import INVALID_ARGUMENT, InvalidTypeError

__all__ = ["run_chunks", "iter_chunks", "chunk_seconds", "points_per_chunk", "Background",
           "call_interruptibly", "Progress", "make_progress"]

# How often (s) a thread waiting for a Background call wakes up to let Python handle a
# signal (Ctrl-C); POSIX interrupts the wait itself, this bounds it elsewhere.
_WAIT_STEP = 0.1

# Work (seconds) per chunk by kind of executor; see the module docstring.
_SECONDS_THREADS = 0.01
_SECONDS_DASK = 0.2
_SECONDS_OTHER = 0.05     # processes, MPI, anything else


def iter_chunks(func, chunks, executor=None):
    """The results of ``func(chunk)`` for every chunk, in the order of `chunks`, as a
    generator.

    Serially (``executor=None``) a chunk is computed when its result is asked for, so a
    caller that raises on a result stops the work there, and Ctrl-C raises between
    two chunks. With an executor, ``executor.map(func, chunks)`` submits every chunk at
    once; closing the generator early (an exception in the caller, Ctrl-C) cancels the
    chunks that have not started (``concurrent.futures`` and dask do).
    """
    if executor is None:
        for chunk in chunks:              # Python handles a pending SIGINT between chunks
            yield func(chunk)
        return
    results = executor.map(func, chunks)
    try:
        yield from results
    finally:
        close = getattr(results, "close", None)
        if close is not None:
            close()                       # cancels what has not started


def run_chunks(func, chunks, executor=None) -> list:
    """``[func(c) for c in chunks]``, serially or on `executor`, in input order.

    Parameters
    ----------
    func : callable
        A module-level function of one argument (picklable by reference, as process
        pools, dask and MPI need).
    chunks : iterable
        The work items (picklable for processes, dask and MPI).
    executor : concurrent.futures.Executor, optional
        None (default): a plain loop in this thread; Ctrl-C raises KeyboardInterrupt
        between two chunks. Otherwise anything with ``map(func, iterable)`` returning
        results in input order: ``ThreadPoolExecutor``, ``ProcessPoolExecutor``,
        dask.distributed ``client.get_executor()``, ``mpi4py.futures.MPIPoolExecutor``.

    Returns
    -------
    list
        One result per chunk, in the order of `chunks`.
    """
    return list(iter_chunks(func, chunks, executor))


def chunk_seconds(executor) -> float:
    """Work (s) a chunk should hold on `executor` so that the per-chunk cost stays
    below 5 % with 2 workers (module docstring)."""
    from concurrent.futures import ThreadPoolExecutor

    if isinstance(executor, ThreadPoolExecutor):
        return _SECONDS_THREADS
    if type(executor).__module__.split(".")[0] == "distributed":
        return _SECONDS_DASK
    return _SECONDS_OTHER


def points_per_chunk(executor, seconds_per_point: float, minimum: int = 1) -> int:
    """Points per chunk: :func:`chunk_seconds` over the cost of one point, at least
    `minimum`."""
    return max(minimum, math.ceil(chunk_seconds(executor) / seconds_per_point))


class Background:
    """``func(*args)`` started in a helper thread (a daemon) at once; :meth:`result`
    waits for it in steps of 0.1 s.

    For one long facade call that cannot be cut into chunks (the adhesion map): Python
    handles Ctrl-C only between bytecodes of the main thread, never during a foreign call,
    but the facade releases the GIL, so the main thread waits here instead and
    ``KeyboardInterrupt`` is raised within 0.1 s. The Fortran call itself cannot be
    stopped: it runs on in the helper thread to its end (its result is dropped; the
    library has no global state, so nothing is left inconsistent), and a daemon thread
    does not keep the interpreter from exiting.
    """

    def __init__(self, func, *args):
        self._outcome = {}
        self._thread = threading.Thread(target=self._run, args=(func, args), daemon=True,
                                        name="wavyadhesion-call")
        self._thread.start()

    def _run(self, func, args):
        try:
            self._outcome["value"] = func(*args)
        except BaseException as exc:         # re-raised in the waiting thread
            self._outcome["error"] = exc

    def result(self):
        """The call's result (or its exception), once it has finished."""
        while self._thread.is_alive():
            self._thread.join(_WAIT_STEP)    # Ctrl-C raises KeyboardInterrupt here
        if "error" in self._outcome:
            raise self._outcome["error"]
        return self._outcome["value"]


def call_interruptibly(func, *args):
    """``func(*args)``, with Ctrl-C raising ``KeyboardInterrupt`` within 0.1 s even while
    it runs one long foreign call (see :class:`Background`)."""
    return Background(func, *args).result()


class Progress:
    """Progress of a sweep of `total` points, reported by :meth:`update` as chunks come
    back (a long sweep's ``progress=`` argument):

    - a callable: called as ``fn(done, total)`` after each chunk (and once with 0 first);
    - True: a tqdm bar on stderr when tqdm is installed, else a line on stderr rewritten
      at most every 0.2 s (and at the end).

    Use :func:`make_progress`, which returns None for ``progress=None`` or False (no cost
    at all then).
    """

    def __init__(self, progress, total: int, desc: str):
        self.total, self.done, self.desc = int(total), 0, desc
        self._fn = progress if callable(progress) else None
        self._bar = None
        self._last = 0.0
        if self._fn is None:
            try:
                from tqdm.auto import tqdm
            except ImportError:
                tqdm = None
            if tqdm is not None:
                self._bar = tqdm(total=self.total, desc=desc, unit="pt")
        self._report()

    def _report(self):
        if self._fn is not None:
            self._fn(self.done, self.total)
        elif self._bar is None:
            now = time.monotonic()
            if self.done in (0, self.total) or now - self._last >= 0.2:
                self._last = now
                end = "\n" if self.done == self.total else ""
                sys.stderr.write(f"\r{self.desc}: {self.done}/{self.total}{end}")
                sys.stderr.flush()

    def update(self, n: int) -> None:
        """`n` more points done."""
        self.done += int(n)
        if self._bar is not None:
            self._bar.update(int(n))
        self._report()

    def close(self) -> None:
        """End the report (a tqdm bar is closed; nothing else to do)."""
        if self._bar is not None:
            self._bar.close()


def make_progress(progress, total: int, desc: str):
    """A :class:`Progress` for ``progress=`` (True or a callable ``fn(done, total)``), or
    None for None or False; anything else is refused naming ``progress``."""
    if progress is None or progress is False:
        return None
    if progress is not True and not callable(progress):
        raise InvalidTypeError(f"progress = {progress!r}: must be True, False, None or a "
                               f"callable fn(done, total)", INVALID_ARGUMENT)
    return Progress(progress, total, desc)
