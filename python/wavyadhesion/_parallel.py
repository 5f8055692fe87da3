"""Run independent chunks of work serially or on any concurrent.futures.Executor.

Minimal version (the map helper's stub; the executor helper owns this file).
"""

from __future__ import annotations


def run_chunks(func, chunks, executor=None) -> list:
    """``[func(c) for c in chunks]``, or ``list(executor.map(func, chunks))`` when an
    executor is given (results in the order of `chunks`). `func` must be a module-level
    (picklable) function for process pools and distributed executors."""
    chunks = list(chunks)
    if executor is None:
        return [func(c) for c in chunks]
    return list(executor.map(func, chunks))
