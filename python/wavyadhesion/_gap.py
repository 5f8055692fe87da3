"""Gap (mean-gap) control: one approach-retraction cycle (:func:`gap_path`) and the
gap law P*(gbar*) (:func:`gap_law`)."""

from __future__ import annotations

from typing import List, NamedTuple, Optional, Tuple, Union

import numpy as np
from numpy.typing import ArrayLike

from . import _wa_f2py as _f
from ._args import (PATH_CAPACITY, chunk_slices, float_array, grown, index_text, model_code,
                    model_name, real_scalar)
from ._lj import LJGapPath, is_lj, lj_gap_path, reject_lj_inputs
from ._results import ResultMixin
from ._errors import INVALID_ARGUMENT, OK, InvalidArgumentError, raise_status

# gap_law: each call walks the cycle again (~1-2 ms), then ~3 us per mean gap (MD), so
# a chunk of 65536 gaps takes ~0.2 s and repeats the walk for < 1 % of the time; the
# values at each gap and W* do not depend on the other gaps of the call.
_CHUNK_GAPS = 65536

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
    model: Optional[str] = None
    alpha: Optional[float] = None
    mu: Optional[float] = None

    to_si = ResultMixin.to_si
    to_dataframe = ResultMixin.to_dataframe
    _field_items = ResultMixin._field_items
    __repr__ = ResultMixin.__repr__
    _columns = ("gbar", "P_approach", "P_retract", "dPdg_approach", "dPdg_retract")
    _coordinates = ("model", "alpha", "mu", "W_star", "W_fraction")
    _repr_fields = ("model", "alpha", "mu", "gbar", "W_star", "W_fraction")


def gap_law(model: str, alpha: float, mu: float, gbar: ArrayLike) -> GapLaw:
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
        Arrays of the shape of ``gbar`` and the floats ``W_star``, ``W_fraction``;
        ``model``, ``alpha``, ``mu``. ``to_si(params)`` gives gbar in m, loads in Pa and
        N/m, the slopes in Pa/m and W in J/m^2.

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
    code = model_code(model)
    alpha = real_scalar(alpha, "alpha")
    mu = real_scalar(mu, "mu")
    g = float_array(gbar, "gbar")
    shape = g.shape
    flat = np.ascontiguousarray(g.reshape(-1))
    if flat.size == 0:
        raise InvalidArgumentError("gbar is empty: give at least one mean gap",
                                   INVALID_ARGUMENT)
    with np.errstate(invalid="ignore"):
        bad = np.flatnonzero(~(np.isfinite(flat) & (flat >= 0)))
    if bad.size:                     # the library's word on it, with the index and value
        i = int(bad[0])
        *_, status, message = _f.fa_gap_law(code, alpha, mu, flat[i:i + 1])
        if status != OK:
            raise_status(status, message, f"gbar[{index_text(i, shape)}] = {float(flat[i])!r}" if shape
                   else f"gbar = {float(flat[i])!r}")
    outputs = [np.empty(flat.size) for _ in range(4)]
    for sl in chunk_slices(flat.size, _CHUNK_GAPS):       # Ctrl-C is seen between chunks
        *values, w, wf, status, message = _f.fa_gap_law(code, alpha, mu, flat[sl])
        if status != OK:
            raise_status(status, message)
        for out, v in zip(outputs, values):
            out[sl] = v
    pa, pr, da, dr = outputs
    return GapLaw(g.copy(), pa.reshape(shape), pr.reshape(shape), da.reshape(shape),
                  dr.reshape(shape), float(w), float(wf), model_name(code), alpha, mu)


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
    model: Optional[str] = None
    alpha: Optional[float] = None
    mu: Optional[float] = None

    to_si = ResultMixin.to_si
    to_dataframe = ResultMixin.to_dataframe
    _field_items = ResultMixin._field_items
    __repr__ = ResultMixin.__repr__
    _columns = ("stage", "event", "zone_case", "a_star", "c_star", "P_star", "gbar")
    _coordinates = ("model", "alpha", "mu", "W_star", "W_fraction", "g_touch")
    _repr_fields = ("model", "alpha", "mu", "events_n", "W_star", "W_fraction", "g_touch")

    @property
    def events_n(self) -> int:
        """The number of events."""
        return int(np.size(self.event))

    @property
    def events(self) -> List[Tuple[str, str, float, float]]:
        """The events as (stage name, event name, gbar*, P*) tuples."""
        return [(GAP_STAGES[int(s)], GAP_EVENTS.get(int(e), str(int(e))), float(g), float(p))
                for s, e, g, p in zip(self.stage, self.event, self.gbar, self.P_star)]


def gap_path(model: str, alpha: float, mu: float, *, n: Optional[int] = None,
             profile: Optional[ArrayLike] = None
             ) -> Union[GapPath, LJGapPath]:
    """Approach from far apart to full contact and retraction under gap control, with
    the energy lost per cycle: the events (first interaction, jumps at constant gbar*,
    contact made or lost, full contact reached or left, interaction lost) with their
    states.

    Parameters
    ----------
    model : {"westergaard", "jkr", "dw", "md", "lj"}
        The contact model ("lj": an :class:`LJGapPath`, with W* and its error estimate
        W_star_err).
    alpha, mu : float
        Johnson's parameter (> 0) and the transition parameter (>= 0; lj: > 0).
    n, profile : optional
        ``model="lj"`` only: the grid and the surface samples, as in :func:`load_path`.

    Returns
    -------
    GapPath
        The events (``stage, event, zone_case, a_star, c_star, P_star, gbar``, one
        element each), ``W_star``, ``W_fraction``, ``g_touch`` and ``model``, ``alpha``,
        ``mu``.

    Raises
    ------
    InvalidArgumentError
        Unknown model, or alpha or mu outside its range.
    ResolutionError
        (model="lj") The grid refuses `n` (beyond its cap) or the automatic grid's zone
        needs more than 2048 points; the message names the N or the cap.
    ConvergenceError
        The continuation or a point solve failed.

    Examples
    --------
    >>> path = gap_path("md", 0.3, 1.0)
    >>> path.events[0][:2], round(path.W_star, 10)
    (('approach', 'touch'), 0.0070144396)
    """
    if is_lj(model):
        return lj_gap_path(alpha, mu, n, profile)
    reject_lj_inputs(n, profile)
    code = model_code(model)
    alpha = real_scalar(alpha, "alpha")
    mu = real_scalar(mu, "mu")
    out = grown(_f.fa_gap_path, PATH_CAPACITY, 7, code, alpha, mu)
    stage, ev, zone, a, c, p, g, n, w, wf, gt, _, _ = out
    n = int(n)
    return GapPath(stage[:n].copy(), ev[:n].copy(), zone[:n].copy(), a[:n].copy(),
                   c[:n].copy(), p[:n].copy(), g[:n].copy(), float(w), float(wf), float(gt),
                   model_name(code), alpha, mu)
