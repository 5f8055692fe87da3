"""Equilibrium states at given contact half-widths: the closed-form loads, the
principal state (vectorised) and every state at one point."""

from __future__ import annotations

from typing import List, NamedTuple, Optional

import numpy as np
from numpy.typing import ArrayLike

from . import _wa_f2py as _f
from ._args import (at_index, chunk_slices, flat_f64, float_array, grown, model_code,
                    model_name, renamed_keyword, shaped)
from ._errors import InvalidArgumentError, raise_status
from ._results import ResultMixin, TupleCompat

# States asked for in a first roots() call; more are fetched in a second call.
_ROOTS_CAPACITY = 16

# Points per facade call in the vectorised functions. Between two calls Python runs and
# raises KeyboardInterrupt on Ctrl-C (a Fortran call cannot be interrupted), so a chunk
# should take well under a second: equilibrium ~2 us/point (DW) to ~50 us/point (MD near
# its limits), critical forces ~1 ms (DW) to ~50 ms (MD) per mu. Calls this size or
# smaller are one facade call, exactly as before chunking.
_CHUNK_POINTS = 4096


class _EquilibriumFields(NamedTuple):
    c_star: np.ndarray
    P_star: np.ndarray
    zone_case: np.ndarray
    gbar: np.ndarray
    a_star: Optional[np.ndarray] = None
    alpha: Optional[np.ndarray] = None
    mu: Optional[np.ndarray] = None
    model: Optional[str] = None


class Equilibrium(_EquilibriumFields):
    """Principal equilibrium states (numpy arrays of the broadcast shape). Unpacks as
    ``c_star, P_star, zone_case, gbar`` (it was a named tuple of these four); has
    ``to_si(params)``, ``to_dataframe()`` and a short repr.

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
    a_star, alpha, mu : numpy.ndarray of float
        The coordinates: the inputs broadcast to the same shape.
    model : str
        The model name.
    """

    # a named tuple underneath (built in ~0.3 us: equilibrium is called point by point);
    # unpacking, len() and indexing see the four fields it had before the coordinates
    __slots__ = ()
    _tuple_fields = ("c_star", "P_star", "zone_case", "gbar")
    __iter__ = TupleCompat.__iter__
    __len__ = TupleCompat.__len__
    __getitem__ = TupleCompat.__getitem__
    _asdict = TupleCompat._asdict
    to_si = ResultMixin.to_si
    to_dataframe = ResultMixin.to_dataframe
    _field_items = ResultMixin._field_items
    __repr__ = ResultMixin.__repr__

    def __getnewargs__(self):
        return tuple.__getitem__(self, slice(None))        # every field (pickle, copy)
    _columns = ("a_star", "alpha", "mu", "c_star", "P_star", "zone_case", "gbar")
    _coordinates = ("model",)
    _repr_fields = ("model", "alpha", "mu", "a_star", "P_star")


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


@renamed_keyword("a", "a_star")
def westergaard_load(a_star: ArrayLike) -> np.ndarray:
    """Westergaard load P* = sin^2(pi a*) (no adhesion).

    Parameters
    ----------
    a_star : array_like
        Contact half-width over the period, a* in [0, 1/2] (the keyword ``a`` is
        deprecated).

    Returns
    -------
    numpy.ndarray or numpy.float64
        P*, same shape as `a_star`.

    Raises
    ------
    InvalidArgumentError
        If any a* is NaN or outside [0, 1/2].

    Examples
    --------
    >>> westergaard_load([0.0, 0.25, 0.5]).round(12)
    array([0. , 0.5, 1. ])
    """
    a = float_array(a_star, "a_star")
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


@renamed_keyword("a", "a_star")
def jkr_load(alpha: ArrayLike, a_star: ArrayLike) -> np.ndarray:
    """JKR load of the wavy surface (Johnson 1995), P* = sin^2(pi a*) - alpha sqrt(tan(pi a*)).

    Parameters
    ----------
    alpha : array_like
        Johnson's parameter, alpha >= 0.
    a_star : array_like
        Contact half-width over the period, a* in [0, 1/2]; broadcast with `alpha` (the
        keyword ``a`` is deprecated).

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
    a = float_array(a_star, "a_star")
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


@renamed_keyword("a", "a_star")
def equilibrium(model: str, alpha: ArrayLike, mu: ArrayLike, a_star: ArrayLike, *,
                errors: str = "raise") -> Equilibrium:
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
    a_star : array_like
        Contact half-width over the period, a* in [0, 1/2] (the keyword ``a`` is
        deprecated).
    errors : {"raise", "nan"}, optional
        "raise" (default): raise on the first point that fails. "nan": return NaN
        (zone case 0) at failed points and raise nothing.

    Returns
    -------
    Equilibrium
        ``c_star, P_star, zone_case, gbar`` (it unpacks as these four) and the
        coordinates ``a_star, alpha, mu``: arrays of the broadcast shape of `alpha`, `mu`
        and `a_star` (numpy scalars when all three are scalars).

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
        float_array(alpha, "alpha"), float_array(mu, "mu"), float_array(a_star, "a_star")
    )
    shape = a_b.shape
    if a_b.size == 0:
        return Equilibrium(np.empty(shape), np.empty(shape), np.empty(shape, np.int32),
                           np.empty(shape), np.empty(shape), np.empty(shape),
                           np.empty(shape), model_name(code))
    alpha_f, mu_f, a_f = flat_f64(alpha_b), flat_f64(mu_b), flat_f64(a_b)
    if shape:
        coords = (a_f.reshape(shape).copy(), alpha_f.reshape(shape).copy(),
                  mu_f.reshape(shape).copy(), model_name(code))
    else:                                            # numpy scalars, as the values
        coords = (a_f[0], alpha_f[0], mu_f[0], model_name(code))
    if a_f.size <= _CHUNK_POINTS:
        c, p, z, g, nfail, ifail, status, message = _f.fa_equilibrium(code, alpha_f, mu_f, a_f)
        if nfail and errors == "raise":
            raise_status(status, message, at_index(ifail, shape))
        return Equilibrium(shaped(c, shape), shaped(p, shape), shaped(z, shape),
                           shaped(g, shape), *coords)
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
                       shaped(g, shape), *coords)


def roots(model: str, alpha: float, mu: float, a_star: float) -> List[State]:
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


