"""Equilibrium states at given contact half-widths: the closed-form loads, the
principal state (vectorised) and every state at one point."""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from . import _wa_f2py as _f
from ._args import (at_index, chunk_slices, flat_f64, float_array, grown, model_code,
                    shaped)
from ._errors import InvalidArgumentError, raise_status

# States asked for in a first roots() call; more are fetched in a second call.
_ROOTS_CAPACITY = 16

# Points per facade call in the vectorised functions. Between two calls Python runs and
# raises KeyboardInterrupt on Ctrl-C (a Fortran call cannot be interrupted), so a chunk
# should take well under a second: equilibrium ~2 us/point (DW) to ~50 us/point (MD near
# its limits), critical forces ~1 ms (DW) to ~50 ms (MD) per mu. Calls this size or
# smaller are one facade call, exactly as before chunking.
_CHUNK_POINTS = 4096


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
    a = float_array(a, "a")
    if a.size == 0:
        return np.empty(a.shape)
    a_f = flat_f64(a)
    if a_f.size <= _CHUNK_POINTS:
        p, nfail, ifail, status, message = _f.fa_westergaard_load(a_f)
        if nfail:
            raise_status(status, message, at_index(ifail, a.shape))
        return shaped(p, a.shape)
    p = np.empty(a_f.size)
    for sl in chunk_slices(a_f.size, _CHUNK_POINTS):
        p[sl], nfail, ifail, status, message = _f.fa_westergaard_load(a_f[sl])
        if nfail:
            raise_status(status, message, at_index(sl.start + ifail, a.shape))
    return shaped(p, a.shape)


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
    alpha = float_array(alpha, "alpha")
    a = float_array(a, "a")
    alpha_b, a_b = np.broadcast_arrays(alpha, a)
    if a_b.size == 0:
        return np.empty(a_b.shape)
    alpha_f, a_f = flat_f64(alpha_b), flat_f64(a_b)
    if a_f.size <= _CHUNK_POINTS:
        p, nfail, ifail, status, message = _f.fa_jkr_load(alpha_f, a_f)
        if nfail:
            raise_status(status, message, at_index(ifail, a_b.shape))
        return shaped(p, a_b.shape)
    p = np.empty(a_f.size)
    for sl in chunk_slices(a_f.size, _CHUNK_POINTS):
        p[sl], nfail, ifail, status, message = _f.fa_jkr_load(alpha_f[sl], a_f[sl])
        if nfail:
            raise_status(status, message, at_index(sl.start + ifail, a_b.shape))
    return shaped(p, a_b.shape)


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
    code = model_code(model)
    if errors not in ("raise", "nan"):
        raise InvalidArgumentError(f"errors = {errors!r} is not 'raise' or 'nan'", 1)
    alpha_b, mu_b, a_b = np.broadcast_arrays(
        float_array(alpha, "alpha"), float_array(mu, "mu"), float_array(a, "a")
    )
    shape = a_b.shape
    if a_b.size == 0:
        return Equilibrium(np.empty(shape), np.empty(shape), np.empty(shape, np.int32),
                           np.empty(shape))
    alpha_f, mu_f, a_f = flat_f64(alpha_b), flat_f64(mu_b), flat_f64(a_b)
    if a_f.size <= _CHUNK_POINTS:
        c, p, z, g, nfail, ifail, status, message = _f.fa_equilibrium(code, alpha_f, mu_f, a_f)
        if nfail and errors == "raise":
            raise_status(status, message, at_index(ifail, shape))
        return Equilibrium(shaped(c, shape), shaped(p, shape), shaped(z, shape),
                           shaped(g, shape))
    c = np.empty(a_f.size)
    p = np.empty(a_f.size)
    z = np.empty(a_f.size, dtype=np.int32)
    g = np.empty(a_f.size)
    for sl in chunk_slices(a_f.size, _CHUNK_POINTS):     # Ctrl-C is seen between chunks
        c[sl], p[sl], z[sl], g[sl], nfail, ifail, status, message = _f.fa_equilibrium(
            code, alpha_f[sl], mu_f[sl], a_f[sl])
        if nfail and errors == "raise":
            raise_status(status, message, at_index(sl.start + ifail, shape))
    return Equilibrium(shaped(c, shape), shaped(p, shape), shaped(z, shape),
                       shaped(g, shape))


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
    code = model_code(model)
    values = []
    for name, x in (("alpha", alpha), ("mu", mu), ("a_star", a_star)):
        arr = float_array(x, name)
        if arr.ndim != 0:
            raise InvalidArgumentError(f"{name} must be a scalar (roots works at one point)", 1)
        values.append(float(arr))
    alpha, mu, a_star = values
    c, p, z, gap, g, n, _, _ = grown(_f.fa_roots, _ROOTS_CAPACITY, 5, code, alpha, mu, a_star)
    return [
        State(a_star, float(c[k]), float(p[k]), int(z[k]), float(gap[k]), float(g[k]))
        for k in range(n)
    ]


