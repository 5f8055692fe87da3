"""The smooth-adhesion model (``model="lj"``): the self-consistent Lennard-Jones 3-9 law
solved by boundary elements (doc/theory.md, "Smooth adhesion").

Parameter mapping: the same work of adhesion as DW and MD, Delta gamma = pi alpha^2/2 (units
p* Delta), and the range eps = Delta gamma/sigma0 (the MD opening h0): eps/Delta = 2 Dcod =
(4 alpha^4)^(1/3)/mu, so mu keeps its meaning; LJ's peak tension is then
16/(9 sqrt 3) sigma0 ~ 1.0264 sigma0. The grid has ``n`` points per period (None: automatic,
12 points on the interaction zone); the surface is the sinusoid 1 - cos(2 pi x*) or, with
``profile=``, the samples of one period (heights over Delta at x* = j/M, j = 0..M-1; their
mean does not matter: gbar* is the mean gap). Every critical value carries its
discretisation-error estimate ``*_err`` = |value at N - value at N/2|.

:func:`trace_branch`, :func:`load_path`, :func:`gap_path` and :func:`critical_forces` call
the functions here for ``model="lj"``.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Dict, List, NamedTuple, Optional

import numpy as np

from . import _wa_f2py as _f
from ._args import C_INT_MAX, count_in, float_array, grown, real_scalar, shaped
from ._errors import INVALID_ARGUMENT, OK, InvalidArgumentError, message_text, raise_status
from ._parallel import call_interruptibly, iter_chunks, make_progress
from ._results import ResultMixin, TupleCompat

__all__ = ["LJ_EVENTS", "LJ_PATH_EVENTS", "LJBranch", "LJBranchEvent", "LJLoadPath",
           "LJGapPath", "LJCriticalForces", "is_lj", "lj_trace_branch", "lj_load_path",
           "lj_gap_path", "lj_critical_forces", "lj_profile", "lj_inputs", "reject_lj_inputs"]

#: Event codes of the points of an LJ branch.
LJ_EVENTS = {0: "none", 1: "fold", 14: "gap_fold", 5: "full_contact", 15: "contact",
             8: "branch_end"}
#: Event codes of an LJ path (those of the other models' paths).
LJ_PATH_EVENTS = {3: "jump_start", 4: "jump_end", 5: "full_contact_reached",
                  6: "full_contact_left", 7: "pull_off"}

# Points asked for in a first trace (a trace at the automatic grid has a few hundred)
_TRACE_CAPACITY = 2048
# A path holds at most 64 events (wa_bem_path)
_PATH_CAPACITY = 64
# The grid's cap: at most 16384 points per period (lj_problem; model_error_map's n_max)
LJ_MAX_N = 16384
_GRID_CAP = LJ_MAX_N


def is_lj(model) -> bool:
    """True for the model name "lj" (any case)."""
    return isinstance(model, str) and model.lower() == "lj"


def reject_lj_inputs(n, profile, n_max=None) -> None:
    """InvalidArgumentError when n, profile or n_max is given to a model other than "lj"."""
    if n is not None or profile is not None:
        raise InvalidArgumentError("n and profile are only for model='lj' (the grid and "
                                   "the surface of the smooth model)", INVALID_ARGUMENT)
    if n_max is not None:
        raise InvalidArgumentError("n_max is only for model='lj' (the cap of the smooth "
                                   "model's automatic grid)", INVALID_ARGUMENT)


def lj_inputs(n, profile):
    """(n, use_profile, samples) for the facade: n None -> 0 (automatic), profile None ->
    the sinusoid (a dummy sample), else a 1-D array of finite heights over Delta."""
    n = 0 if n is None else count_in(n, "n", 1, C_INT_MAX)
    if profile is None:
        return n, 0, np.zeros(1)
    samples = np.ascontiguousarray(float_array(profile, "profile"), dtype=np.float64)
    if samples.ndim != 1:
        raise InvalidArgumentError(f"profile must be a 1-D array of samples of one period, "
                                   f"got shape {samples.shape}", INVALID_ARGUMENT)
    if samples.size < 4:
        raise InvalidArgumentError("profile must hold at least 4 samples of one period",
                                   INVALID_ARGUMENT)
    return n, 1, samples


class LJBranchEvent(NamedTuple):
    """A point of an LJ branch that carries an event (:data:`LJ_EVENTS`)."""

    index: int
    kind: str
    a_star: float
    P_star: float
    gbar: float


@dataclass(frozen=True, eq=False, repr=False)
class LJBranch(ResultMixin):
    """The equilibrium curve of the smooth (LJ) model, from far apart to full contact
    (:func:`trace_branch` with ``model="lj"``), in the order of the trace.

    Attributes
    ----------
    model : str
        "lj".
    alpha, mu : float
        The parameters.
    N : int
        Grid points per period.
    a_star : numpy.ndarray of float
        Contact half-width: half the measure of {h <= eps}.
    b_star : numpy.ndarray of float
        Half the measure of {h <= 3^(1/6) eps}: the position of the peak tension (the
        abscissa the paper's Fig. 5 compares with DW's and MD's a* + 0.4 (c* - a*)).
    P_star, gbar : numpy.ndarray of float
        Load and mean gap over Delta.
    h_min, h_max : numpy.ndarray of float
        Smallest and largest gap over Delta.
    stable, stable_gap : numpy.ndarray of bool
        Stable under load control; under gap control.
    event : numpy.ndarray of int
        :data:`LJ_EVENTS` (0 for ordinary points).
    extremum : numpy.ndarray of int
        +1/-1 maximum/minimum of P* along the curve, +2/-2 of gbar*, else 0.
    P_fc, P_pf, W_star : float
        The critical loads and the energy lost per gap cycle of the paths on this curve
        (NaN where a path failed).
    P_fc_err, P_pf_err, W_star_err : float
        Their discretisation-error estimates |value at N - value at N/2| (NaN where the
        cycle at N/2 failed); the points of the curve have none of their own.
    """

    model: str
    alpha: float
    mu: float
    N: int
    a_star: np.ndarray
    b_star: np.ndarray
    P_star: np.ndarray
    gbar: np.ndarray
    h_min: np.ndarray
    h_max: np.ndarray
    stable: np.ndarray
    stable_gap: np.ndarray
    event: np.ndarray
    extremum: np.ndarray
    P_fc: float = float("nan")
    P_fc_err: float = float("nan")
    P_pf: float = float("nan")
    P_pf_err: float = float("nan")
    W_star: float = float("nan")
    W_star_err: float = float("nan")

    _columns = ("a_star", "b_star", "P_star", "gbar", "h_min", "h_max", "stable",
                "stable_gap", "event", "extremum")
    _coordinates = ("model", "alpha", "mu", "N", "P_fc", "P_fc_err", "P_pf", "P_pf_err",
                    "W_star", "W_star_err")
    _repr_fields = ("model", "alpha", "mu", "N", "points", "folds_P")

    @property
    def points(self) -> int:
        """The number of points (``len(branch)``)."""
        return len(self)

    def __len__(self) -> int:
        return int(self.P_star.size)

    @property
    def events(self) -> List[LJBranchEvent]:
        """Every point with an event, in order."""
        return [LJBranchEvent(int(i), LJ_EVENTS[int(self.event[i])], float(self.a_star[i]),
                              float(self.P_star[i]), float(self.gbar[i]))
                for i in np.flatnonzero(self.event)]

    @property
    def folds_P(self) -> np.ndarray:
        """P* at the folds of P*, in order."""
        return self.P_star[np.abs(self.extremum) == 1]


@dataclass(frozen=True, eq=False, repr=False)
class _LJPathBase(ResultMixin):
    model: str
    alpha: float
    mu: float
    N: int
    stage: np.ndarray
    event: np.ndarray
    a_star: np.ndarray
    P_star: np.ndarray
    gbar: np.ndarray

    _columns = ("stage", "event", "a_star", "P_star", "gbar")

    @property
    def events_n(self) -> int:
        """The number of events."""
        return len(self)

    def __len__(self) -> int:
        return int(self.stage.size)


@dataclass(frozen=True, eq=False, repr=False)
class LJLoadPath(_LJPathBase):
    """Load-controlled loading (stage 1) and unloading (stage 2) of the LJ model
    (:func:`load_path` with ``model="lj"``): one element per event
    (:data:`LJ_PATH_EVENTS`), and the critical loads with their error estimates.

    Attributes
    ----------
    stage, event, a_star, P_star, gbar : numpy.ndarray
        The events in order.
    P_fc, P_pf : float
        Load at which full contact is first reached; pull-off load.
    P_snap : float
        Load of the last jump on loading (the snap towards full contact; P_fc where
        loading has no jump).
    P_fc_peak : float
        Load at which b* (the abscissa of the peak tension, h = 3^(1/6) eps) first
        reaches 1/2 on loading (a jump's load where a jump reaches it): the full-contact
        load comparable with DW's and MD's P_fc (their b* = 1/2 only in full contact).
    P_fc_err, P_pf_err, P_snap_err, P_fc_peak_err : float
        |value at N - value at N/2| (0 with ``estimate=False``).
    fc_by_jump, pf_by_jump, fc_peak_by_jump : bool
        Full contact reached, contact lost, b* = 1/2 reached, by a jump.
    N : int
        Grid points per period.
    """

    P_fc: float = 0.0
    P_pf: float = 0.0
    P_snap: float = 0.0
    P_fc_err: float = 0.0
    P_pf_err: float = 0.0
    P_snap_err: float = 0.0
    fc_by_jump: bool = False
    pf_by_jump: bool = False
    P_fc_peak: float = 0.0
    P_fc_peak_err: float = 0.0
    fc_peak_by_jump: bool = False

    _coordinates = ("model", "alpha", "mu", "N", "P_fc", "P_pf", "P_snap", "P_fc_err",
                    "P_pf_err", "P_snap_err", "P_fc_peak", "P_fc_peak_err")
    _repr_fields = ("model", "alpha", "mu", "N", "events_n", "P_fc", "P_fc_err", "P_pf",
                    "P_pf_err")


@dataclass(frozen=True, eq=False, repr=False)
class LJGapPath(_LJPathBase):
    """Gap-controlled approach (stage 1) and retraction (stage 2) of the LJ model
    (:func:`gap_path` with ``model="lj"``), with the energy lost per cycle.

    Attributes
    ----------
    stage, event, a_star, P_star, gbar : numpy.ndarray
        The events in order (jumps keep gbar*).
    W_star : float
        Energy lost per cycle, -oint P* dgbar* (units p* Delta).
    W_fraction : float
        W*/(pi alpha^2/2).
    W_star_err : float
        |W* at N - W* at N/2| (0 with ``estimate=False``).
    N : int
        Grid points per period.
    """

    W_star: float = 0.0
    W_fraction: float = 0.0
    W_star_err: float = 0.0

    _coordinates = ("model", "alpha", "mu", "N", "W_star", "W_fraction", "W_star_err")
    _repr_fields = ("model", "alpha", "mu", "N", "events_n", "W_star", "W_star_err")


@dataclass(frozen=True, eq=False, repr=False)
class LJCriticalForces(TupleCompat, ResultMixin):
    """Critical values of the LJ model over broadcast (alpha, mu)
    (:func:`critical_forces` with ``model="lj"``); unpacks as ``P_fc, P_pf``.

    Attributes
    ----------
    P_fc, P_pf, P_snap, W_star : numpy.ndarray of float
        Full-contact load, pull-off load, snap load, energy lost per gap cycle.
    P_fc_err, P_pf_err, P_snap_err, W_star_err : numpy.ndarray of float
        Their discretisation-error estimates |value at N - value at N/2|.
    P_fc_peak, P_fc_peak_err : numpy.ndarray of float
        Load at which b* (the abscissa of the peak tension) first reaches 1/2 on loading
        (a jump's load where a jump reaches it; :class:`LJLoadPath`), the full-contact
        load comparable with DW's and MD's P_fc, and its error estimate.
    N : numpy.ndarray of int
        Grid points per period of each point.
    status, messages : as :class:`CriticalForces` (``errors="nan"``).
    alpha, mu : numpy.ndarray of float
        The inputs broadcast to the same shape.
    """

    P_fc: np.ndarray
    P_pf: np.ndarray
    P_fc_err: np.ndarray
    P_pf_err: np.ndarray
    P_snap: np.ndarray
    P_snap_err: np.ndarray
    W_star: np.ndarray
    W_star_err: np.ndarray
    N: np.ndarray
    status: np.ndarray
    messages: Dict = field(default_factory=dict)
    alpha: Optional[np.ndarray] = None
    mu: Optional[np.ndarray] = None
    model: str = "lj"
    P_fc_peak: Optional[np.ndarray] = None
    P_fc_peak_err: Optional[np.ndarray] = None

    _columns = ("alpha", "mu", "P_fc", "P_pf", "P_fc_err", "P_pf_err", "P_snap",
                "P_snap_err", "W_star", "W_star_err", "N", "status", "P_fc_peak",
                "P_fc_peak_err")
    _coordinates = ("model",)
    _repr_fields = ("model", "alpha", "mu", "P_fc", "P_fc_err", "P_pf", "P_pf_err")
    _tuple_fields = ("P_fc", "P_pf")

    @property
    def ok(self) -> np.ndarray:
        """True where the point's values were computed (status 0)."""
        return np.asarray(self.status) == OK


def lj_trace_branch(alpha, mu, n=None, profile=None) -> LJBranch:
    """The LJ equilibrium curve (see :func:`trace_branch`)."""
    alpha = real_scalar(alpha, "alpha")
    mu = real_scalar(mu, "mu")
    n, use, samples = lj_inputs(n, profile)
    out = grown(_f.fa_lj_trace, _TRACE_CAPACITY, 10, alpha, mu, n, use, samples)
    p, g, a, b, hmin, hmax, sl, sg, ev, ex, count, n_period, v, _, _ = out
    k = int(count)
    return LJBranch("lj", alpha, mu, int(n_period), a[:k].copy(), b[:k].copy(), p[:k].copy(),
                    g[:k].copy(), hmin[:k].copy(), hmax[:k].copy(), sl[:k].astype(bool),
                    sg[:k].astype(bool), ev[:k].copy(), ex[:k].copy(), *map(float, v))


def _cycle(alpha, mu, n, use, samples, estimate, n_max=0):
    """The facade's cycle: (load events, gap events, values, N, status, message); n_max
    the automatic grid's cap (0: the library's)."""
    out = _f.fa_lj_cycle(_PATH_CAPACITY, alpha, mu, n, use, samples, int(bool(estimate)),
                         n_max)
    (ls, le, la, lp, lg, nl, gs, ge, ga, gp, gg, ng, values, n_period, status,
     message) = out
    nl, ng = int(nl), int(ng)
    load = (ls[:nl].copy(), le[:nl].copy(), la[:nl].copy(), lp[:nl].copy(), lg[:nl].copy())
    gap = (gs[:ng].copy(), ge[:ng].copy(), ga[:ng].copy(), gp[:ng].copy(), gg[:ng].copy())
    return load, gap, values.copy(), int(n_period), int(status), message


def _scalar_cycle(alpha, mu, n, profile, estimate):
    """(alpha, mu, load events, gap events, values, N) of one point; raises on failure."""
    alpha = real_scalar(alpha, "alpha")
    mu = real_scalar(mu, "mu")
    n, use, samples = lj_inputs(n, profile)
    load, gap, v, n_period, status, message = _cycle(alpha, mu, n, use, samples, estimate)
    if status != OK:
        raise_status(status, message)
    return alpha, mu, load, gap, v, n_period


def lj_load_path(alpha, mu, n=None, profile=None, estimate=True) -> LJLoadPath:
    """The LJ load-controlled path (see :func:`load_path`)."""
    alpha, mu, load, _, v, n_period = _scalar_cycle(alpha, mu, n, profile, estimate)
    return LJLoadPath("lj", alpha, mu, n_period, *load, P_fc=float(v[0]), P_pf=float(v[1]),
                      P_snap=float(v[2]), P_fc_err=float(v[5]), P_pf_err=float(v[6]),
                      P_snap_err=float(v[7]), fc_by_jump=bool(v[9]), pf_by_jump=bool(v[10]),
                      P_fc_peak=float(v[11]), P_fc_peak_err=float(v[12]),
                      fc_peak_by_jump=bool(v[13]))


def lj_gap_path(alpha, mu, n=None, profile=None, estimate=True) -> LJGapPath:
    """The LJ gap-controlled path (see :func:`gap_path`)."""
    alpha, mu, _, gap, v, n_period = _scalar_cycle(alpha, mu, n, profile, estimate)
    return LJGapPath("lj", alpha, mu, n_period, *gap, W_star=float(v[3]),
                     W_fraction=float(v[4]), W_star_err=float(v[8]))


def _cell(task):
    """Worker of lj_critical_forces (module level: picklable for processes, dask, MPI): one
    cycle's (values, N, status, message) from the facade."""
    alpha, mu, n, use, samples, estimate, n_max = task
    _, _, values, n_period, status, message = _cycle(alpha, mu, n, use, samples, estimate,
                                                     n_max)
    return values, n_period, status, message


def _cell_interruptibly(task):
    """_cell in a helper thread: serially, Ctrl-C stops the sweep within 0.1 s even while
    one cycle (a second or more at the automatic grid) runs."""
    return call_interruptibly(_cell, task)


def lj_critical_forces(alpha, mu, n=None, profile=None, errors="raise", estimate=True,
                       executor=None, progress=None, n_max=None) -> LJCriticalForces:
    """The LJ critical values over broadcast (alpha, mu) (see :func:`critical_forces`): one
    task per point, serially or on `executor`, in the order of the points (the results
    are the serial ones bit for bit); `progress` reports the points done. ``n_max``: the
    automatic grid's cap, in [128, 16384] (None: the library's, 2048); a point whose zone
    needs more is refused (status 4, the message naming the N it needs: ResolutionError,
    or that status and message with errors="nan")."""
    if errors not in ("raise", "nan"):
        raise InvalidArgumentError(f"errors = {errors!r} is not one of 'raise', 'nan'",
                                   INVALID_ARGUMENT)
    a_arr, m_arr = np.broadcast_arrays(float_array(alpha, "alpha"), float_array(mu, "mu"))
    shape = a_arr.shape
    n, use, samples = lj_inputs(n, profile)
    n_max = 0 if n_max is None else count_in(n_max, "n_max", 128, _GRID_CAP)
    a_f, m_f = a_arr.reshape(-1), m_arr.reshape(-1)
    size = a_f.size
    vals = np.full((size, 11), np.nan)
    grid = np.zeros(size, dtype=np.int32)
    stat = np.zeros(size, dtype=np.int32)
    messages = {}
    tasks = [(float(a_f[k]), float(m_f[k]), n, use, samples, estimate, n_max)
             for k in range(size)]
    report = make_progress(progress, size, "critical_forces (lj)")
    cells = iter_chunks(_cell_interruptibly if executor is None else _cell, tasks, executor)
    try:
        for k, (v, n_period, status, message) in enumerate(cells):
            if report is not None:
                report.update(1)
            if status != OK:
                if errors == "raise":
                    raise_status(status, message)
                key = tuple(int(i) for i in np.unravel_index(k, shape)) if shape else ()
                messages[key] = message_text(message)
                stat[k] = status
                continue
            vals[k] = np.concatenate([v[:9], v[11:13]])
            grid[k] = n_period
    finally:
        cells.close()                    # on an executor: cancels what has not started
        if report is not None:
            report.close()
    col = {name: shaped(vals[:, i], shape) for i, name in enumerate(
        ("P_fc", "P_pf", "P_snap", "W_star", "W_fraction", "P_fc_err", "P_pf_err",
         "P_snap_err", "W_star_err", "P_fc_peak", "P_fc_peak_err"))}
    return LJCriticalForces(col["P_fc"], col["P_pf"], col["P_fc_err"], col["P_pf_err"],
                            col["P_snap"], col["P_snap_err"], col["W_star"],
                            col["W_star_err"], shaped(grid, shape), shaped(stat, shape),
                            messages, shaped(a_f.copy(), shape), shaped(m_f.copy(), shape),
                            P_fc_peak=col["P_fc_peak"], P_fc_peak_err=col["P_fc_peak_err"])


def lj_profile(alpha, mu, a_star, n=None, profile=None):
    """(x, traction, gap, N, (a*, b*, P*, gbar*)) of the traced LJ state with a* nearest
    `a_star` (among the load-stable ones when there are any), at the N grid nodes from
    x* = -1/2 (see :func:`profile`)."""
    alpha = real_scalar(alpha, "alpha")
    mu = real_scalar(mu, "mu")
    a_star = real_scalar(a_star, "a_star")
    n, use, samples = lj_inputs(n, profile)
    # N points: n itself when it is a valid grid (at most the cap 16384), else at most
    # 2048 (the automatic grid's cap); a bad n is refused by the library, never allocated
    out = grown(_f.fa_lj_profile, n if 2048 < n <= _GRID_CAP else 2048, 3, alpha, mu, n,
                use, samples, a_star)
    x, t, h, n_period, state, _, _ = out
    k = int(n_period)
    return x[:k].copy(), t[:k].copy(), h[:k].copy(), k, [float(v) for v in state]
