"""The dimensionless parameters (alpha, mu) and the SI scales of a problem."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Optional

from . import _wa_f2py as _f
from ._args import real_scalar
from ._errors import OK, InvalidArgumentError, raise_status


@dataclass(frozen=True)
class Scales:
    """SI scales that turn dimensionless results back into physical ones (a result's
    ``to_si(params)`` uses them).

    Attributes
    ----------
    estar : float
        Reduced modulus E* [Pa].
    pressure : float
        p* = pi E* Delta / L [Pa]: mean traction = P* * pressure.
    force : float
        p* L [N/m]: force per period and unit depth = P* * force.
    length : float
        Period L [m]: a = a* L, c = c* L, x = x* L.
    radius : float
        Crest radius R = L^2 / (4 pi^2 Delta) [m].
    amplitude : float
        Amplitude Delta [m]: mean gap = gbar* * amplitude, gap = h* * amplitude.
        Optional for backward compatibility: given 5 values, it is p* L / (pi E*).
    energy : float
        p* Delta [J/m^2] (a property): energy lost per cycle and unit area = W* * energy.
    stiffness : float
        p* / Delta [Pa/m] (a property): dP/dgbar = dP*/dgbar* * stiffness.
    """

    estar: float
    pressure: float
    force: float
    length: float
    radius: float
    amplitude: Optional[float] = None

    def __post_init__(self):
        if self.amplitude is None:
            object.__setattr__(self, "amplitude",
                               self.pressure * self.length / (math.pi * self.estar))

    @property
    def energy(self) -> float:
        """p* Delta [J/m^2], the unit of W* and of the jump energies."""
        return self.pressure * self.amplitude

    @property
    def stiffness(self) -> float:
        """p* / Delta [Pa/m], the unit of dP*/dgbar*."""
        return self.pressure / self.amplitude


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
        alpha = real_scalar(self.alpha, "alpha")
        mu = real_scalar(self.mu, "mu")
        sigma0, dcod, status, message = _f.fa_params(alpha, mu)
        if status != OK:
            raise_status(status, message)
        object.__setattr__(self, "alpha", alpha)
        object.__setattr__(self, "mu", mu)
        object.__setattr__(self, "sigma0", float(sigma0))
        object.__setattr__(self, "dcod", float(dcod))

    @classmethod
    def from_dimensional(
        cls,
        *,
        E1: Optional[float] = None,
        nu1: Optional[float] = None,
        E2: Optional[float] = None,
        nu2: Optional[float] = None,
        Estar: Optional[float] = None,
        period: float,
        amplitude: float,
        work_of_adhesion: float,
        peak_stress: float,
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
                *(real_scalar(v, k) for k, v in moduli.items()))
            if status != OK:
                raise_status(status, message)
        else:
            given = [k for k, v in moduli.items() if v is not None]
            if given:
                raise InvalidArgumentError(
                    f"give Estar or E1, nu1, E2, nu2, not both (got Estar and "
                    f"{', '.join(given)})", 1)
            estar = real_scalar(Estar, "Estar")
        out = _f.fa_dimensional(
            float(estar), real_scalar(period, "period"), real_scalar(amplitude, "amplitude"),
            real_scalar(work_of_adhesion, "work_of_adhesion"), real_scalar(peak_stress, "peak_stress"),
        )
        alpha, mu, sigma0, dcod, pressure, force, length, radius, status, message = out
        if status != OK:
            raise_status(status, message)
        scales = Scales(float(estar), float(pressure), float(force), float(length),
                        float(radius), real_scalar(amplitude, "amplitude"))
        return cls(float(alpha), float(mu), scales)

    def __repr__(self) -> str:
        extra = "" if self.scales is None else f", scales={self.scales!r}"
        return (f"Params(alpha={self.alpha!r}, mu={self.mu!r}, sigma0={self.sigma0!r}, "
                f"dcod={self.dcod!r}{extra})")


