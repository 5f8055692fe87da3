"""The model-error map: how far the cohesive-zone models (DW, MD) are from the smooth
Lennard-Jones model (``model="lj"``) in P_fc, P_pf and W*, over a grid of (alpha, mu)
(:func:`model_error_map`).

Every cell is one LJ cycle (:func:`critical_forces` with ``model="lj"``: the three values
and their discretisation-error estimates |value at N - value at N/2|) and the cohesive
models' values (:func:`critical_forces` and :func:`energy_lost`, the existing vectorised
sweeps, on the same executor). LJ's full-contact load compared is ``P_fc_peak``, the load
at which b* (the peak tension's abscissa) first reaches 1/2: DW's and MD's b* =
a* + 0.4 (c* - a*) is 1/2 only in full contact (doc/theory.md, "Smooth adhesion"). A cell
whose LJ grid would exceed the cap ``n_max`` (the automatic grid puts 12 points on the
interaction zone; status "output capacity too small", the message naming the N needed)
is *unresolved*: its values are NaN, never extrapolated; one whose LJ cycle fails otherwise
(e.g. a trace beyond its 20000 points) is *failed*, with its message.
"""

from __future__ import annotations

from concurrent.futures import Executor, as_completed
from dataclasses import dataclass, field
from typing import Any, Callable, Dict, Optional, Sequence, Tuple, Union

import time

import numpy as np
from numpy.typing import ArrayLike

from ._args import count_in, float_array, model_code, model_name, C_INT_MAX
from ._energy import energy_lost
from ._errors import CAPACITY_TOO_SMALL, INVALID_ARGUMENT, OK, InvalidArgumentError
from ._lj import LJ_MAX_N, lj_critical_forces
from ._loadpath import MECHANISMS, critical_forces
from ._parallel import make_progress

__all__ = ["QUANTITIES", "CELL_STATUSES", "ModelErrorMap", "model_error_map"]

#: The compared quantities: full-contact load, pull-off load, energy lost per gap cycle.
QUANTITIES = ("P_fc", "P_pf", "W_star")
#: Per-cell statuses.
CELL_STATUSES = ("ok", "unresolved", "failed")

# An LJ error estimate counts as small against the model error when it is below this
# fraction of |model - LJ| ...
_RESOLVED_FRACTION = 0.1
# ... or below this fraction of |LJ| (a tenth of the 1 % contour: the cell then lies on the
# right side of every contour drawn, even where the two models agree to better than that).
_RESOLVED_RELATIVE = 1e-3
# Values at most this large (units p* or p* Delta; the smallest work of adhesion on the
# issue's range is pi 0.01^2/2 ~ 1.6e-4) count as zero: W* = 0 where a cycle has no jump
# comes out as rounding (~1e-17).
_ZERO = 1e-12
# LJ statuses that may mean "the grid cap": the automatic grid refuses the zone, or an
# explicit grid is beyond the solver's; ...
_UNRESOLVED = (INVALID_ARGUMENT, CAPACITY_TOO_SMALL)
# ... when the message is lj_problem's refusal of the grid (a trace beyond its 20000
# points has the same status, but is a failure: at alpha 0.01, mu 2.5, N = 4096)
_GRID_REFUSALS = ("above the automatic grid's cap", "n gives more than")


def _cell_status(stat: int, text: str) -> str:
    """"ok", "unresolved" (the grid refused: beyond the cap) or "failed" (anything else)."""
    if stat == OK:
        return "ok"
    refused = stat in _UNRESOLVED and any(r in text for r in _GRID_REFUSALS)
    return "unresolved" if refused else "failed"


@dataclass(frozen=True, eq=False, repr=False)
class ModelErrorMap:
    """The relative error of the cohesive-zone models against LJ over an (alpha, mu) grid
    (:func:`model_error_map`). Every array has shape (n_alpha, n_mu).

    Attributes
    ----------
    alpha, mu : numpy.ndarray of float
        The grid axes (1-D).
    models : tuple of str
        The compared models ("dw", "md").
    lj, lj_err : dict of str -> numpy.ndarray
        LJ's P_fc, P_pf, W_star and their discretisation-error estimates, by quantity
        (NaN where the cell is not "ok" for LJ). lj["P_fc"] is LJ's ``P_fc_peak`` (b*
        reaches 1/2), the value comparable with the cohesive models' P_fc; lj also holds
        "P_fc_contact" (LJ's own P_fc: every gap within eps, a* = 1/2) and "P_snap" (the
        last jump on loading), values only.
    lj_N : numpy.ndarray of int
        LJ grid points per period (0 where the cycle failed).
    lj_seconds : numpy.ndarray of float
        CPU seconds of each cell's LJ cycle (both grids; ~0 where refused at once).
    lj_status : numpy.ndarray of str
        "ok", "unresolved" (beyond the grid cap) or "failed" (another error).
    values : dict of (model, quantity) -> numpy.ndarray
        The model's value.
    rel_error : dict of (model, quantity) -> numpy.ndarray
        |model - LJ| / |LJ| (NaN where the cell's status is not "ok"). Where LJ's value is
        zero (|LJ| <= max(its error estimate, 1e-12): W* of a cycle without a jump) it is 0
        if the model's is zero too and inf if not (a difference in kind, e.g. a jump, and
        so hysteresis, in one model only).
    resolved : dict of (model, quantity) -> numpy.ndarray of bool
        True where LJ's error estimate is small against the model error:
        lj_err <= 0.1 |model - LJ| (rel_error known to 10 %), or lj_err <= 1e-3 |LJ|
        (below a tenth of the 1 % contour), or both values zero. False where the
        status is not "ok". With an explicit ``n`` a zone too fine for the grid is not
        refused: its cells show up here (a large estimate) or as "failed".
    status : dict of str -> numpy.ndarray of str
        Per model: "unresolved" where LJ is, "failed" where LJ or the model failed,
        else "ok".
    fc_mechanism : dict of str -> numpy.ndarray of str
        Per model, how its loading reaches full contact (:data:`MECHANISMS`: "gradual"
        or a jump; "" where it failed).
    messages : dict of (source, i, j) -> str
        The message of every failed or unresolved cell (source "lj" or the model name).
    """

    alpha: np.ndarray
    mu: np.ndarray
    models: Tuple[str, ...]
    lj: Dict[str, np.ndarray]
    lj_err: Dict[str, np.ndarray]
    lj_N: np.ndarray
    lj_status: np.ndarray
    lj_seconds: np.ndarray
    values: Dict[Tuple[str, str], np.ndarray]
    rel_error: Dict[Tuple[str, str], np.ndarray]
    resolved: Dict[Tuple[str, str], np.ndarray]
    status: Dict[str, np.ndarray]
    fc_mechanism: Dict[str, np.ndarray]
    messages: Dict[Tuple[str, int, int], str] = field(default_factory=dict)

    @property
    def shape(self) -> Tuple[int, int]:
        """(n_alpha, n_mu)."""
        return (self.alpha.size, self.mu.size)

    def __repr__(self) -> str:
        counts = {s: int((self.lj_status == s).sum()) for s in CELL_STATUSES}
        return (f"ModelErrorMap(shape={self.shape}, models={self.models}, "
                f"alpha=[{self.alpha.min():.3g}, {self.alpha.max():.3g}], "
                f"mu=[{self.mu.min():.3g}, {self.mu.max():.3g}], lj_status={counts})")

    def to_dataframe(self):
        """A pandas table, one row per (alpha, mu, model, quantity): columns alpha, mu,
        model, quantity, lj, lj_err, lj_N, lj_seconds, value, rel_error, resolved,
        status."""
        import pandas as pd

        a, m = np.meshgrid(self.alpha, self.mu, indexing="ij")
        frames = []
        for model in self.models:
            for q in QUANTITIES:
                frames.append(pd.DataFrame({
                    "alpha": a.ravel(), "mu": m.ravel(), "model": model, "quantity": q,
                    "lj": self.lj[q].ravel(), "lj_err": self.lj_err[q].ravel(),
                    "lj_N": self.lj_N.ravel(), "lj_seconds": self.lj_seconds.ravel(),
                    "value": self.values[model, q].ravel(),
                    "rel_error": self.rel_error[model, q].ravel(),
                    "resolved": self.resolved[model, q].ravel(),
                    "status": self.status[model].ravel()}))
        return pd.concat(frames, ignore_index=True)


def _lj_cell(task):
    """Worker (module level: picklable for processes, dask, MPI): one LJ cycle as
    (values, errors, N, status, message, CPU seconds); values P_fc_peak, P_pf, W_star,
    P_fc, P_snap, errors those of the first three."""
    alpha, mu, n, n_max = task
    t0 = time.process_time()
    r = lj_critical_forces(alpha, mu, n=n, errors="nan", n_max=n_max)
    seconds = time.process_time() - t0
    values = np.array([float(r.P_fc_peak), float(r.P_pf), float(r.W_star), float(r.P_fc),
                       float(r.P_snap)])
    errors = np.array([float(r.P_fc_peak_err), float(r.P_pf_err), float(r.W_star_err)])
    message = r.messages.get((), "")
    return values, errors, int(r.N), int(r.status), message, seconds


def _cost_order(tasks):
    """Task indices, the costliest first (so that 2 workers finish together): by the
    zone's need 24 Sigma0^2/alpha^2 ~ mu^2 alpha^(-2/3) (the automatic rule's N), cells
    beyond the cap (refused at once) last. Only the order of the work depends on it."""
    def need(task):
        alpha, mu, n, n_max = task
        if n:
            return float(n)
        want = 24.0 * (np.pi * mu) ** 2 * (alpha ** 2 / 32.0) ** (2 / 3) / alpha ** 2
        return want if want <= n_max else -1.0
    return sorted(range(len(tasks)), key=lambda k: -need(tasks[k]))


def _as_completed(func, tasks, executor):
    """(index, func(task)) for every task: serially in order (Ctrl-C between two), or
    submitted to `executor` costliest first and yielded as they complete (so progress
    moves with the work); closing early cancels what has not started."""
    if executor is None:
        for k, task in enumerate(tasks):
            yield k, func(task)
        return
    futures = {executor.submit(func, tasks[k]): k for k in _cost_order(tasks)}
    try:
        for fut in as_completed(futures):
            yield futures[fut], fut.result()
    finally:
        for fut in futures:
            fut.cancel()


def _axis(x, name: str) -> np.ndarray:
    arr = np.atleast_1d(float_array(x, name)).astype(np.float64)
    if arr.ndim != 1 or arr.size == 0:
        raise InvalidArgumentError(f"{name} must be a non-empty 1-D array (a grid axis), "
                                   f"got shape {arr.shape}", INVALID_ARGUMENT)
    if not (np.isfinite(arr).all() and (arr > 0).all()):
        raise InvalidArgumentError(f"{name} must hold finite values > 0", INVALID_ARGUMENT)
    return arr


def model_error_map(alpha: ArrayLike, mu: ArrayLike, *, models: Sequence[str] = ("dw", "md"),
                    n: Optional[int] = None, n_max: int = LJ_MAX_N,
                    executor: Optional[Executor] = None,
                    progress: Union[bool, Callable[[int, int], Any], None] = False
                    ) -> ModelErrorMap:
    """The relative error of DW's and MD's P_fc, P_pf and W* against the smooth LJ model,
    |model - LJ|/|LJ|, at every cell of the grid alpha x mu, with LJ's error estimates.

    Parameters
    ----------
    alpha : array_like
        Grid axis of Johnson's parameter (1-D, > 0).
    mu : array_like
        Grid axis of the transition parameter (1-D, > 0).
    models : sequence of str, optional
        The models compared with LJ (default "dw", "md"; any of :data:`MODELS`).
    n : int, optional
        LJ grid points per period (even, >= 8); None (default): automatic, refused (the
        cell unresolved) where the interaction zone needs more than ``n_max``.
    n_max : int, optional
        Cap of LJ's automatic grid, in [128, 16384] (default 16384, the solver's largest
        grid; the other entry points' automatic grid stops at 2048). A cycle's CPU time
        grows about like N^2: about 0.1 s at N = 256, 3 s at 1024, 50 s at 4096 (one
        core, both grids of the estimate).
    executor : concurrent.futures.Executor, optional
        Runs the LJ cells (one task each, submitted costliest first and collected as
        they complete, so that the progress moves with the work) and the cohesive
        models' sweeps (:func:`critical_forces`, :func:`energy_lost`) in
        parallel: a ``ThreadPoolExecutor``, a ``ProcessPoolExecutor``, a dask.distributed
        ``client.get_executor()``. None (default): serially.
    progress : bool or callable, optional
        True: a progress bar over the LJ cells; a callable ``fn(done, total)``.

    Returns
    -------
    ModelErrorMap
        Arrays of shape (len(alpha), len(mu)): ``rel_error[model, quantity]``,
        ``lj_err[quantity]``, ``resolved[model, quantity]``, ``status[model]`` ("ok",
        "unresolved", "failed"); ``to_dataframe()`` gives the long table.

    Raises
    ------
    InvalidArgumentError
        An axis that is not 1-D, empty, non-finite or not positive; an unknown model; a
        bad ``n``. A cell's failure is never raised: it is recorded in ``status`` and
        ``messages``.

    Examples
    --------
    >>> m = model_error_map([0.3], [3.0], models=("dw",), n=256)
    >>> m.rel_error["dw", "P_pf"].shape, str(m.status["dw"][0, 0])
    ((1, 1), 'ok')
    """
    a_ax, m_ax = _axis(alpha, "alpha"), _axis(mu, "mu")
    names = tuple(model_name(model_code(m)) for m in models)
    if n is not None:
        n = count_in(n, "n", 1, C_INT_MAX)
    n_max = count_in(n_max, "n_max", 128, LJ_MAX_N)
    shape = (a_ax.size, m_ax.size)
    A, M = np.meshgrid(a_ax, m_ax, indexing="ij")
    tasks = [(float(a), float(m), n, n_max) for a, m in zip(A.ravel(), M.ravel())]

    lj_v = np.full((A.size, 5), np.nan)
    lj_e = np.full((A.size, 3), np.nan)
    lj_N = np.zeros(A.size, dtype=np.int64)
    lj_seconds = np.zeros(A.size)
    lj_status = np.full(A.size, "ok", dtype=object)
    messages: Dict[Tuple[str, int, int], str] = {}
    report = make_progress(progress, A.size, "model_error_map (lj)")
    try:
        for k, (v, e, n_used, stat, text, sec) in _as_completed(_lj_cell, tasks, executor):
            i, j = np.unravel_index(k, shape)
            lj_seconds[k] = sec
            if stat == OK:
                lj_v[k], lj_e[k], lj_N[k] = v, e, n_used
            else:
                lj_status[k] = _cell_status(stat, text)
                messages["lj", int(i), int(j)] = text
            if report is not None:
                report.update(1)
    finally:
        if report is not None:
            report.close()
    lj_status = lj_status.reshape(shape).astype(str)
    lj = {q: lj_v[:, c].reshape(shape) for c, q in enumerate(
        QUANTITIES + ("P_fc_contact", "P_snap"))}
    lj_err = {q: lj_e[:, c].reshape(shape) for c, q in enumerate(QUANTITIES)}

    values, rel_error, resolved, status, mechanism = {}, {}, {}, {}, {}
    for model in names:
        cf = critical_forces(model, A, M, errors="nan", executor=executor)
        el = energy_lost(model, A, M, errors="nan", executor=executor)
        model_ok = (np.asarray(cf.status) == OK) & (np.asarray(el.status) == OK)
        for key, text in list(cf.messages.items()) + list(el.messages.items()):
            messages[model, int(key[0]), int(key[1])] = text
        st = np.where(lj_status == "ok", np.where(model_ok, "ok", "failed"), lj_status)
        status[model] = st.astype(str)
        codes = np.asarray(cf.fc_mechanism).reshape(shape)
        mechanism[model] = np.array([MECHANISMS[c] if 0 <= c < len(MECHANISMS) else ""
                                     for c in codes.ravel()]).reshape(shape)
        ok = status[model] == "ok"
        for q, v in zip(QUANTITIES, (cf.P_fc, cf.P_pf, el.W_star)):
            v = np.asarray(v, dtype=np.float64).reshape(shape)
            values[model, q] = v
            diff = np.abs(v - lj[q])
            with np.errstate(invalid="ignore", divide="ignore"):
                # LJ zero within its estimate (or rounding): 0 where the model is zero too
                # (no hysteresis in either), else inf (a difference in kind)
                lj_zero = np.abs(lj[q]) <= np.fmax(lj_err[q], _ZERO)
                model_zero = np.abs(v) <= np.fmax(lj_err[q], _ZERO)
                rel = np.where(lj_zero, np.where(model_zero, 0.0, np.inf),
                               diff / np.abs(lj[q]))
                rel = np.where(ok, rel, np.nan)
                res = ok & ((lj_err[q] <= _RESOLVED_FRACTION * diff)
                            | (lj_err[q] <= _RESOLVED_RELATIVE * np.abs(lj[q]))
                            | (lj_zero & model_zero))
            rel_error[model, q] = rel
            resolved[model, q] = res
    return ModelErrorMap(a_ax, m_ax, names, lj, lj_err, lj_N.reshape(shape), lj_status,
                         lj_seconds.reshape(shape), values, rel_error, resolved, status,
                         mechanism, dict(sorted(messages.items())))
