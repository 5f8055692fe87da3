"""Python layer over the f2py facade ``wavyadhesion._wa_f2py``.

Broadcasting, model names, result types and exceptions live here; every number is
computed by the Fortran library, one facade call per numpy array (the GIL is released
during the call, so threads run concurrently).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import NamedTuple, Optional

import numpy as np

from . import _wa_f2py as _f
from ._parallel import iter_chunks, points_per_chunk

__all__ = [
    "MODELS",
    "Equilibrium",
    "State",
    "Scales",
    "Params",
    "WavyAdhesionError",
    "InvalidArgumentError",
    "InvalidTypeError",
    "ConvergenceError",
    "NoSolutionError",
    "westergaard_load",
    "jkr_load",
    "equilibrium",
    "roots",
    "EVENTS",
    "MECHANISMS",
    "STAGES",
    "Branch",
    "BranchEvent",
    "LoadPath",
    "PathEvent",
    "CriticalForces",
    "trace_branch",
    "load_path",
    "critical_forces",
    "Profile",
    "profile",
    "GapLaw",
    "gap_law",
]

#: Model names and the library's integer constants (include/wavyadhesion.h).
MODELS = {"westergaard": 0, "jkr": 1, "dw": 2, "md": 3}

# Status codes of the library (src/wa_status.f90).
_OK, _INVALID_ARGUMENT, _NO_SOLUTION, _NOT_CONVERGED = 0, 1, 2, 3
_CAPACITY_TOO_SMALL, _NUMERICAL_ERROR = 4, 5

# States asked for in a first roots() call; more are fetched in a second call.
_ROOTS_CAPACITY = 16

# Points asked for in a first trace_branch() call. Branches have a few hundred points
# (at most 1320 over DW and MD, alpha 0.1-3, mu 0.01-30); a longer one (the library
# allows 20000) is traced again into arrays of the exact size. Room for 20000 at once
# would cost ~0.5 ms per call in array set-up (1.55 vs 1.03 ms for a DW branch).
_BRANCH_CAPACITY = 4096

# Events asked for in a first load_path() call (path_type holds at most 64).
_PATH_CAPACITY = 64

# The library's bounds, read from it (wa_params, wa_map): the supported domain
# (WA_ALPHA_MIN ... WA_MU_MAX in include/wavyadhesion.h; a test checks they agree) and
# the size of an adhesion map's grid. Used to refuse bad input before any work or
# allocation; for alpha and mu the library's own check decides and words the message.
_LIMITS = _f.fa_limits()
_ALPHA_MIN, _ALPHA_MAX, _MU_MIN, _MU_MAX = (float(v) for v in _LIMITS[:4])
_MAP_N_MU_MAX, _MAP_N_ALPHA_MAX, _MAP_CELLS_MAX = (int(v) for v in _LIMITS[4:])

# The largest value of a C int (an integer the facade passes to Fortran)
_C_INT_MAX = 2**31 - 1

# Points per facade call in the vectorised functions. Between two calls Python runs and
# raises KeyboardInterrupt on Ctrl-C (a Fortran call cannot be interrupted), so a chunk
# should take well under a second: equilibrium ~2 us/point (DW) to ~50 us/point (MD near
# its limits), critical forces ~1 ms (DW) to ~50 ms (MD) per mu. Calls this size or
# smaller are one facade call, exactly as before chunking.
_CHUNK_POINTS = 4096
_CHUNK_SWEEP = 16
# gap_law: each call walks the cycle again (~1-2 ms), then ~3 us per mean gap (MD), so
# a chunk of 65536 gaps takes ~0.2 s and repeats the walk for < 1 % of the time; the
# values at each gap and W* do not depend on the other gaps of the call.
_CHUNK_GAPS = 65536

# On an executor a chunk holds at least _parallel.chunk_seconds() of work (scheduling
# overhead < 5 %), estimated with the cheapest measured cost of one critical_forces point
# (s, by model code; mu from 0.01 to 30, alpha 0.1 to 3: Westergaard/JKR ~0.03 ms,
# DW 0.29-0.61 ms, MD 1.4-3.2 ms; python/benchmarks/bench_parallel.py --costs).
_SWEEP_SECONDS = {0: 2.5e-5, 1: 2.5e-5, 2: 2.9e-4, 3: 1.4e-3}

#: Event codes of branch points and load-path events (SPEC section 7, include/wavyadhesion.h).
EVENTS = {
    0: "none",
    1: "fold",
    2: "switch",
    3: "jump_start",
    4: "jump_end",
    5: "full_contact_reached",
    6: "full_contact_left",
    7: "pull_off",
    8: "branch_end",
    9: "a_turn",
}

#: How full contact is reached or contact is lost, by code (WA_MECHANISM_* in C).
MECHANISMS = ("gradual", "jump_case1", "jump_case2", "snap")

#: Load-path stages by code.
STAGES = {1: "loading", 2: "unloading"}

#: Gap-control event codes (3-6 as in EVENTS; WA_GAP_EVENT_* in C).
GAP_EVENTS = {
    3: "jump_start",
    4: "jump_end",
    5: "full_contact_reached",
    6: "full_contact_left",
    10: "touch",
    11: "contact_made",
    12: "contact_lost",
    13: "interaction_lost",
}

#: Gap-control stages by code.
GAP_STAGES = {1: "approach", 2: "retraction"}


class WavyAdhesionError(Exception):
    """Base class of every error raised by wavyadhesion.

    Attributes
    ----------
    status : int
        The library's status code (1 invalid argument, 2 no solution, 3 not
        converged, 5 numerical error).
    message : str
        The library's message, naming the argument or the step that failed.
    """

    def __init__(self, message: str, status: int):
        super().__init__(message)
        self.status = status
        self.message = message


class InvalidArgumentError(WavyAdhesionError, ValueError):
    """An argument is NaN, infinite or outside its valid range (status 1)."""


class InvalidTypeError(InvalidArgumentError, TypeError):
    """An argument has the wrong type (None, complex, a string, a masked array with
    masked values): also a TypeError, and an InvalidArgumentError (status 1)."""


class ConvergenceError(WavyAdhesionError):
    """A numerical failure: an iteration did not converge (status 3), a numerical
    building block failed (status 5), or no solution was found (status 2, see
    :class:`NoSolutionError`)."""


class NoSolutionError(ConvergenceError):
    """The equations have no solution of the kind asked for (status 2)."""


def _text(message) -> str:
    if isinstance(message, (bytes, np.bytes_)):
        message = message.decode("ascii", "replace")
    elif isinstance(message, np.ndarray):
        message = message.tobytes().decode("ascii", "replace")
    return str(message).strip("\x00 ").strip()


def _raise(status: int, message, where: str = "") -> None:
    """Raise the exception that matches a non-zero library status."""
    text = _text(message)
    if not text:
        text = _text(_f.fa_status_text(status))
    if where:
        text = f"{text} ({where})"
    if status == _INVALID_ARGUMENT:
        raise InvalidArgumentError(text, status)
    if status == _NO_SOLUTION:
        raise NoSolutionError(text, status)
    raise ConvergenceError(text, status)


def _model_name(code: int) -> str:
    return next(name for name, c in MODELS.items() if c == code)


def _scalar(x, name: str) -> float:
    arr = _float_array(x, name)
    if arr.ndim != 0:
        raise InvalidArgumentError(f"{name} must be a scalar, got shape {arr.shape}",
                                   _INVALID_ARGUMENT)
    return float(arr)


def _count(value, name: str, lo: int, hi: int) -> int:
    """A count given as an integer in [lo, hi] (an integral float such as 60.0 too),
    checked before anything is allocated. A bool, a non-integral or non-finite number and
    anything but a real number are refused, naming `name` and its range."""
    expected = f"an integer in [{lo}, {hi}]"
    if isinstance(value, (bool, np.bool_)) or not isinstance(
            value, (int, float, np.integer, np.floating)):
        raise InvalidTypeError(f"{name} = {value!r}: must be {expected}", _INVALID_ARGUMENT)
    if isinstance(value, (float, np.floating)) and not (np.isfinite(value)
                                                         and float(value).is_integer()):
        raise InvalidArgumentError(f"{name} = {value!r}: must be {expected}",
                                   _INVALID_ARGUMENT)
    if not lo <= int(value) <= hi:
        raise InvalidArgumentError(f"{name} = {value!r} is outside [{lo}, {hi}]",
                                   _INVALID_ARGUMENT)
    return int(value)


def _real_in(value, name: str, lo: float, hi: float) -> float:
    """A real scalar in [lo, hi] (finite), or an error naming `name` and the range."""
    x = _scalar(value, name)
    if not lo <= x <= hi:
        raise InvalidArgumentError(f"{name} = {value!r} is outside its valid range "
                                   f"[{lo:g}, {hi:g}]", _INVALID_ARGUMENT)
    return x


def _model_code(model) -> int:
    if not isinstance(model, str):
        raise InvalidTypeError(
            f"model must be a string, one of {', '.join(map(repr, MODELS))}; got "
            f"{type(model).__name__} {model!r}", _INVALID_ARGUMENT)
    if model.lower() in MODELS:
        return MODELS[model.lower()]
    raise InvalidArgumentError(
        f"model = {model!r} is not one of {', '.join(map(repr, MODELS))}", _INVALID_ARGUMENT
    )


def _float_array(x, name: str) -> np.ndarray:
    """x as a float64 array. None (also inside a sequence), complex numbers, strings,
    bytes and masked values are refused with an InvalidTypeError naming the argument
    (numpy would read None as NaN, drop the imaginary part, parse strings and drop
    masks)."""
    if type(x) is float or type(x) is int:                # the common scalar case
        return np.asarray(x, dtype=np.float64)
    if x is None:
        raise InvalidTypeError(f"{name} is None: give a real number or an array of them",
                               _INVALID_ARGUMENT)
    if isinstance(x, np.ma.MaskedArray):
        n_masked = int(np.ma.count_masked(x))
        if n_masked:
            raise InvalidTypeError(
                f"{name} is a masked array with {n_masked} masked value(s): masks are not "
                f"supported (pass x.filled(np.nan) or x.compressed())", _INVALID_ARGUMENT)
        x = np.ma.getdata(x)
    if isinstance(x, np.ndarray) and x.dtype.kind in "fiub":
        return np.asarray(x, dtype=np.float64)
    try:
        raw = np.asarray(x)
    except (TypeError, ValueError) as exc:
        raise InvalidTypeError(f"{name}: not convertible to float ({exc})",
                               _INVALID_ARGUMENT) from None
    kind = raw.dtype.kind
    if kind == "c":
        raise InvalidTypeError(f"{name} is complex ({raw.dtype}): give real numbers (the "
                               f"imaginary part would be lost)", _INVALID_ARGUMENT)
    if kind in "USVMm":
        raise InvalidTypeError(f"{name}: {raw.dtype} values are not real numbers",
                               _INVALID_ARGUMENT)
    if kind == "O":
        for v in raw.flat:
            if v is None:
                raise InvalidTypeError(f"{name} contains None: give real numbers",
                                       _INVALID_ARGUMENT)
            if isinstance(v, (complex, np.complexfloating)):
                raise InvalidTypeError(f"{name} contains a complex number ({v!r})",
                                       _INVALID_ARGUMENT)
            if isinstance(v, (str, bytes)):
                raise InvalidTypeError(f"{name} contains a string ({v!r})",
                                       _INVALID_ARGUMENT)
    try:
        return np.asarray(raw, dtype=np.float64)
    except (TypeError, ValueError) as exc:
        raise InvalidTypeError(f"{name}: not convertible to float ({exc})",
                               _INVALID_ARGUMENT) from None


def _chunks(n: int, size: int):
    """Slices of at most `size` covering range(n) (one slice when n <= size)."""
    for start in range(0, n, size):
        yield slice(start, min(start + size, n))


def _flat(arr: np.ndarray) -> np.ndarray:
    """Contiguous 1-D float64 view or copy (what the facade takes without copying)."""
    return np.ascontiguousarray(arr, dtype=np.float64).reshape(-1)


def _shaped(values: np.ndarray, shape):
    """Back to the broadcast shape; a numpy scalar when the inputs were scalars."""
    out = values.reshape(shape)
    return out[()] if out.ndim == 0 else out


def _where(index: int, shape) -> str:
    if len(shape) == 0:
        return ""
    return f"at index {tuple(int(i) for i in np.unravel_index(index - 1, shape))}"


def _index_text(i: int, shape) -> str:
    """'2' or '1, 0' for the flat index i of an array of `shape` ('' for a scalar)."""
    return ", ".join(str(int(k)) for k in np.unravel_index(i, shape)) if shape else ""


class Equilibrium(NamedTuple):
    """Principal equilibrium states (numpy arrays of the broadcast shape).

    Attributes
    ----------
    c_star : numpy.ndarray of float
        Interaction-zone half-width over the period, c* = c/L (1/2 in zone case 2).
    P_star : numpy.ndarray of float
        Load P* = mean traction / p*, p* = pi E* Delta / L (negative = tensile).
    zone_case : numpy.ndarray of int
        1: a* < c* < 1/2, 2: c* = 1/2, 3: full contact (a* = 1/2).
    gbar : numpy.ndarray of float
        Mean gap gbar* = gbar/Delta (mean of the gap h over one period): 0 in full
        contact, 1 for the undeformed wave touching at its crest. NaN where a point
        failed (errors="nan") or the mean gap is not defined (DW at a* = 0).
    """

    c_star: np.ndarray
    P_star: np.ndarray
    zone_case: np.ndarray
    gbar: np.ndarray


class State(NamedTuple):
    """One equilibrium state at a given a*.

    Attributes
    ----------
    a_star : float
        Contact half-width over the period.
    c_star : float
        Interaction-zone half-width over the period.
    P_star : float
        Load over p* (negative = tensile).
    zone_case : int
        1: a* < c* < 1/2, 2: c* = 1/2, 3: full contact.
    gap_width : float
        c* - a*, computed without cancellation (accurate for very thin zones).
    gbar : float
        Mean gap gbar* = gbar/Delta of the state (NaN where not defined).
    """

    a_star: float
    c_star: float
    P_star: float
    zone_case: int
    gap_width: float
    gbar: float


def westergaard_load(a):
    """Westergaard load P* = sin^2(pi a*) (no adhesion).

    Parameters
    ----------
    a : array_like
        Contact half-width over the period, a* in [0, 1/2].

    Returns
    -------
    numpy.ndarray or numpy.float64
        P*, same shape as `a`.

    Raises
    ------
    InvalidArgumentError
        If any a* is NaN or outside [0, 1/2].

    Examples
    --------
    >>> westergaard_load([0.0, 0.25, 0.5]).round(12)
    array([0. , 0.5, 1. ])
    """
    a = _float_array(a, "a")
    if a.size == 0:
        return np.empty(a.shape)
    a_f = _flat(a)
    if a_f.size <= _CHUNK_POINTS:
        p, nfail, ifail, status, message = _f.fa_westergaard_load(a_f)
        if nfail:
            _raise(status, message, _where(ifail, a.shape))
        return _shaped(p, a.shape)
    p = np.empty(a_f.size)
    for sl in _chunks(a_f.size, _CHUNK_POINTS):
        p[sl], nfail, ifail, status, message = _f.fa_westergaard_load(a_f[sl])
        if nfail:
            _raise(status, message, _where(sl.start + ifail, a.shape))
    return _shaped(p, a.shape)


def jkr_load(alpha, a):
    """JKR load of the wavy surface (Johnson 1995), P* = sin^2(pi a*) - alpha sqrt(tan(pi a*)).

    Parameters
    ----------
    alpha : array_like
        Johnson's parameter, alpha >= 0.
    a : array_like
        Contact half-width over the period, a* in [0, 1/2]; broadcast with `alpha`.

    Returns
    -------
    numpy.ndarray or numpy.float64
        P*, of the broadcast shape; -inf at a* = 1/2 (full contact never releases).

    Raises
    ------
    InvalidArgumentError
        If any alpha < 0 or a* outside [0, 1/2], or either is NaN.
    """
    alpha = _float_array(alpha, "alpha")
    a = _float_array(a, "a")
    alpha_b, a_b = np.broadcast_arrays(alpha, a)
    if a_b.size == 0:
        return np.empty(a_b.shape)
    alpha_f, a_f = _flat(alpha_b), _flat(a_b)
    if a_f.size <= _CHUNK_POINTS:
        p, nfail, ifail, status, message = _f.fa_jkr_load(alpha_f, a_f)
        if nfail:
            _raise(status, message, _where(ifail, a_b.shape))
        return _shaped(p, a_b.shape)
    p = np.empty(a_f.size)
    for sl in _chunks(a_f.size, _CHUNK_POINTS):
        p[sl], nfail, ifail, status, message = _f.fa_jkr_load(alpha_f[sl], a_f[sl])
        if nfail:
            _raise(status, message, _where(sl.start + ifail, a_b.shape))
    return _shaped(p, a_b.shape)


def equilibrium(model, alpha, mu, a, *, errors: str = "raise") -> Equilibrium:
    """Principal equilibrium state at given contact half-widths.

    For "dw" and "md" the principal state is the case-1 state (a* < c* < 1/2) with the
    smallest c*, else the case-2 state (c* = 1/2); a* = 1/2 is full contact at its
    threshold load. "westergaard" and "jkr" have no cohesive zone: c* = a*.

    Parameters
    ----------
    model : {"westergaard", "jkr", "dw", "md"}
        The contact model.
    alpha : array_like
        Johnson's parameter, alpha > 0.
    mu : array_like
        Transition parameter, mu >= 0 (mu = 0 is Westergaard; large mu tends to JKR).
    a : array_like
        Contact half-width over the period, a* in [0, 1/2].
    errors : {"raise", "nan"}, optional
        "raise" (default): raise on the first point that fails. "nan": return NaN
        (zone case 0) at failed points and raise nothing.

    Returns
    -------
    Equilibrium
        Named tuple ``(c_star, P_star, zone_case, gbar)`` of arrays of the broadcast shape of
        `alpha`, `mu` and `a` (numpy scalars when all three are scalars).

    Raises
    ------
    InvalidArgumentError
        Unknown model, or alpha, mu or a* outside its range (also a ValueError).
    ConvergenceError
        The solver failed at some point (NoSolutionError when no equilibrium exists).

    Examples
    --------
    >>> eq = equilibrium("dw", 0.3, 1.0, [0.1, 0.2, 0.3])
    >>> eq.P_star.shape
    (3,)
    """
    code = _model_code(model)
    if errors not in ("raise", "nan"):
        raise InvalidArgumentError(f"errors = {errors!r} is not 'raise' or 'nan'", 1)
    alpha_b, mu_b, a_b = np.broadcast_arrays(
        _float_array(alpha, "alpha"), _float_array(mu, "mu"), _float_array(a, "a")
    )
    shape = a_b.shape
    if a_b.size == 0:
        return Equilibrium(np.empty(shape), np.empty(shape), np.empty(shape, np.int32),
                           np.empty(shape))
    alpha_f, mu_f, a_f = _flat(alpha_b), _flat(mu_b), _flat(a_b)
    if a_f.size <= _CHUNK_POINTS:
        c, p, z, g, nfail, ifail, status, message = _f.fa_equilibrium(code, alpha_f, mu_f, a_f)
        if nfail and errors == "raise":
            _raise(status, message, _where(ifail, shape))
        return Equilibrium(_shaped(c, shape), _shaped(p, shape), _shaped(z, shape),
                           _shaped(g, shape))
    c = np.empty(a_f.size)
    p = np.empty(a_f.size)
    z = np.empty(a_f.size, dtype=np.int32)
    g = np.empty(a_f.size)
    for sl in _chunks(a_f.size, _CHUNK_POINTS):     # Ctrl-C is seen between chunks
        c[sl], p[sl], z[sl], g[sl], nfail, ifail, status, message = _f.fa_equilibrium(
            code, alpha_f[sl], mu_f[sl], a_f[sl])
        if nfail and errors == "raise":
            _raise(status, message, _where(sl.start + ifail, shape))
    return Equilibrium(_shaped(c, shape), _shaped(p, shape), _shaped(z, shape),
                       _shaped(g, shape))


def _grown(fortran, capacity, n_index, *args):
    """Call an f2py routine whose first argument is the capacity of its output arrays,
    growing the capacity until the outputs fit (out[n_index] is the count needed);
    raise on failure (status and message are the last two outputs)."""
    while True:
        out = fortran(capacity, *args)
        status, n = out[-2], out[n_index]
        if status == _CAPACITY_TOO_SMALL and n > capacity:
            capacity = int(n)
            continue
        if status != _OK:
            _raise(status, out[-1])
        return out


def roots(model, alpha, mu, a_star) -> list:
    """Every equilibrium state at one point (alpha, mu, a*).

    Parameters
    ----------
    model : {"westergaard", "jkr", "dw", "md"}
        The contact model.
    alpha : float
        Johnson's parameter, alpha > 0.
    mu : float
        Transition parameter, mu >= 0.
    a_star : float
        Contact half-width over the period, in [0, 1/2].

    Returns
    -------
    list of State
        Case-1 states by increasing c*, then the case-2 state (one state for
        "westergaard" and "jkr"). The first is the state `equilibrium` returns.

    Raises
    ------
    InvalidArgumentError
        Unknown model or an argument outside its range.
    ConvergenceError
        The solver failed.
    """
    code = _model_code(model)
    values = []
    for name, x in (("alpha", alpha), ("mu", mu), ("a_star", a_star)):
        arr = _float_array(x, name)
        if arr.ndim != 0:
            raise InvalidArgumentError(f"{name} must be a scalar (roots works at one point)", 1)
        values.append(float(arr))
    alpha, mu, a_star = values
    c, p, z, gap, g, n, _, _ = _grown(_f.fa_roots, _ROOTS_CAPACITY, 5, code, alpha, mu, a_star)
    return [
        State(a_star, float(c[k]), float(p[k]), int(z[k]), float(gap[k]), float(g[k]))
        for k in range(n)
    ]


class BranchEvent(NamedTuple):
    """A point of a branch that carries an event.

    Attributes
    ----------
    index : int
        Position of the point in the branch's arrays.
    kind : str
        ``"fold"`` (dP*/da* = 0), ``"switch"`` (zone-case switch: c* reaches or leaves
        1/2) or ``"branch_end"`` (first and last point); see :data:`EVENTS`.
    a_star, c_star, P_star : float
        The state at the event.
    zone_case : int
        1: a* < c* < 1/2, 2: c* = 1/2, 3: full contact.
    """

    index: int
    kind: str
    a_star: float
    c_star: float
    P_star: float
    zone_case: int


@dataclass(frozen=True, eq=False)
class Branch:
    """An equilibrium branch traced by :func:`trace_branch` (points in the order of the
    curve, from a* -> 0 to a* = 1/2; not necessarily monotone in a*).

    Attributes
    ----------
    model : str
        The model name.
    alpha, mu : float
        The parameters.
    a_star, c_star, P_star : numpy.ndarray of float
        Contact half-width, interaction-zone half-width and load of each point.
    b_star : numpy.ndarray of float
        b* = a* + 0.4 (c* - a*) (the paper's Fig. 5 abscissa).
    zone_case : numpy.ndarray of int
        0: no contact (MD: a* = 0, Dugdale zone |x*| < c*), 1: a* < c* < 1/2, 2: c* = 1/2,
        3: full contact.
    stable : numpy.ndarray of bool
        True where the state is stable under load control (case 2: dP*/da* > 0;
        case 1: the flag changes only at extrema of P*, not at a*-turns); False at folds.
    event : numpy.ndarray of int
        Event code of each point (:data:`EVENTS`; 0 for ordinary points).
    extremum : numpy.ndarray of int
        +1 at a local maximum of P* along the curve, -1 at a local minimum, else 0.
    gbar : numpy.ndarray of float
        Mean gap gbar* = gbar/Delta of each point.
    """

    model: str
    alpha: float
    mu: float
    a_star: np.ndarray
    c_star: np.ndarray
    P_star: np.ndarray
    b_star: np.ndarray
    zone_case: np.ndarray
    stable: np.ndarray
    event: np.ndarray
    extremum: np.ndarray
    gbar: np.ndarray

    def __len__(self) -> int:
        return int(self.a_star.size)

    @property
    def events(self) -> list:
        """Every point with an event, in order, as :class:`BranchEvent`."""
        return [
            BranchEvent(int(i), EVENTS[int(self.event[i])], float(self.a_star[i]),
                        float(self.c_star[i]), float(self.P_star[i]), int(self.zone_case[i]))
            for i in np.flatnonzero(self.event)
        ]

    @property
    def folds(self) -> list:
        """The folds (dP*/da* = 0), in order along the curve."""
        return [e for e in self.events if e.kind == "fold"]

    @property
    def switches(self) -> list:
        """The zone-case switches (c* reaching or leaving 1/2)."""
        return [e for e in self.events if e.kind == "switch"]


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


@dataclass(frozen=True, eq=False)
class LoadPath:
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

    def __len__(self) -> int:
        return int(self.event.size)

    @property
    def mechanisms(self) -> dict:
        """``{"full_contact": fc_mechanism, "pull_off": pf_mechanism}``."""
        return {"full_contact": self.fc_mechanism, "pull_off": self.pf_mechanism}

    @property
    def events(self) -> list:
        """The events in order, as :class:`PathEvent`."""
        return [
            PathEvent(STAGES[int(st)], EVENTS[int(ev)], float(a), float(c), float(p))
            for st, ev, a, c, p in zip(self.stage, self.event, self.a_star, self.c_star,
                                       self.P_star)
        ]


@dataclass(frozen=True, eq=False)
class CriticalForces:
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
    """

    P_fc: np.ndarray
    P_pf: np.ndarray
    fc_mechanism: np.ndarray
    pf_mechanism: np.ndarray
    status: np.ndarray = None
    messages: dict = field(default_factory=dict)

    @property
    def ok(self) -> np.ndarray:
        """True where the point's forces were computed (status 0)."""
        return np.asarray(self.status) == _OK

    def __iter__(self):
        yield self.P_fc
        yield self.P_pf

    def __len__(self) -> int:
        return 2

    def __getitem__(self, i):
        return (self.P_fc, self.P_pf)[i]


def trace_branch(model, alpha, mu) -> Branch:
    """The equilibrium branch P*(a*), c*(a*) over 0 < a* <= 1/2, with its folds and
    zone-case switches.

    DW and MD: pseudo-arclength continuation with adaptive steps through every fold,
    switching zone case where c* reaches 1/2; folds and switches are located as points
    of their own. Westergaard and JKR: the closed form sampled at 201 points, JKR's
    folds located. The whole branch is computed in one Fortran call (GIL released).

    Parameters
    ----------
    model : {"westergaard", "jkr", "dw", "md"}
        The contact model.
    alpha : float
        Johnson's parameter, alpha > 0.
    mu : float
        Transition parameter, mu >= 0.

    Returns
    -------
    Branch
        Arrays ``a_star, c_star, P_star, b_star, zone_case, stable, event, extremum,
        gbar`` (one element per point) and the list ``events`` (also ``folds``,
        ``switches``).

    Raises
    ------
    InvalidArgumentError
        Unknown model, alpha <= 0, mu < 0, NaN or infinite values.
    ConvergenceError
        The continuation failed (e.g. step-size underflow).

    Examples
    --------
    >>> b = trace_branch("dw", 0.3, 5.0)
    >>> [e.kind for e in b.events]
    ['branch_end', 'fold', 'fold', 'switch', 'branch_end']
    >>> round(b.folds[1].P_star, 12)
    0.387507241744
    """
    code = _model_code(model)
    alpha = _scalar(alpha, "alpha")
    mu = _scalar(mu, "mu")
    out = _grown(_f.fa_trace_branch, _BRANCH_CAPACITY, 9, code, alpha, mu)
    a, c, p, b, z, st, ev, ex, g, n, _, _ = out
    n = int(n)
    return Branch(_model_name(code), alpha, mu, a[:n].copy(), c[:n].copy(), p[:n].copy(),
                  b[:n].copy(), z[:n].copy(), st[:n].astype(bool), ev[:n].copy(),
                  ex[:n].copy(), g[:n].copy())


def load_path(model, alpha, mu) -> LoadPath:
    """Load-controlled loading and unloading along the branch (MODEL-NOTES.md).

    Loading starts from separation at P* = 0 (jump-in), rises along stable pieces and
    jumps at every maximum of P* until full contact (load P_fc); unloading leaves full
    contact, falls along stable pieces and jumps at every minimum until contact is lost
    (load P_pf).

    Parameters
    ----------
    model : {"westergaard", "jkr", "dw", "md"}
        The contact model.
    alpha : float
        Johnson's parameter, alpha > 0.
    mu : float
        Transition parameter, mu >= 0.

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
    code = _model_code(model)
    alpha = _scalar(alpha, "alpha")
    mu = _scalar(mu, "mu")
    out = _grown(_f.fa_load_path, _PATH_CAPACITY, 5, code, alpha, mu)
    stage, ev, a, c, p, n, p_fc, p_pf, fc_m, pf_m, area, jump_e, _, _ = out
    n = int(n)
    return LoadPath(_model_name(code), alpha, mu, stage[:n].copy(), ev[:n].copy(),
                    a[:n].copy(), c[:n].copy(), p[:n].copy(), float(p_fc), float(p_pf),
                    MECHANISMS[int(fc_m)], MECHANISMS[int(pf_m)], float(area),
                    jump_e[:n].copy())


def critical_forces(model, alpha, mu, *, errors: str = "raise", executor=None,
                    chunk_size=None) -> CriticalForces:
    """Critical forces P_fc* (full contact reached on loading) and P_pf* (pull-off on
    unloading), vectorised over mu and broadcast with alpha.

    The Fortran ``critical_sweep`` (GIL released) traces the branch and follows the load
    path for each mu, in calls of at most 16 mu that share an alpha; Ctrl-C
    (KeyboardInterrupt) takes effect between two calls. A point that fails never stops
    the others.

    Parameters
    ----------
    model : {"westergaard", "jkr", "dw", "md"}
        The contact model.
    alpha : array_like
        Johnson's parameter, alpha > 0.
    mu : array_like
        Transition parameter, mu >= 0; broadcast with `alpha`.
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

    Returns
    -------
    CriticalForces
        ``P_fc``, ``P_pf`` (unpack as ``P_fc, P_pf = critical_forces(...)``), the
        mechanism codes ``fc_mechanism``, ``pf_mechanism`` and the library status
        ``status`` (0 where the point succeeded), arrays of the broadcast shape (numpy
        scalars when alpha and mu are scalars); ``messages`` maps the index of each failed
        point to the library's message. JKR: P_pf = -inf.

    Raises
    ------
    InvalidArgumentError
        Unknown model; (errors="raise") alpha outside [1e-12, 1e12], mu outside 0 or
        [1e-100, 1e100], NaN or infinite values (the
        message gives the index of the first bad point).
    InvalidTypeError
        alpha or mu is None, complex, a string or a masked array with masked values.
    ConvergenceError
        (errors="raise") A point's branch or load path could not be computed; the
        message gives its index, alpha and mu.

    Examples
    --------
    >>> P_fc, P_pf = critical_forces("dw", 0.3, [0.1, 1.0, 5.0])
    >>> P_fc.round(6), P_pf.round(6)
    (array([0.977827, 0.778274, 0.387507]), array([-0.022173, -0.088714, -0.119953]))
    """
    code = _model_code(model)
    if errors not in ("raise", "nan"):
        raise InvalidArgumentError(f"errors = {errors!r} is not 'raise' or 'nan'", 1)
    alpha_b, mu_b = np.broadcast_arrays(_float_array(alpha, "alpha"), _float_array(mu, "mu"))
    shape = mu_b.shape
    alpha_f, mu_f = _flat(alpha_b), _flat(mu_b)
    out = (np.full(mu_f.size, np.nan), np.full(mu_f.size, np.nan),
           np.full(mu_f.size, -1, dtype=np.int32), np.full(mu_f.size, -1, dtype=np.int32),
           np.zeros(mu_f.size, dtype=np.int32))
    messages = {}
    size = _chunk_size(chunk_size, executor, _SWEEP_SECONDS[code], _CHUNK_SWEEP)
    if mu_f.size == 1:
        _sweep_chunk(code, float(alpha_f[0]), mu_f, np.zeros(1, dtype=np.intp), out,
                     messages, errors, shape)
    elif mu_f.size:
        values, inverse = np.unique(alpha_f, return_inverse=True)
        if errors == "raise" and (values.size > 1 or mu_f.size > size):
            _check_sweep_arguments(code, alpha_f, mu_f, shape)   # all before any work
        chunks = _sweep_pieces(values, inverse.reshape(-1), size)
        tasks = [(code, [(value, mu_f[idx]) for value, idx in chunk]) for chunk in chunks]
        # in order; serially Ctrl-C is seen between chunks
        for chunk, results in zip(chunks, iter_chunks(_sweep_task, tasks, executor)):
            for (value, idx), result in zip(chunk, results):
                _sweep_chunk(code, value, mu_f, idx, out, messages, errors, shape, result)
    p_fc, p_pf, fc_m, pf_m, status = out
    return CriticalForces(_shaped(p_fc, shape), _shaped(p_pf, shape), _shaped(fc_m, shape),
                          _shaped(pf_m, shape), _shaped(status, shape), messages)


def _check_sweep_arguments(code, alpha_f, mu_f, shape):
    """InvalidArgumentError naming the first bad alpha or mu, before any work."""
    with np.errstate(invalid="ignore"):
        bad_alpha = ~((alpha_f >= _ALPHA_MIN) & (alpha_f <= _ALPHA_MAX))
        bad_mu = ~((mu_f == 0) | ((mu_f >= _MU_MIN) & (mu_f <= _MU_MAX)))
    for bad in (bad_alpha, bad_mu):
        if bad.any():
            i = int(np.flatnonzero(bad)[0])
            *_, status, message = _f.fa_critical_sweep(code, float(alpha_f[i]),
                                                       np.array([mu_f[i]]))
            if status != _OK:
                _raise(status, message, _where(i + 1, shape))


def _chunk_size(chunk_size, executor, seconds_per_point, serial):
    """Points per chunk: `chunk_size` (validated), else `serial` without an executor,
    else enough points for _parallel.chunk_seconds(executor) of work."""
    if chunk_size is None:
        if executor is None:
            return serial
        return points_per_chunk(executor, seconds_per_point, serial)
    if isinstance(chunk_size, (bool, np.bool_)) or not isinstance(
            chunk_size, (int, np.integer)) or chunk_size < 1:
        raise InvalidArgumentError(f"chunk_size = {chunk_size!r} is not a positive integer",
                                   _INVALID_ARGUMENT)
    return int(chunk_size)


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
    if status == _INVALID_ARGUMENT and (rs == _INVALID_ARGUMENT).all():
        # an argument was refused and nothing computed
        if errors == "raise":
            where = idx[ifail - 1] if ifail > 0 else idx[0]
            _raise(status, message, _where(int(where) + 1, shape))
        if idx.size > 1:                                 # isolate the bad points
            for i in idx:
                _sweep_chunk(code, alpha, mu_f, np.array([i]), out, messages, errors, shape)
            return
    p_fc[idx], p_pf[idx], fc_m[idx], pf_m[idx], status_out[idx] = fc, pf, fm, pm, rs
    if status == _OK:
        return
    for j in np.flatnonzero(rs != _OK):
        i = int(idx[j])
        where = _where(i + 1, shape)
        # the sweep's message is about its first failing row: ask this row's own
        # (as load_path gives it; failures are rare, so the extra call costs little)
        text = _text(_f.fa_load_path(_PATH_CAPACITY, code, alpha, float(mu_f[i]))[-1])
        text = text or _text(_f.fa_status_text(int(rs[j])))
        key = tuple(int(v) for v in np.unravel_index(i, shape)) if shape else ()
        messages[key] = text
        if errors == "raise":
            _raise(int(rs[j]), text, f"{where + ', ' if where else ''}alpha = {alpha!r}, "
                   f"mu = {float(mu_f[i])!r}")


class Profile(NamedTuple):
    """Traction and gap profiles of one state (:func:`profile`); unpacks as
    ``x, traction, gap``.

    Attributes
    ----------
    x : numpy.ndarray of float
        The points x* = x/L (period 1, crest at x* = 0).
    traction : numpy.ndarray of float
        p(x)/p* (positive = compressive; its mean over a period is P*). JKR: -inf exactly
        at the contact edges |x*| = a*.
    gap : numpy.ndarray of float
        h(x)/Delta >= 0 (0 on the contact; its mean over a period is gbar*).
    """

    x: np.ndarray
    traction: np.ndarray
    gap: np.ndarray


#: Points of profile()'s default grid of x* over [-1/2, 1/2].
_PROFILE_POINTS = 401


def profile(model, alpha, mu, a_star, c_star=None, x=None) -> Profile:
    """Traction p(x)/p* and gap h(x)/Delta of one equilibrium state.

    The state is the one at `a_star` whose c* is nearest `c_star` among :func:`roots`
    (it must lie within 1e-6 of `c_star`), or the principal state (:func:`equilibrium`)
    when `c_star` is None. "md" at a* = 0: the state without contact whose Dugdale zone
    |x*| < c_star pulls the crest region (c_star < 1/2 required).

    Parameters
    ----------
    model : {"westergaard", "jkr", "dw", "md"}
        The contact model.
    alpha : float
        Johnson's parameter, alpha > 0.
    mu : float
        Transition parameter, mu >= 0.
    a_star : float
        Contact half-width over the period, in [0, 1/2].
    c_star : float, optional
        Interaction-zone half-width of the state, in [0, 1/2] (Westergaard, JKR:
        c* = a*). Default: the principal state.
    x : array_like, optional
        Points x* = x/L, any finite values (period 1, crest at 0). Default: 401 points
        from -1/2 to 1/2.

    Returns
    -------
    Profile
        ``(x, traction, gap)``, arrays of the shape of `x`.

    Raises
    ------
    InvalidArgumentError
        Unknown model, an argument outside its range, x not finite, or c_star None for
        "md" at a* = 0.
    InvalidTypeError
        An argument that is not a real number (None, complex, a string).
    NoSolutionError
        No state at `a_star` has that c*, "dw" at a* = 0, "jkr" at a* = 1/2, or "md" at
        a* = 0 with no state without contact at `c_star`.
    ConvergenceError
        The solver failed.

    Examples
    --------
    >>> x, t, h = profile("dw", 0.3, 1.0, 0.2)
    >>> bool(h.min() >= 0 and h[200] == 0)
    True
    """
    code = _model_code(model)
    alpha = _scalar(alpha, "alpha")
    mu = _scalar(mu, "mu")
    a_star = _scalar(a_star, "a_star")
    principal = c_star is None
    c_value = 0.0 if principal else _scalar(c_star, "c_star")
    if x is None:
        x = np.linspace(-0.5, 0.5, _PROFILE_POINTS)
    x = _float_array(x, "x")
    shape = x.shape
    x_f = _flat(x)
    bad = np.flatnonzero(~np.isfinite(x_f))
    if bad.size:
        where = _where(int(bad[0]) + 1, shape)
        raise InvalidArgumentError(
            f"x: every value must be finite (any finite x* is valid: the period is 1); got "
            f"{x_f[bad[0]]!r}{' ' + where if where else ''}", _INVALID_ARGUMENT)
    t = np.empty(x_f.size)
    h = np.empty(x_f.size)
    chunks = list(_chunks(x_f.size, _CHUNK_POINTS)) or [slice(0, 0)]
    for sl in chunks:                                 # Ctrl-C is seen between chunks
        out = _f.fa_profile(code, alpha, mu, a_star, c_value, int(principal), x_f[sl])
        t[sl], h[sl], _, _, _, _, status, message = out
        if status != _OK:
            _raise(status, message)
    return Profile(x_f.reshape(shape).copy(), t.reshape(shape), h.reshape(shape))


@dataclass(frozen=True)
class Scales:
    """SI scales that turn dimensionless results back into physical ones.

    Attributes
    ----------
    estar : float
        Reduced modulus E* [Pa].
    pressure : float
        p* = pi E* Delta / L [Pa]: mean traction = P* * pressure.
    force : float
        p* L [N/m]: force per period and unit depth = P* * force.
    length : float
        Period L [m]: a = a* L, c = c* L.
    radius : float
        Crest radius R = L^2 / (4 pi^2 Delta) [m].
    """

    estar: float
    pressure: float
    force: float
    length: float
    radius: float


@dataclass(frozen=True)
class Params:
    """The dimensionless parameters (alpha, mu), validated, and what derives from them.

    Parameters
    ----------
    alpha : float
        Johnson's parameter, alpha = sqrt(2 dgamma L / (pi^2 E* Delta^2)) > 0.
    mu : float
        Transition parameter, mu = Sigma0 / (pi (alpha^2/32)^(1/3)) >= 0.
    scales : Scales, optional
        SI scales, set by :meth:`from_dimensional`.

    Attributes
    ----------
    sigma0 : float
        Peak adhesive stress over p*, Sigma0 = pi mu (alpha^2/32)^(1/3).
    dcod : float
        Maugis-Dugdale opening, Dcod = (alpha^4/2)^(1/3)/mu (inf at mu = 0).

    Raises
    ------
    InvalidArgumentError
        If alpha <= 0, mu < 0, or either is NaN or infinite.
    InvalidTypeError
        If alpha or mu is not a real scalar (None, complex, a string; also a TypeError).
    """

    alpha: float
    mu: float
    scales: Optional[Scales] = None
    sigma0: float = field(init=False)
    dcod: float = field(init=False)

    def __post_init__(self):
        alpha = _scalar(self.alpha, "alpha")
        mu = _scalar(self.mu, "mu")
        sigma0, dcod, status, message = _f.fa_params(alpha, mu)
        if status != _OK:
            _raise(status, message)
        object.__setattr__(self, "alpha", alpha)
        object.__setattr__(self, "mu", mu)
        object.__setattr__(self, "sigma0", float(sigma0))
        object.__setattr__(self, "dcod", float(dcod))

    @classmethod
    def from_dimensional(
        cls,
        *,
        E1=None,
        nu1=None,
        E2=None,
        nu2=None,
        Estar=None,
        period,
        amplitude,
        work_of_adhesion,
        peak_stress,
    ) -> "Params":
        """Parameters and SI scales from physical inputs (SI units).

        Parameters
        ----------
        E1, nu1, E2, nu2 : float, optional
            Young's moduli [Pa] and Poisson's ratios of the two bodies; give all four
            or `Estar`.
        Estar : float, optional
            Reduced modulus [Pa], 1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2.
        period : float
            Period L of the wavy surface [m].
        amplitude : float
            Amplitude Delta [m].
        work_of_adhesion : float
            Work of adhesion dgamma [J/m^2].
        peak_stress : float
            Peak adhesive stress sigma0 [Pa].

        Returns
        -------
        Params
            With alpha, mu, sigma0, dcod and `scales` set.

        Raises
        ------
        InvalidArgumentError
            Missing or conflicting moduli, or any input out of range.
        InvalidTypeError
            An input that is not a real scalar (None for a required one, complex, a
            string; also a TypeError); the message names it.

        Examples
        --------
        >>> p = Params.from_dimensional(Estar=1e6, period=1e-3, amplitude=1e-5,
        ...                             work_of_adhesion=0.05, peak_stress=1e5)
        >>> round(p.alpha, 6)
        0.31831
        """
        moduli = {"E1": E1, "nu1": nu1, "E2": E2, "nu2": nu2}
        if Estar is None:
            missing = [k for k, v in moduli.items() if v is None]
            if missing:
                raise InvalidArgumentError(
                    f"give Estar, or all of E1, nu1, E2 and nu2 (missing: "
                    f"{', '.join(missing)})", 1)
            estar, status, message = _f.fa_reduced_modulus(
                *(_scalar(v, k) for k, v in moduli.items()))
            if status != _OK:
                _raise(status, message)
        else:
            given = [k for k, v in moduli.items() if v is not None]
            if given:
                raise InvalidArgumentError(
                    f"give Estar or E1, nu1, E2, nu2, not both (got Estar and "
                    f"{', '.join(given)})", 1)
            estar = _scalar(Estar, "Estar")
        out = _f.fa_dimensional(
            float(estar), _scalar(period, "period"), _scalar(amplitude, "amplitude"),
            _scalar(work_of_adhesion, "work_of_adhesion"), _scalar(peak_stress, "peak_stress"),
        )
        alpha, mu, sigma0, dcod, pressure, force, length, radius, status, message = out
        if status != _OK:
            _raise(status, message)
        scales = Scales(float(estar), float(pressure), float(force), float(length),
                        float(radius))
        return cls(float(alpha), float(mu), scales)

    def __repr__(self) -> str:
        extra = "" if self.scales is None else f", scales={self.scales!r}"
        return (f"Params(alpha={self.alpha!r}, mu={self.mu!r}, sigma0={self.sigma0!r}, "
                f"dcod={self.dcod!r}{extra})")


# GSL must return error codes, not abort() the Python process.
_f.fa_init()


class GapLaw(NamedTuple):
    """P* against the mean gap under gap control (doc/user-guide.md, "Gap control")."""
    gbar: np.ndarray
    #: P* after approaching from far apart
    P_approach: np.ndarray
    #: P* after retracting from full contact
    P_retract: np.ndarray
    #: dP*/dgbar* on approach (-inf at gbar* = 0, 0 where the surfaces do not interact)
    dPdg_approach: np.ndarray
    #: dP*/dgbar* on retraction
    dPdg_retract: np.ndarray
    #: Energy lost per cycle W* = -oint P* dgbar* (units p* Delta per unit area)
    W_star: float
    #: W*/(pi alpha^2/2), the fraction of the work of adhesion lost per cycle
    W_fraction: float


def gap_law(model, alpha, mu, gbar) -> GapLaw:
    """The gap law: P* on approach and on retraction, and their slopes dP*/dgbar*, at
    the mean gaps ``gbar`` (>= 0), with the energy lost per cycle W*.

    Parameters
    ----------
    model : {"westergaard", "jkr", "dw", "md"}
        The contact model.
    alpha, mu : float
        Johnson's parameter (> 0) and the transition parameter (>= 0).
    gbar : float or array_like
        Mean gaps gbar* = mean gap / Delta, each finite and >= 0.

    Returns
    -------
    GapLaw
        Arrays of the shape of ``gbar`` and the floats ``W_star``, ``W_fraction``.

    Raises
    ------
    InvalidArgumentError
        Unknown model, or alpha, mu or a gbar outside its range.
    ConvergenceError
        The continuation or a point solve failed.

    Examples
    --------
    >>> law = gap_law("westergaard", 0.3, 1.0, [0.25, 2.0])
    >>> float(law.P_approach[1]), law.W_star
    (0.0, 0.0)
    """
    code = _model_code(model)
    alpha = _scalar(alpha, "alpha")
    mu = _scalar(mu, "mu")
    g = _float_array(gbar, "gbar")
    shape = g.shape
    flat = np.ascontiguousarray(g.reshape(-1))
    if flat.size == 0:
        raise InvalidArgumentError("gbar is empty: give at least one mean gap",
                                   _INVALID_ARGUMENT)
    with np.errstate(invalid="ignore"):
        bad = np.flatnonzero(~(np.isfinite(flat) & (flat >= 0)))
    if bad.size:                     # the library's word on it, with the index and value
        i = int(bad[0])
        *_, status, message = _f.fa_gap_law(code, alpha, mu, flat[i:i + 1])
        if status != _OK:
            _raise(status, message, f"gbar[{_index_text(i, shape)}] = {float(flat[i])!r}" if shape
                   else f"gbar = {float(flat[i])!r}")
    outputs = [np.empty(flat.size) for _ in range(4)]
    for sl in _chunks(flat.size, _CHUNK_GAPS):       # Ctrl-C is seen between chunks
        *values, w, wf, status, message = _f.fa_gap_law(code, alpha, mu, flat[sl])
        if status != _OK:
            _raise(status, message)
        for out, v in zip(outputs, values):
            out[sl] = v
    pa, pr, da, dr = outputs
    return GapLaw(g.copy(), pa.reshape(shape), pr.reshape(shape), da.reshape(shape),
                  dr.reshape(shape), float(w), float(wf))


class GapPath(NamedTuple):
    """One approach-retraction cycle under gap (mean-gap) control, as :func:`gap_path`
    returns it: one element per event (doc/user-guide.md, "Gap control")."""
    #: 1 approach, 2 retraction (:data:`GAP_STAGES`)
    stage: np.ndarray
    #: Event codes (:data:`GAP_EVENTS`)
    event: np.ndarray
    #: Zone case of the state at each event (0 where the surfaces are apart or MD has no
    #: contact)
    zone_case: np.ndarray
    a_star: np.ndarray
    c_star: np.ndarray
    P_star: np.ndarray
    gbar: np.ndarray
    #: Energy lost per cycle W* = -oint P* dgbar* (units p* Delta per unit area)
    W_star: float
    #: W*/(pi alpha^2/2)
    W_fraction: float
    #: gbar* where the surfaces first interact on approach
    g_touch: float

    @property
    def events(self):
        """The events as (stage name, event name, gbar*, P*) tuples."""
        return [(GAP_STAGES[int(s)], GAP_EVENTS.get(int(e), str(int(e))), float(g), float(p))
                for s, e, g, p in zip(self.stage, self.event, self.gbar, self.P_star)]


def gap_path(model, alpha, mu) -> GapPath:
    """Approach from far apart to full contact and retraction under gap control, with
    the energy lost per cycle: the events (first interaction, jumps at constant gbar*,
    contact made or lost, full contact reached or left, interaction lost) with their
    states.

    Parameters
    ----------
    model : {"westergaard", "jkr", "dw", "md"}
        The contact model.
    alpha, mu : float
        Johnson's parameter (> 0) and the transition parameter (>= 0).

    Returns
    -------
    GapPath

    Raises
    ------
    InvalidArgumentError
        Unknown model, or alpha or mu outside its range.
    ConvergenceError
        The continuation or a point solve failed.

    Examples
    --------
    >>> path = gap_path("md", 0.3, 1.0)
    >>> path.events[0][:2], round(path.W_star, 10)
    (('approach', 'touch'), 0.0070144396)
    """
    code = _model_code(model)
    alpha = _scalar(alpha, "alpha")
    mu = _scalar(mu, "mu")
    out = _grown(_f.fa_gap_path, _PATH_CAPACITY, 7, code, alpha, mu)
    stage, ev, zone, a, c, p, g, n, w, wf, gt, _, _ = out
    n = int(n)
    return GapPath(stage[:n].copy(), ev[:n].copy(), zone[:n].copy(), a[:n].copy(),
                   c[:n].copy(), p[:n].copy(), g[:n].copy(), float(w), float(wf), float(gt))
