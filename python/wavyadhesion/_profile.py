"""Traction and gap profiles of one equilibrium state."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Optional

import numpy as np
from numpy.typing import ArrayLike

from . import _wa_f2py as _f
from ._args import (at_index, chunk_slices, flat_f64, float_array, model_code, model_name,
                    real_scalar)
from ._errors import INVALID_ARGUMENT, OK, InvalidArgumentError, raise_status
from ._lj import is_lj, lj_profile, reject_lj_inputs
from ._results import ResultMixin, TupleCompat

# Points per facade call (Ctrl-C is seen between two calls).
_CHUNK_POINTS = 4096


@dataclass(frozen=True, eq=False, repr=False)
class Profile(TupleCompat, ResultMixin):
    """Traction and gap profiles of one state (:func:`profile`); unpacks as
    ``x, traction, gap`` (it was a named tuple of these three).

    Attributes
    ----------
    x : numpy.ndarray of float
        The points x* = x/L (period 1, crest at x* = 0).
    traction : numpy.ndarray of float
        p(x)/p* (positive = compressive; its mean over a period is P*). JKR: -inf exactly
        at the contact edges |x*| = a*.
    gap : numpy.ndarray of float
        h(x)/Delta >= 0 (0 on the contact; its mean over a period is gbar*).
    model : str
    alpha, mu, a_star : float
        The inputs.
    c_star, P_star, gbar : float
        The state drawn: its interaction-zone half-width, load and mean gap.
    zone_case : int
        Its zone case.
    b_star : float
        ``model="lj"``: the state's b* (half the measure of {h <= 3^(1/6) eps}; a_star is
        then the state's a*, c_star and zone_case are None).
    N : int
        ``model="lj"``: grid points per period (the points of the profile).
    """

    x: np.ndarray
    traction: np.ndarray
    gap: np.ndarray
    model: Optional[str] = None
    alpha: Optional[float] = None
    mu: Optional[float] = None
    a_star: Optional[float] = None
    c_star: Optional[float] = None
    P_star: Optional[float] = None
    zone_case: Optional[int] = None
    gbar: Optional[float] = None
    b_star: Optional[float] = None
    N: Optional[int] = None

    _tuple_fields = ("x", "traction", "gap")
    _columns = ("x", "traction", "gap")
    _coordinates = ("model", "alpha", "mu", "a_star", "c_star", "P_star", "zone_case", "gbar",
                    "b_star", "N")
    _repr_fields = ("model", "alpha", "mu", "a_star", "c_star", "P_star", "x")


#: Points of profile()'s default grid of x* over [-1/2, 1/2].
_PROFILE_POINTS = 401


def profile(model: str, alpha: float, mu: float, a_star: float,
            c_star: Optional[float] = None, x: Optional[ArrayLike] = None, *,
            n: Optional[int] = None, profile: Optional[ArrayLike] = None) -> Profile:
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
    n, profile : optional
        ``model="lj"`` only: the grid and the surface samples, as in :func:`load_path`.
        The state is then the traced one with a* nearest `a_star` (among the load-stable
        states when there are any), drawn at the N grid nodes from x* = -1/2 (`c_star`
        and `x` must be None).

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
    ResolutionError
        (model="lj") The grid refuses `n` (beyond its cap) or the automatic grid's zone
        needs more than 2048 points; the message names the N or the cap.
    ConvergenceError
        The solver failed.

    Examples
    --------
    >>> x, t, h = profile("dw", 0.3, 1.0, 0.2)
    >>> bool(h.min() >= 0 and h[200] == 0)
    True
    """
    if is_lj(model):
        if c_star is not None or x is not None:
            raise InvalidArgumentError("c_star and x do not apply to model='lj' (no zone "
                                       "edge; the profile is drawn at the grid nodes)",
                                       INVALID_ARGUMENT)
        xs, t, h, n_period, (a, b, p, g) = lj_profile(alpha, mu, a_star, n, profile)
        return Profile(xs, t, h, "lj", float(alpha), float(mu), a, None, p, None, g, b,
                       n_period)
    reject_lj_inputs(n, profile)
    code = model_code(model)
    alpha = real_scalar(alpha, "alpha")
    mu = real_scalar(mu, "mu")
    a_star = real_scalar(a_star, "a_star")
    principal = c_star is None
    c_value = 0.0 if principal else real_scalar(c_star, "c_star")
    if x is None:
        x = np.linspace(-0.5, 0.5, _PROFILE_POINTS)
    x = float_array(x, "x")
    shape = x.shape
    x_f = flat_f64(x)
    bad = np.flatnonzero(~np.isfinite(x_f))
    if bad.size:
        where = at_index(int(bad[0]) + 1, shape)
        raise InvalidArgumentError(
            f"x: every value must be finite (any finite x* is valid: the period is 1); got "
            f"{x_f[bad[0]]!r}{' ' + where if where else ''}", INVALID_ARGUMENT)
    t = np.empty(x_f.size)
    h = np.empty(x_f.size)
    chunks = list(chunk_slices(x_f.size, _CHUNK_POINTS)) or [slice(0, 0)]
    for sl in chunks:                                 # Ctrl-C is seen between chunks
        out = _f.fa_profile(code, alpha, mu, a_star, c_value, int(principal), x_f[sl])
        t[sl], h[sl], sc, sp, sz, sg, status, message = out
        if status != OK:
            raise_status(status, message)
    return Profile(x_f.reshape(shape).copy(), t.reshape(shape), h.reshape(shape),
                   model_name(code), alpha, mu, a_star, float(sc), float(sp), int(sz),
                   float(sg))


