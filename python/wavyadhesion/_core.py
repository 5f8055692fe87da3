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

__all__ = [
    "MODELS",
    "Equilibrium",
    "State",
    "Scales",
    "Params",
    "WavyAdhesionError",
    "InvalidArgumentError",
    "ConvergenceError",
    "NoSolutionError",
    "westergaard_load",
    "jkr_load",
    "equilibrium",
    "roots",
]

#: Model names and the library's integer constants (include/wavyadhesion.h).
MODELS = {"westergaard": 0, "jkr": 1, "dw": 2, "md": 3}

# Status codes of the library (src/wa_status.f90).
_OK, _INVALID_ARGUMENT, _NO_SOLUTION, _NOT_CONVERGED = 0, 1, 2, 3
_CAPACITY_TOO_SMALL, _NUMERICAL_ERROR = 4, 5

# States asked for in a first roots() call; more are fetched in a second call.
_ROOTS_CAPACITY = 16


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


def _model_code(model) -> int:
    if isinstance(model, str) and model.lower() in MODELS:
        return MODELS[model.lower()]
    raise InvalidArgumentError(
        f"model = {model!r} is not one of {', '.join(map(repr, MODELS))}", _INVALID_ARGUMENT
    )


def _float_array(x, name: str) -> np.ndarray:
    try:
        arr = np.asarray(x, dtype=np.float64)
    except (TypeError, ValueError) as exc:
        raise InvalidArgumentError(f"{name}: not convertible to float ({exc})", 1) from None
    return arr


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
    """

    c_star: np.ndarray
    P_star: np.ndarray
    zone_case: np.ndarray


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
    """

    a_star: float
    c_star: float
    P_star: float
    zone_case: int
    gap_width: float


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
    p, nfail, ifail, status, message = _f.fa_westergaard_load(_flat(a))
    if nfail:
        _raise(status, message, _where(ifail, a.shape))
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
    p, nfail, ifail, status, message = _f.fa_jkr_load(_flat(alpha_b), _flat(a_b))
    if nfail:
        _raise(status, message, _where(ifail, a_b.shape))
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
        Named tuple ``(c_star, P_star, zone_case)`` of arrays of the broadcast shape of
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
        return Equilibrium(np.empty(shape), np.empty(shape), np.empty(shape, np.int32))
    c, p, z, nfail, ifail, status, message = _f.fa_equilibrium(
        code, _flat(alpha_b), _flat(mu_b), _flat(a_b)
    )
    if nfail and errors == "raise":
        _raise(status, message, _where(ifail, shape))
    return Equilibrium(_shaped(c, shape), _shaped(p, shape), _shaped(z, shape))


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
    capacity = _ROOTS_CAPACITY
    while True:
        c, p, z, gap, n, status, message = _f.fa_roots(capacity, code, alpha, mu, a_star)
        if status == _CAPACITY_TOO_SMALL and n > capacity:
            capacity = int(n)
            continue
        break
    if status != _OK:
        _raise(status, message)
    return [
        State(a_star, float(c[k]), float(p[k]), int(z[k]), float(gap[k])) for k in range(n)
    ]


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
    """

    alpha: float
    mu: float
    scales: Optional[Scales] = None
    sigma0: float = field(init=False)
    dcod: float = field(init=False)

    def __post_init__(self):
        alpha = float(_float_array(self.alpha, "alpha"))
        mu = float(_float_array(self.mu, "mu"))
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

        Examples
        --------
        >>> p = Params.from_dimensional(Estar=1e6, period=1e-3, amplitude=1e-5,
        ...                             work_of_adhesion=0.05, peak_stress=1e5)
        >>> round(p.alpha, 6)
        0.31831
        """
        moduli = (E1, nu1, E2, nu2)
        if Estar is None:
            if any(v is None for v in moduli):
                raise InvalidArgumentError("give Estar, or all of E1, nu1, E2 and nu2", 1)
            estar, status, message = _f.fa_reduced_modulus(*map(float, moduli))
            if status != _OK:
                _raise(status, message)
        else:
            if any(v is not None for v in moduli):
                raise InvalidArgumentError("give Estar or E1, nu1, E2, nu2, not both", 1)
            estar = Estar
        out = _f.fa_dimensional(
            float(estar), float(period), float(amplitude), float(work_of_adhesion),
            float(peak_stress),
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
