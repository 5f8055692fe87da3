"""Load-controlled loading and unloading: one load path (:func:`load_path`) and the
critical forces over many (alpha, mu) (:func:`critical_forces`)."""

from __future__ import annotations

from dataclasses import dataclass, field
from concurrent.futures import Executor
from typing import Any, Callable, Dict, List, NamedTuple, Optional, Union

import numpy as np
from numpy.typing import ArrayLike

from . import _wa_f2py as _f
from ._args import (PATH_CAPACITY, at_index, check_sweep_arguments, chunk_size_for, flat_f64,
                    float_array, grown, model_code, model_name, real_scalar, shaped)
from ._branch import EVENTS
from ._errors import INVALID_ARGUMENT, OK, InvalidArgumentError, raise_status, message_text
from ._parallel import iter_chunks, make_progress
from ._lj import (LJCriticalForces, LJLoadPath, is_lj, lj_critical_forces, lj_load_path,
                  reject_lj_inputs)
from ._results import ResultMixin

_CHUNK_SWEEP = 16

# On an executor a chunk holds at least _parallel.chunk_seconds() of work (scheduling
# overhead < 5 %), estimated with the cheapest measured cost of one critical_forces point
# (s, by model code; mu from 0.01 to 30, alpha 0.1 to 3: Westergaard/JKR ~0.03 ms,
# DW 0.29-0.61 ms, MD 1.4-3.2 ms; python/benchmarks/bench_parallel.py --costs).
_SWEEP_SECONDS = {0: 2.5e-5, 1: 2.5e-5, 2: 2.9e-4, 3: 1.4e-3}

#: How full contact is reached or contact is lost, by code (WA_MECHANISM_* in C).
MECHANISMS = ("gradual", "jump_case1", "jump_case2", "snap")

#: Load-path stages by code.
STAGES = {1: "loading", 2: "unloading"}


class PathEvent(NamedTuple):
    """One event of a load path.

    Attributes
    ----------
    stage : str
        ``"loading"`` or ``"unloading"``.
    kind : str
        ``"jump_start"``, ``"jump_end"``, ``"full_contact_reached"``,
        ``"full_contact_left"`` or ``"pull_off"`` (:data:`EVENTS`).
    a_star, c_star, P_star : float
        The state (a* = c* = 0 at the jump-in from separation).
    """

    stage: str
    kind: str
    a_star: float
    c_star: float
    P_star: float


@dataclass(frozen=True, eq=False, repr=False)
class LoadPath(ResultMixin):
    """Load-controlled loading from separation at P* = 0 to full contact, then unloading
    to pull-off, as :func:`load_path` returns it.

    Attributes
    ----------
    model : str
        The model name.
    alpha, mu : float
        The parameters.
    stage : numpy.ndarray of int
        1 loading, 2 unloading (:data:`STAGES`), one per event.
    event : numpy.ndarray of int
        Event codes (:data:`EVENTS`).
    a_star, c_star, P_star : numpy.ndarray of float
        The state at each event.
    P_fc : float
        Load at which full contact is first reached.
    P_pf : float
        Pull-off load (-inf for JKR: full contact never releases).
    fc_mechanism, pf_mechanism : str
        How full contact is reached and contact lost (:data:`MECHANISMS`: "gradual",
        "jump_case1", "jump_case2", "snap").
    loop_area : float
        Area enclosed by the loading-unloading loop in the (a*, P*) plane: the paper's
        measure of hysteresis, kept to reproduce its figures; not an energy
        (trapezoidal along the branch points, relative accuracy about 1e-4).
    jump_energy : numpy.ndarray of float
        Energy released by the jump that starts at each event, in units p* Delta per
        period: the drop of E + P0 gbar* at the jump load P0 (NaN at other events and for
        a pull-off, which separates the surfaces). See :func:`gap_path` for the energy
        lost per cycle under gap control.
    """

    model: str
    alpha: float
    mu: float
    stage: np.ndarray
    event: np.ndarray
    a_star: np.ndarray
    c_star: np.ndarray
    P_star: np.ndarray
    P_fc: float
    P_pf: float
    fc_mechanism: str
    pf_mechanism: str
    loop_area: float
    jump_energy: np.ndarray

    _columns = ("stage", "event", "a_star", "c_star", "P_star", "jump_energy")
    _coordinates = ("model", "alpha", "mu", "P_fc", "P_pf", "loop_area")
    _repr_fields = ("model", "alpha", "mu", "events_n", "P_fc", "P_pf", "fc_mechanism",
                    "pf_mechanism")

    @property
    def events_n(self) -> int:
        """The number of events (``len(path)``)."""
        return len(self)

    def __len__(self) -> int:
        return int(self.event.size)

    @property
    def mechanisms(self) -> Dict[str, str]:
        """``{"full_contact": fc_mechanism, "pull_off": pf_mechanism}``."""
        return {"full_contact": self.fc_mechanism, "pull_off": self.pf_mechanism}

    @property
    def events(self) -> List[PathEvent]:
        """The events in order, as :class:`PathEvent`."""
        return [
            PathEvent(STAGES[int(st)], EVENTS[int(ev)], float(a), float(c), float(p))
            for st, ev, a, c, p in zip(self.stage, self.event, self.a_star, self.c_star,
                                       self.P_star)
        ]


@dataclass(frozen=True, eq=False, repr=False)
class CriticalForces(ResultMixin):
    """Critical forces of :func:`critical_forces`; unpacks as ``P_fc, P_pf``.

    Attributes
    ----------
    P_fc : numpy.ndarray of float
        Load at which full contact is first reached (loading from P* = 0).
    P_pf : numpy.ndarray of float
        Pull-off load on unloading from full contact (-inf for JKR).
    fc_mechanism, pf_mechanism : numpy.ndarray of int
        Index into :data:`MECHANISMS` (0 gradual, 1 jump from case 1, 2 jump from
        case 2, 3 snap at P* = 0); -1 where a point failed with ``errors="nan"``.
    status : numpy.ndarray of int
        The library's status of each point: 0 where it succeeded, else 1 invalid
        argument, 2 no solution, 3 not converged, 5 numerical error (non-zero only with
        ``errors="nan"``: with "raise" a failure raises).
    messages : dict
        The library's message for each failed point, keyed by its index tuple (``()``
        for scalar inputs); empty when every point succeeded.
    alpha, mu : numpy.ndarray of float
        The coordinates: the inputs broadcast to the same shape.
    model : str
        The model name.
    """

    P_fc: np.ndarray
    P_pf: np.ndarray
    fc_mechanism: np.ndarray
    pf_mechanism: np.ndarray
    status: np.ndarray = None
    messages: dict = field(default_factory=dict)
    alpha: Optional[np.ndarray] = None
    mu: Optional[np.ndarray] = None
    model: Optional[str] = None

    _columns = ("alpha", "mu", "P_fc", "P_pf", "fc_mechanism", "pf_mechanism", "status")
    _coordinates = ("model",)
    _repr_fields = ("model", "alpha", "mu", "P_fc", "P_pf")

    @property
    def ok(self) -> np.ndarray:
        """True where the point's forces were computed (status 0)."""
        return np.asarray(self.status) == OK

    def __iter__(self):
        yield self.P_fc
        yield self.P_pf

    def __len__(self) -> int:
        return 2

    def __getitem__(self, i):
        return (self.P_fc, self.P_pf)[i]


def load_path(model: str, alpha: float, mu: float, *, n: Optional[int] = None,
              profile: Optional[ArrayLike] = None
              ) -> Union[LoadPath, LJLoadPath]:
    """Load-controlled loading and unloading along the branch (doc/theory.md, "Load paths and critical forces").

    Loading starts from separation at P* = 0 (jump-in), rises along stable pieces and
    jumps at every maximum of P* until full contact (load P_fc); unloading leaves full
    contact, falls along stable pieces and jumps at every minimum until contact is lost
    (load P_pf).

    Parameters
    ----------
    model : {"westergaard", "jkr", "dw", "md", "lj"}
        The contact model ("lj": an :class:`LJLoadPath`, with P_fc, P_pf, P_snap and
        their error estimates P_fc_err, P_pf_err, P_snap_err).
    alpha : float
        Johnson's parameter, alpha > 0.
    mu : float
        Transition parameter, mu >= 0 (lj: mu > 0).
    n : int, optional
        ``model="lj"`` only: grid points per period (even, >= 8; default automatic, 12
        points on the interaction zone).
    profile : array_like, optional
        ``model="lj"`` only: the surface as samples of one period, heights over Delta at
        x* = j/M, j = 0..M-1 (their mean does not matter); default the sinusoid
        1 - cos(2 pi x*).

    Returns
    -------
    LoadPath
        Arrays ``stage, event, a_star, c_star, P_star`` (one element per event), the
        floats ``P_fc, P_pf, loop_area``, the array ``jump_energy`` (energy released
        by the jump starting at each event), the mechanism names ``fc_mechanism,
        pf_mechanism`` (also ``mechanisms``) and the list ``events``.

    Raises
    ------
    InvalidArgumentError
        Unknown model or an argument outside its range.
    ResolutionError
        (model="lj") The grid refuses `n` (beyond its cap) or the automatic grid's zone
        needs more than 2048 points; the message names the N or the cap.
    ConvergenceError
        The continuation or a landing-point solve failed.

    Examples
    --------
    >>> path = load_path("dw", 0.3, 5.0)
    >>> [(e.stage, e.kind) for e in path.events][:4]  # doctest: +NORMALIZE_WHITESPACE
    [('loading', 'jump_start'), ('loading', 'jump_end'), ('loading', 'jump_start'),
     ('loading', 'full_contact_reached')]
    >>> path.mechanisms
    {'full_contact': 'jump_case1', 'pull_off': 'jump_case2'}
    """
    if is_lj(model):
        return lj_load_path(alpha, mu, n, profile)
    reject_lj_inputs(n, profile)
    code = model_code(model)
    alpha = real_scalar(alpha, "alpha")
    mu = real_scalar(mu, "mu")
    out = grown(_f.fa_load_path, PATH_CAPACITY, 5, code, alpha, mu)
    stage, ev, a, c, p, n, p_fc, p_pf, fc_m, pf_m, area, jump_e, _, _ = out
    n = int(n)
    return LoadPath(model_name(code), alpha, mu, stage[:n].copy(), ev[:n].copy(),
                    a[:n].copy(), c[:n].copy(), p[:n].copy(), float(p_fc), float(p_pf),
                    MECHANISMS[int(fc_m)], MECHANISMS[int(pf_m)], float(area),
                    jump_e[:n].copy())


def critical_forces(model: str, alpha: ArrayLike, mu: ArrayLike, *, errors: str = "raise",
                    executor: Optional[Executor] = None, chunk_size: Optional[int] = None,
                    progress: Union[bool, Callable[[int, int], Any], None] = None,
                    n: Optional[int] = None, profile: Optional[ArrayLike] = None,
                    n_max: Optional[int] = None) -> Union[CriticalForces, LJCriticalForces]:
    """Critical forces P_fc* (full contact reached on loading) and P_pf* (pull-off on
    unloading), vectorised over mu and broadcast with alpha.

    The Fortran ``critical_sweep`` (GIL released) traces the branch and follows the load
    path for each mu, in calls of at most 16 mu that share an alpha; Ctrl-C
    (KeyboardInterrupt) takes effect between two calls. A point that fails never stops
    the others.

    Parameters
    ----------
    model : {"westergaard", "jkr", "dw", "md", "lj"}
        The contact model.
    alpha : array_like
        Johnson's parameter, alpha > 0.
    mu : array_like
        Transition parameter, mu >= 0 (lj: mu > 0); broadcast with `alpha`.
    errors : {"raise", "nan"}, optional
        "raise" (default): raise at the first point that fails (an invalid alpha or mu
        before any work). "nan": compute every point; where one fails (or is invalid),
        P_fc and P_pf are NaN, the mechanisms -1, and ``status`` and ``messages`` say
        why; nothing is raised for a point.
    executor : concurrent.futures.Executor, optional
        Runs the chunks in parallel: a ``ThreadPoolExecutor`` (the GIL is released), a
        ``ProcessPoolExecutor``, a dask.distributed ``client.get_executor()``, an
        ``mpi4py.futures.MPIPoolExecutor``. The results are the serial ones bit for bit.
        None (default): serial, Ctrl-C between chunks.
    chunk_size : int, optional
        Points per chunk (a chunk is one task; each alpha in it one facade call).
        Default: 16 serially; on an executor enough points for 10 ms (threads), 50 ms
        (processes, MPI) or 200 ms (dask) of work, so that scheduling costs < 5 %.
    progress : bool or callable, optional
        True: a progress bar on stderr (tqdm when installed, else a plain line); a
        callable: called as ``progress(done, total)`` (points) after each chunk, in
        order (on an executor: as the chunks come back). None (default): nothing.
    n, profile : optional
        ``model="lj"`` only: the grid and the surface samples, as in load_path.
        With ``model="lj"`` every point is one task (one cycle: about a second at the
        automatic grid), serially or on `executor`, and `progress` counts the points;
        chunk_size is not used. Serially Ctrl-C stops the sweep within 0.1 s (the cycle
        under way runs on to its end in a helper thread, its result dropped). The result
        is an :class:`LJCriticalForces`: ``P_fc, P_pf`` with ``P_fc_err, P_pf_err``
        (|value at N - value at N/2|), the snap load and W* with theirs, and ``N``.
    n_max : int, optional
        ``model="lj"`` only: the cap of the automatic grid, in [128, 16384] (None: the
        library's, 2048; not used where `n` is given). A point whose interaction zone
        needs more is refused: :class:`ResolutionError` naming the N it needs (with
        errors="nan": status 4 and that message).

    Returns
    -------
    CriticalForces
        ``P_fc``, ``P_pf`` (unpack as ``P_fc, P_pf = critical_forces(...)``), the
        mechanism codes ``fc_mechanism``, ``pf_mechanism`` and the library status
        ``status`` (0 where the point succeeded), arrays of the broadcast shape (numpy
        scalars when alpha and mu are scalars); ``messages`` maps the index of each failed
        point to the library's message; ``alpha``, ``mu`` broadcast to that shape and
        ``model``. JKR: P_pf = -inf.

    Raises
    ------
    InvalidArgumentError
        Unknown model; (errors="raise") alpha outside [1e-12, 1e12], mu outside 0 or
        [1e-100, 1e100], NaN or infinite values (the
        message gives the index of the first bad point).
    InvalidTypeError
        alpha or mu is None, complex, a string or a masked array with masked values.
    ResolutionError
        (model="lj", errors="raise") The LJ grid refuses a point: `n` beyond the grid's
        cap, or the automatic grid beyond its cap (2048 or `n_max`); the message names
        the N needed or the cap. Also an InvalidArgumentError.
    ConvergenceError
        (errors="raise") A point's branch or load path could not be computed; the
        message gives its index, alpha and mu.

    Examples
    --------
    >>> P_fc, P_pf = critical_forces("dw", 0.3, [0.1, 1.0, 5.0])
    >>> P_fc.round(6), P_pf.round(6)
    (array([0.977827, 0.778274, 0.387507]), array([-0.022173, -0.088714, -0.119953]))
    """
    if is_lj(model):
        chunk_size_for(chunk_size, None, 1.0, 1)        # checked; one task per point
        return lj_critical_forces(alpha, mu, n, profile, errors, executor=executor,
                                  progress=progress, n_max=n_max)
    reject_lj_inputs(n, profile, n_max)
    code = model_code(model)
    if errors not in ("raise", "nan"):
        raise InvalidArgumentError(f"errors = {errors!r} is not 'raise' or 'nan'", 1)
    alpha_b, mu_b = np.broadcast_arrays(float_array(alpha, "alpha"), float_array(mu, "mu"))
    shape = mu_b.shape
    alpha_f, mu_f = flat_f64(alpha_b), flat_f64(mu_b)
    out = (np.full(mu_f.size, np.nan), np.full(mu_f.size, np.nan),
           np.full(mu_f.size, -1, dtype=np.int32), np.full(mu_f.size, -1, dtype=np.int32),
           np.zeros(mu_f.size, dtype=np.int32))
    messages = {}
    size = chunk_size_for(chunk_size, executor, _SWEEP_SECONDS[code], _CHUNK_SWEEP)
    if mu_f.size == 1:
        report = make_progress(progress, 1, "critical_forces")
        _sweep_chunk(code, float(alpha_f[0]), mu_f, np.zeros(1, dtype=np.intp), out,
                     messages, errors, shape)
        if report is not None:
            report.update(1)
            report.close()
    elif mu_f.size:
        values, inverse = np.unique(alpha_f, return_inverse=True)
        if errors == "raise" and (values.size > 1 or mu_f.size > size):
            check_sweep_arguments(code, alpha_f, mu_f, shape)   # all before any work
        chunks = _sweep_pieces(values, inverse.reshape(-1), size)
        tasks = [(code, [(value, mu_f[idx]) for value, idx in chunk]) for chunk in chunks]
        report = make_progress(progress, mu_f.size, "critical_forces")
        try:
            # in order; serially Ctrl-C is seen between chunks
            for chunk, results in zip(chunks, iter_chunks(_sweep_task, tasks, executor)):
                for (value, idx), result in zip(chunk, results):
                    _sweep_chunk(code, value, mu_f, idx, out, messages, errors, shape,
                                 result)
                if report is not None:
                    report.update(sum(idx.size for _, idx in chunk))
        finally:
            if report is not None:
                report.close()
    p_fc, p_pf, fc_m, pf_m, status = out
    return CriticalForces(shaped(p_fc, shape), shaped(p_pf, shape), shaped(fc_m, shape),
                          shaped(pf_m, shape), shaped(status, shape), messages,
                          shaped(alpha_f.copy(), shape), shaped(mu_f.copy(), shape),
                          model_name(code))


def _sweep_pieces(values, inverse, size):
    """The points grouped by alpha (values[inverse]) and cut into chunks of at most
    `size`: each chunk a list of (alpha, indices) pieces, one facade call each."""
    order = np.argsort(inverse, kind="stable")
    ends = np.cumsum(np.bincount(inverse, minlength=values.size))
    chunks, chunk, room, start = [], [], size, 0
    for k, end in enumerate(ends):
        while start < end:
            take = min(room, int(end) - start)
            chunk.append((float(values[k]), order[start:start + take]))
            start, room = start + take, room - take
            if room == 0:
                chunks.append(chunk)
                chunk, room = [], size
    if chunk:
        chunks.append(chunk)
    return chunks


def _sweep_task(task):
    """Worker of critical_forces (module-level: picklable for processes, dask, MPI): the
    facade's raw output for each (alpha, mu array) piece of one chunk."""
    code, pieces = task
    return [_f.fa_critical_sweep(code, alpha, np.ascontiguousarray(mu))
            for alpha, mu in pieces]


def _sweep_chunk(code, alpha, mu_f, idx, out, messages, errors, shape, result=None):
    """One facade call for the points `idx` (one alpha), or its `result` computed by
    _sweep_task; failed points keep NaN, -1 and their status; errors="raise" raises at
    the first one."""
    p_fc, p_pf, fc_m, pf_m, status_out = out
    fc, pf, fm, pm, rs, ifail, status, message = result if result is not None else (
        _f.fa_critical_sweep(code, alpha, np.ascontiguousarray(mu_f[idx])))
    if status == INVALID_ARGUMENT and (rs == INVALID_ARGUMENT).all():
        # an argument was refused and nothing computed
        if errors == "raise":
            where = idx[ifail - 1] if ifail > 0 else idx[0]
            raise_status(status, message, at_index(int(where) + 1, shape))
        if idx.size > 1:                                 # isolate the bad points
            for i in idx:
                _sweep_chunk(code, alpha, mu_f, np.array([i]), out, messages, errors, shape)
            return
    p_fc[idx], p_pf[idx], fc_m[idx], pf_m[idx], status_out[idx] = fc, pf, fm, pm, rs
    if status == OK:
        return
    for j in np.flatnonzero(rs != OK):
        i = int(idx[j])
        where = at_index(i + 1, shape)
        # the sweep's message is about its first failing row: ask this row's own
        # (as load_path gives it; failures are rare, so the extra call costs little)
        text = message_text(_f.fa_load_path(PATH_CAPACITY, code, alpha, float(mu_f[i]))[-1])
        text = text or message_text(_f.fa_status_text(int(rs[j])))
        key = tuple(int(v) for v in np.unravel_index(i, shape)) if shape else ()
        messages[key] = text
        if errors == "raise":
            raise_status(int(rs[j]), text, f"{where + ', ' if where else ''}alpha = {alpha!r}, "
                   f"mu = {float(mu_f[i])!r}")


