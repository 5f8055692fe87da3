"""The energy lost per gap-controlled cycle over many (alpha, mu): :func:`energy_lost`, a
vectorised :func:`~wavyadhesion.gap_path` that keeps only W* and W*/(pi alpha^2/2), and runs
on any ``concurrent.futures``-style executor (the adhesion-map figures draw its contours)."""

from __future__ import annotations

from concurrent.futures import Executor
from typing import Any, Callable, NamedTuple, Optional, Union

import numpy as np
from numpy.typing import ArrayLike

from . import _wa_f2py as _f
from ._args import (ALPHA_MAX, ALPHA_MIN, MU_MAX, MU_MIN, PATH_CAPACITY, at_index, chunk_size_for,
                    flat_f64, float_array, model_code, model_name, shaped)
from ._errors import (CAPACITY_TOO_SMALL, INVALID_ARGUMENT, OK, InvalidArgumentError,
                      message_text, raise_status)
from ._parallel import iter_chunks, make_progress
from ._results import ResultMixin

__all__ = ["EnergyLost", "energy_lost"]

# Points per task serially (Ctrl-C is seen between two tasks: 16 MD cycles take well
# under a second).
_CHUNK_ENERGY = 16

# The cheapest measured cost of one gap_path cycle (s, by model code), from which a task
# on an executor gets enough points for _parallel.chunk_seconds() of work: Westergaard
# ~0.08 ms, JKR ~0.2 ms, DW 0.3 ms (mu <~ 1) to 2 ms, MD 0.15 ms (no contact, small mu) to
# 20 ms (mu = 1000) here.
_GAP_SECONDS = {0: 8e-5, 1: 2e-4, 2: 3e-4, 3: 1.5e-4}


class EnergyLost(NamedTuple):
    """Energy lost per gap-controlled cycle (:func:`energy_lost`): arrays of the broadcast
    shape of alpha and mu (numpy scalars when both are scalars)."""
    #: W* = -oint P* dgbar* (units p* Delta per unit area); NaN where the point failed
    W_star: np.ndarray
    #: W*/(pi alpha^2/2), the fraction of the work of adhesion lost; NaN where it failed
    W_fraction: np.ndarray
    #: the library's status of each point: 0 computed, else 1 invalid argument, 2 no
    #: solution, 3 not converged, 5 numerical error (non-zero only with errors="nan")
    status: np.ndarray
    #: the library's message of each failed point, keyed by its index tuple (() for
    #: scalar inputs)
    messages: dict
    #: alpha and mu, broadcast to that shape (the coordinates of a grid)
    alpha: np.ndarray
    mu: np.ndarray
    #: the model name
    model: Optional[str] = None

    to_si = ResultMixin.to_si
    to_dataframe = ResultMixin.to_dataframe
    _field_items = ResultMixin._field_items
    __repr__ = ResultMixin.__repr__
    _columns = ("alpha", "mu", "W_star", "W_fraction", "status")
    _coordinates = ("model",)
    _repr_fields = ("model", "alpha", "mu", "W_star", "W_fraction")

    @property
    def ok(self) -> np.ndarray:
        """True where the point was computed (status 0)."""
        return np.asarray(self.status) == OK


def _energy_task(task):
    """Worker of energy_lost (module level: picklable for processes, dask, MPI): W*,
    W*/(pi alpha^2/2), the status and the message of each (alpha, mu) of one task."""
    code, alpha, mu = task
    w = np.full(alpha.size, np.nan)
    wf = np.full(alpha.size, np.nan)
    status = np.zeros(alpha.size, dtype=np.int32)
    messages = {}
    for k in range(alpha.size):
        capacity = PATH_CAPACITY
        for _ in range(8):                  # grow the event arrays (bounded)
            out = _f.fa_gap_path(capacity, code, float(alpha[k]), float(mu[k]))
            n, stat = int(out[7]), int(out[-2])
            if stat != CAPACITY_TOO_SMALL or n <= capacity:
                break
            capacity = n
        if stat == OK:
            w[k], wf[k] = out[8], out[9]
        else:
            status[k] = stat
            messages[k] = message_text(out[-1]) or message_text(_f.fa_status_text(stat))
    return w, wf, status, messages


def energy_lost(model: str, alpha: ArrayLike, mu: ArrayLike, *, errors: str = "raise",
                executor: Optional[Executor] = None, chunk_size: Optional[int] = None,
                progress: Union[bool, Callable[[int, int], Any], None] = None) -> EnergyLost:
    """Energy lost per approach-retraction cycle under gap control, W*, and its fraction of
    the work of adhesion W*/(pi alpha^2/2), at every point of the broadcast of `alpha` and
    `mu`: the ``W_star`` and ``W_fraction`` of :func:`~wavyadhesion.gap_path`, point by
    point (same facade call, same values bit for bit).

    Parameters
    ----------
    model : {"westergaard", "jkr", "dw", "md"}
        The contact model.
    alpha : array_like
        Johnson's parameter, alpha > 0.
    mu : array_like
        Transition parameter, mu >= 0; broadcast with `alpha`.
    errors : {"raise", "nan"}, optional
        "raise" (default): every alpha and mu is validated before any work (an invalid one
        raises, named with its index), then a point whose cycle fails raises (the first
        met: tasks are read in order).
        "nan": every point is computed; where one fails (or is invalid) W_star and
        W_fraction are NaN, ``status`` holds the library's status and ``messages`` its
        message; nothing is raised for a point.
    executor : concurrent.futures.Executor, optional
        Runs the tasks in parallel: a ``ThreadPoolExecutor`` (the GIL is released), a
        ``ProcessPoolExecutor``, a dask.distributed ``client.get_executor()``, an
        ``mpi4py.futures.MPIPoolExecutor``. The results are the serial ones bit for bit.
        None (default): serial, Ctrl-C between tasks.
    chunk_size : int, optional
        Points per task. Default: 16 serially; on an executor enough points for 10 ms
        (threads), 50 ms (processes, MPI) or 200 ms (dask) of the cheapest cycles. A task
        takes every n-th point (n the number of tasks), so that the cheap and the costly
        cycles (small and large mu) are spread over the tasks evenly.
    progress : bool or callable, optional
        True: a progress bar on stderr (tqdm when installed, else a plain line); a
        callable: called as ``progress(done, total)`` (points) after each chunk, in
        order (on an executor: as the tasks come back). None (default): nothing.

    Returns
    -------
    EnergyLost
        ``W_star``, ``W_fraction``, ``status``, ``messages`` (index tuple -> message),
        ``alpha``, ``mu`` broadcast to the same shape, and ``model``. ``to_si(params)``
        gives W in J/m^2.

    Raises
    ------
    InvalidArgumentError
        Unknown model, ``errors`` or ``chunk_size``; (errors="raise") alpha outside
        [1e-12, 1e12], mu outside 0 or [1e-100, 1e100], NaN or infinite values (the
        message names the argument and the index of the first bad point); an empty
        input.
    InvalidTypeError
        alpha or mu is None, complex, a string or a masked array with masked values.
    ConvergenceError
        (errors="raise") A point's cycle could not be computed; the message gives its
        index, alpha and mu.

    Examples
    --------
    >>> e = energy_lost("dw", 0.3, [1.0, 10.0])
    >>> e.W_fraction.round(4)
    array([0.1382, 0.2359])
    """
    code = model_code(model)
    if errors not in ("raise", "nan"):
        raise InvalidArgumentError(f"errors = {errors!r} is not 'raise' or 'nan'",
                                   INVALID_ARGUMENT)
    alpha_b, mu_b = np.broadcast_arrays(float_array(alpha, "alpha"), float_array(mu, "mu"))
    shape = mu_b.shape
    alpha_f, mu_f = flat_f64(alpha_b), flat_f64(mu_b)
    if mu_f.size == 0:
        raise InvalidArgumentError("alpha and mu broadcast to an empty array: give at least "
                                   "one point", INVALID_ARGUMENT)
    size = chunk_size_for(chunk_size, executor, _GAP_SECONDS[code], _CHUNK_ENERGY)
    if errors == "raise":                      # every point validated before any work
        with np.errstate(invalid="ignore"):
            bad = ~((alpha_f >= ALPHA_MIN) & (alpha_f <= ALPHA_MAX) &
                    ((mu_f == 0) | ((mu_f >= MU_MIN) & (mu_f <= MU_MAX))))
        if bad.any():
            i = int(np.flatnonzero(bad)[0])
            *_, status, message = _f.fa_gap_path(1, code, float(alpha_f[i]), float(mu_f[i]))
            raise_status(status if status != OK else INVALID_ARGUMENT, message,
                   at_index(i + 1, shape))
    n_tasks = -(-mu_f.size // size)
    picks = [np.arange(t, mu_f.size, n_tasks) for t in range(n_tasks)]   # strided
    tasks = [(code, alpha_f[idx].copy(), mu_f[idx].copy()) for idx in picks]
    w = np.full(mu_f.size, np.nan)
    wf = np.full(mu_f.size, np.nan)
    status = np.zeros(mu_f.size, dtype=np.int32)
    messages = {}
    report = make_progress(progress, mu_f.size, "energy_lost")
    try:
        _collect(picks, iter_chunks(_energy_task, tasks, executor), w, wf, status, messages,
                 errors, shape, alpha_f, mu_f, report)
    finally:
        if report is not None:
            report.close()
    return EnergyLost(shaped(w, shape), shaped(wf, shape), shaped(status, shape),
                      dict(sorted(messages.items())), shaped(alpha_f.copy(), shape),
                      shaped(mu_f.copy(), shape), model_name(code))


def _collect(picks, results, w, wf, status, messages, errors, shape, alpha_f, mu_f, report):
    """Put each task's results in place (in task order); errors="raise" raises at the
    first failed point met."""
    for idx, (tw, twf, tstatus, tmessages) in zip(picks, results):
        w[idx], wf[idx], status[idx] = tw, twf, tstatus
        for k, text in sorted(tmessages.items()):
            i = int(idx[k])
            key = tuple(int(v) for v in np.unravel_index(i, shape)) if shape else ()
            if errors == "raise":
                where = at_index(i + 1, shape)
                raise_status(int(tstatus[k]), text, f"{where + ', ' if where else ''}"
                             f"alpha = {float(alpha_f[i])!r}, mu = {float(mu_f[i])!r}")
            messages[key] = text
        if report is not None:
            report.update(idx.size)
