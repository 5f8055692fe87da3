"""The equilibrium branch P*(a*) traced through its folds."""

from __future__ import annotations

from dataclasses import dataclass
from typing import List, NamedTuple, Optional, Union

import numpy as np
from numpy.typing import ArrayLike

from . import _wa_f2py as _f
from ._args import grown, model_code, model_name, real_scalar
from ._lj import LJBranch, is_lj, lj_trace_branch, reject_lj_inputs
from ._results import ResultMixin

# Points asked for in a first trace_branch() call. Branches have a few hundred points
# (at most 1320 over DW and MD, alpha 0.1-3, mu 0.01-30); a longer one (the library
# allows 20000) is traced again into arrays of the exact size. Room for 20000 at once
# would cost ~0.5 ms per call in array set-up (1.55 vs 1.03 ms for a DW branch).
_BRANCH_CAPACITY = 4096

#: Event codes of branch points and load-path events (include/wavyadhesion.h, doc/user-guide.md).
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


@dataclass(frozen=True, eq=False, repr=False)
class Branch(ResultMixin):
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

    _columns = ("a_star", "c_star", "P_star", "b_star", "zone_case", "stable", "event",
                "extremum", "gbar")
    _repr_fields = ("model", "alpha", "mu", "points", "folds_P")

    @property
    def points(self) -> int:
        """The number of points (``len(branch)``)."""
        return len(self)

    @property
    def folds_P(self) -> np.ndarray:
        """P* at the folds, in order (the critical values of the branch)."""
        return np.array([e.P_star for e in self.folds])

    def __len__(self) -> int:
        return int(self.a_star.size)

    @property
    def events(self) -> List[BranchEvent]:
        """Every point with an event, in order, as :class:`BranchEvent`."""
        return [
            BranchEvent(int(i), EVENTS[int(self.event[i])], float(self.a_star[i]),
                        float(self.c_star[i]), float(self.P_star[i]), int(self.zone_case[i]))
            for i in np.flatnonzero(self.event)
        ]

    @property
    def folds(self) -> List[BranchEvent]:
        """The folds (dP*/da* = 0), in order along the curve."""
        return [e for e in self.events if e.kind == "fold"]

    @property
    def switches(self) -> List[BranchEvent]:
        """The zone-case switches (c* reaching or leaving 1/2)."""
        return [e for e in self.events if e.kind == "switch"]


def trace_branch(model: str, alpha: float, mu: float, *, n: Optional[int] = None,
                 profile: Optional[ArrayLike] = None
                 ) -> Union[Branch, LJBranch]:
    """The equilibrium branch P*(a*), c*(a*) over 0 < a* <= 1/2, with its folds and
    zone-case switches.

    DW and MD: pseudo-arclength continuation with adaptive steps through every fold,
    switching zone case where c* reaches 1/2; folds and switches are located as points
    of their own. Westergaard and JKR: the closed form sampled at 201 points, JKR's
    folds located. The whole branch is computed in one Fortran call (GIL released).

    Parameters
    ----------
    model : {"westergaard", "jkr", "dw", "md", "lj"}
        The contact model ("lj": the smooth Lennard-Jones model, doc/theory.md "Smooth
        adhesion"; it returns an :class:`LJBranch`, traced from far apart to full contact).
    alpha : float
        Johnson's parameter, alpha > 0.
    mu : float
        Transition parameter, mu >= 0 (lj: mu > 0).
    n, profile : optional
        ``model="lj"`` only: the grid and the surface samples, as in :func:`load_path`.

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
    ResolutionError
        (model="lj") The grid refuses `n` (beyond its cap) or the automatic grid's zone
        needs more than 2048 points; the message names the N or the cap.
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
    if is_lj(model):
        return lj_trace_branch(alpha, mu, n, profile)
    reject_lj_inputs(n, profile)
    code = model_code(model)
    alpha = real_scalar(alpha, "alpha")
    mu = real_scalar(mu, "mu")
    out = grown(_f.fa_trace_branch, _BRANCH_CAPACITY, 9, code, alpha, mu)
    a, c, p, b, z, st, ev, ex, g, n, _, _ = out
    n = int(n)
    return Branch(model_name(code), alpha, mu, a[:n].copy(), c[:n].copy(), p[:n].copy(),
                  b[:n].copy(), z[:n].copy(), st[:n].astype(bool), ev[:n].copy(),
                  ex[:n].copy(), g[:n].copy())


