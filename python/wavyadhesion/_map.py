"""The adhesion map of the (alpha, mu) plane (Fortran ``adhesion_map``, wa_map.f90)."""

from __future__ import annotations

from dataclasses import dataclass, field
from concurrent.futures import Executor
from typing import Any, Callable, Optional, Tuple, Union

import numpy as np
from numpy.typing import ArrayLike

from . import _wa_f2py as _f
from ._args import (ALPHA_MAX, ALPHA_MIN, C_INT_MAX, MAP_CELLS_MAX, MAP_N_ALPHA_MAX, MAP_N_MU_MAX,
                    MODELS, MU_MAX, MU_MIN, count_in, float_array, model_code, real_in)
from ._errors import INVALID_ARGUMENT, OK, InvalidArgumentError, InvalidTypeError, raise_status
from ._loadpath import critical_forces
from ._parallel import Background, call_interruptibly, iter_chunks, make_progress, run_chunks

#: Mechanism names by code (full contact: 0..3; pull-off: 0..2).
_NAMES = ("gradual", "jump case 1", "jump case 2", "snap at P=0")
#: Gap control (wa_gapmech): approach (which 3) and retraction (which 4) mechanisms, sums of
#: 1 (contact made / lost by a jump) and 2 (jumps between states with contact).
GAP_APPROACH_NAMES = ("gradual", "jump-in", "gradual+inner jumps", "jump-in+inner jumps")
GAP_RETRACTION_NAMES = ("gradual", "jump-out", "inner jumps+gradual", "inner jumps+jump-out")
#: The ``control`` values of :func:`adhesion_map`
CONTROLS = {"load": 1, "gap": 2, "both": 3}
#: How a curve starts or ends.
END_KINDS = ("grid edge", "inside (meets another boundary or turns)", "leaves the mu range",
             "load path fails")


def boundary_meaning(code: int) -> str:
    """'full contact: gradual -> jump case 1' for code 101, and so on: code = 100*which +
    10*(mechanism below) + (mechanism above) in mu, which 1 full contact, 2 pull-off.
    Gap control: which 3 approach, 4 retraction ('gap retraction: gradual -> jump-out'
    for 401; mechanisms in GAP_APPROACH_NAMES, GAP_RETRACTION_NAMES).
    Codes from 1000 (Python only, ``forces=True``): 1000 + the same, for a boundary
    crossed in alpha (mechanism left -> right as alpha grows) at fixed mu."""
    in_alpha = code >= 1000
    code = code - 1000 if in_alpha else code
    which, lo, hi = code // 100, code // 10 % 10, code % 10
    if which not in (1, 2, 3, 4) or lo > 3 or hi > 3 or lo == hi or code < 0:
        return "unknown"
    if which == 3:
        return f"gap approach: {GAP_APPROACH_NAMES[lo]} -> {GAP_APPROACH_NAMES[hi]}"
    if which == 4:
        return f"gap retraction: {GAP_RETRACTION_NAMES[lo]} -> {GAP_RETRACTION_NAMES[hi]}"
    text = f"{'full contact' if which == 1 else 'pull-off'}: {_NAMES[lo]} -> {_NAMES[hi]}"
    return text + (" (as alpha grows, at fixed mu)" if in_alpha else "")


@dataclass(frozen=True)
class Boundary:
    """One boundary curve mu_b(alpha): ``code`` (see :func:`boundary_meaning`), the
    points ``alpha``, ``mu`` (increasing alpha), and how it starts and ends
    (``start``, ``end``: indices into ``END_KINDS``)."""

    code: int
    alpha: np.ndarray
    mu: np.ndarray
    start: int
    end: int

    @property
    def meaning(self) -> str:
        return boundary_meaning(self.code)


#: Kinds of special points (wa_map's map_point_*), by code.
SPECIAL_KINDS = {1: "meet", 2: "turn", 3: "end", 4: "load path fails"}


@dataclass(frozen=True)
class SpecialPoint:
    """Where boundaries meet (``kind`` "meet"), where one turns back in alpha ("turn": it
    meets its reverse, e.g. 212 and 221, and the region between closes), where one ends
    alone ("end": its region closes), or where the load path fails; ``codes`` are the
    boundary codes involved (one or two), ``meaning`` says it in words."""

    kind: str
    alpha: float
    mu: float
    codes: tuple

    @property
    def meaning(self) -> str:
        first = boundary_meaning(self.codes[0])
        if self.kind == "meet":
            return f"{first} meets {boundary_meaning(self.codes[1])}"
        if self.kind == "turn":
            return (f"{first} turns back in alpha (meets its reverse {self.codes[1]}; "
                    "the region between closes)")
        if self.kind == "end":
            return f"{first} ends (its region closes)"
        return f"{first}: the load path fails here"


@dataclass(frozen=True, repr=False)
class AdhesionMap:
    """Boundaries and regions of one model over an (alpha, mu) grid.

    ``fc_region`` and ``pf_region`` have shape (len(mu), len(alpha)): the full-contact and
    pull-off mechanism codes (0 gradual, 1 jump case 1, 2 jump case 2, 3 snap; -1 where
    the load path failed): computed at the scanned alpha and filled from the boundary
    curves elsewhere, or, with ``forces=True``, computed in every cell. ``ga_region``,
    ``gr_region`` (``control`` "gap" or "both", else None): the gap-control approach and
    retraction mechanisms (GAP_APPROACH_NAMES, GAP_RETRACTION_NAMES; computed at the
    scanned alpha, filled from the boundary curves elsewhere). With ``forces=True``: ``P_fc``, ``P_pf`` on the same grid (NaN
    where they failed) and the model-choice masks ``westergaard`` (both forces within
    1 %: P_fc within 1 % of 1, |P_pf| <= 0.01) and ``jkr_fc`` (P_fc within 1 % of JKR's;
    JKR's pull-off, -inf, is qualitatively wrong everywhere)."""

    model: str
    alpha: np.ndarray
    mu: np.ndarray
    fc_region: np.ndarray
    pf_region: np.ndarray
    boundaries: list
    n_paths: int
    P_fc: Optional[np.ndarray] = None
    P_pf: Optional[np.ndarray] = None
    westergaard: Optional[np.ndarray] = None
    jkr_fc: Optional[np.ndarray] = None
    jkr_P_fc: Optional[np.ndarray] = field(default=None, repr=False)
    #: Where boundaries meet, turn back, end or fail inside the grid (SpecialPoint)
    special: list = field(default_factory=list)
    #: "load", "gap" or "both": which boundaries and regions were computed
    control: str = "load"
    ga_region: Optional[np.ndarray] = None
    gr_region: Optional[np.ndarray] = None

    def __repr__(self) -> str:
        return (f"AdhesionMap(model={self.model!r}, control={self.control!r}, "
                f"alpha={self.alpha.size} in [{self.alpha[0]:.4g}, {self.alpha[-1]:.4g}], "
                f"mu={self.mu.size} in [{self.mu[0]:.4g}, {self.mu[-1]:.4g}], "
                f"boundaries={len(self.boundaries)}, special={len(self.special)}, "
                f"n_paths={self.n_paths}, forces={self.P_fc is not None})")

    def to_dataframe(self):
        """One row per cell of the (mu, alpha) grid: ``alpha``, ``mu`` and the region
        codes (and ``P_fc``, ``P_pf``, the masks with ``forces=True``); pandas is imported
        only here. The boundaries are in ``boundaries``."""
        try:
            import pandas as pd
        except ImportError:
            raise ImportError("to_dataframe() needs pandas: pip install pandas") from None
        mu, alpha = np.meshgrid(self.mu, self.alpha, indexing="ij")
        cols = {"model": np.repeat(self.model, mu.size), "alpha": alpha.reshape(-1),
                "mu": mu.reshape(-1)}
        for name in ("fc_region", "pf_region", "ga_region", "gr_region", "P_fc", "P_pf",
                     "westergaard", "jkr_fc"):
            value = getattr(self, name)
            if value is not None:
                cols[name] = np.asarray(value).reshape(-1)
        return pd.DataFrame(cols)


#: The accepted forms of alpha_range and mu_range, for messages
_ALPHA_FORM = ("(lo, hi, n) with 1e-12 <= lo < hi <= 1e12 and n an integer in [2, 100000], "
               "or an array of strictly increasing alpha values in [1e-12, 1e12]")
_MU_FORM = ("(lo, hi, n) with 1e-100 <= lo < hi <= 1e100 and n an integer in "
            "[2, 100000]")


def _range3(spec, name, lo_min, hi_max, n_max, form):
    """(lo, hi, n) validated: reals lo < hi in [lo_min, hi_max], an integer n in
    [2, n_max]; every error names `name`'s part and the expected form."""
    if not (isinstance(spec, (tuple, list)) and len(spec) == 3):
        raise InvalidArgumentError(f"{name} = {spec!r}: expected {form}", INVALID_ARGUMENT)
    lo = real_in(spec[0], f"{name} lo", lo_min, hi_max)
    hi = real_in(spec[1], f"{name} hi", lo_min, hi_max)
    n = count_in(spec[2], f"{name} n", 2, n_max)
    if not lo < hi:
        raise InvalidArgumentError(f"{name} = {spec!r}: need lo < hi (expected {form})",
                                   INVALID_ARGUMENT)
    return lo, hi, n


def _grid(spec, name):
    """The alpha values: (lo, hi, n) -> n log-spaced values, else an array of strictly
    increasing values; checked against the library's bounds before anything is
    allocated (the errors name `name` and the expected form)."""
    if isinstance(spec, (str, bytes)) or spec is None:
        raise InvalidTypeError(f"{name} = {spec!r}: expected {_ALPHA_FORM}",
                               INVALID_ARGUMENT)
    if isinstance(spec, tuple) and len(spec) == 3:
        lo, hi, n = _range3(spec, name, ALPHA_MIN, ALPHA_MAX, MAP_N_ALPHA_MAX,
                            _ALPHA_FORM)
        return np.geomspace(lo, hi, n)
    if np.ndim(spec) > 1:
        raise InvalidArgumentError(f"{name}: expected {_ALPHA_FORM}; got an array of shape "
                                   f"{np.shape(spec)}", INVALID_ARGUMENT)
    if not 1 <= np.size(spec) <= MAP_N_ALPHA_MAX:
        raise InvalidArgumentError(f"{name} holds {np.size(spec)} values: expected 1 to "
                                   f"{MAP_N_ALPHA_MAX} ({_ALPHA_FORM})", INVALID_ARGUMENT)
    values = float_array(spec, name).reshape(-1)
    with np.errstate(invalid="ignore"):
        outside = np.flatnonzero(~((values >= ALPHA_MIN) & (values <= ALPHA_MAX)))
        falling = np.flatnonzero(~(values[1:] > values[:-1])) + 1
    if outside.size:
        i = int(outside[0])
        raise InvalidArgumentError(f"{name}[{i}] = {float(values[i])!r} is outside its valid "
                                   f"range [{ALPHA_MIN:g}, {ALPHA_MAX:g}]", INVALID_ARGUMENT)
    if falling.size:
        i = int(falling[0])
        raise InvalidArgumentError(f"{name}[{i}] = {float(values[i])!r} is not greater than "
                                   f"{name}[{i - 1}] = {float(values[i - 1])!r}: the values "
                                   "must be strictly increasing", INVALID_ARGUMENT)
    return values


def _forces_chunk(args):
    """Critical forces for one alpha over the mu grid (module level: picklable)."""
    model, alpha, mu = args
    res = critical_forces(model, alpha, mu, errors="nan")
    return (np.asarray(res.P_fc, dtype=float), np.asarray(res.P_pf, dtype=float),
            np.asarray(res.fc_mechanism, dtype=np.int32),
            np.asarray(res.pf_mechanism, dtype=np.int32))


def _force_grid(model, alpha, mu, executor, report):
    """The critical forces of every alpha column over the mu grid (one chunk each, in
    order), reporting each column as it comes back."""
    parts = []
    for part in iter_chunks(_forces_chunk, [(str(model), float(a), mu) for a in alpha],
                            executor):
        parts.append(part)
        if report is not None:
            report.update(1)
    return parts


def _alpha_boundary(model, which, mu, a_lo, a_hi, m_lo, tol=1e-9):
    """Bisect ln alpha at fixed mu to where the mechanism `which` leaves m_lo."""
    lo, hi = np.log(a_lo), np.log(a_hi)
    for _ in range(80):
        if hi - lo <= tol:
            break
        mid = 0.5 * (lo + hi)
        res = critical_forces(model, float(np.exp(mid)), mu, errors="nan")
        m = int(res.fc_mechanism if which == 1 else res.pf_mechanism)
        if m < 0:
            return None
        if m == m_lo:
            lo = mid
        else:
            hi = mid
    return float(np.exp(0.5 * (lo + hi)))


def _alpha_chunk(args):
    """Boundaries crossed in alpha at one mu (module level: picklable)."""
    model, which, mu, a_lo, a_hi, m_lo, tol = args
    return _alpha_boundary(model, which, mu, a_lo, a_hi, m_lo, tol)


def _vertical_boundaries(model, alpha, mu, regions, executor, tol=1e-9):
    """Changes of mechanism between neighbouring alpha columns that no mu boundary
    explains (the cells above and below agree on each side): a boundary crossed in alpha,
    such as full contact: jump case 1 -> snap (DW, MD near alpha = 0.57 for large mu),
    located by bisection in alpha at that mu to `tol` relative (default 1e-9)."""
    jobs = []
    for which, reg in ((1, regions[0]), (2, regions[1])):
        for i in range(1, reg.shape[0] - 1):
            for j in range(reg.shape[1] - 1):
                a, b = reg[i, j], reg[i, j + 1]
                if a < 0 or b < 0 or a == b:
                    continue
                if (reg[i - 1:i + 2, j] == a).all() and (reg[i - 1:i + 2, j + 1] == b).all():
                    jobs.append((which, int(a), int(b), float(mu[i]), float(alpha[j]),
                                 float(alpha[j + 1])))
    found = run_chunks(_alpha_chunk, [(str(model), w, m, lo, hi, a, float(tol))
                                      for (w, a, b, m, lo, hi) in jobs], executor)
    curves = {}
    for (which, a, b, m, _lo, _hi), alpha_b in zip(jobs, found):
        if alpha_b is not None:
            curves.setdefault(1000 + 100 * which + 10 * a + b, []).append((alpha_b, m))
    out = []
    for code, pts in sorted(curves.items()):
        pts.sort(key=lambda p: p[1])
        out.append(Boundary(code, np.array([p[0] for p in pts]), np.array([p[1] for p in pts]),
                            1, 1))
    return out


def adhesion_map(model: str, alpha_range: Union[Tuple[float, float, int], ArrayLike] = (
                     0.01, 10.0, 200),
                 mu_range: Tuple[float, float, int] = (1e-3, 1e3, 60), *,
                 forces: bool = False, scan_every: int = 20,
                 executor: Optional[Executor] = None, alpha_tol: float = 1e-9,
                 control: str = "load",
                 progress: Union[bool, Callable[[int, int], Any], None] = None
                 ) -> AdhesionMap:
    """The adhesion map of the (alpha, mu) plane for "dw" or "md".

    Parameters
    ----------
    model : {"dw", "md"}
    alpha_range : (lo, hi, n) or array_like
        Log-spaced alpha (default 0.01..10, 200 values; 1e-12 <= lo < hi <= 1e12, n an
        integer in [2, 100000]) or strictly increasing values in [1e-12, 1e12] (1 to
        100000 of them).
    mu_range : (lo, hi, n)
        The mu range and the number of log-spaced mu of the region grid (default 1e-3..1e3,
        60; 1e-100 <= lo < hi <= 1e100, n an integer in [2, 100000]); the boundaries are
        located anywhere in [lo, hi] to 2e-9 relative. The grid holds at most 1e7 cells
        (n times the number of alpha values).
    forces : bool
        Also compute P_fc, P_pf and the mechanisms in every cell, the model-choice masks,
        and the boundaries crossed in alpha (codes from 1000, located by bisection in
        alpha at the grid mu where the mechanism changes between two alpha columns).
    scan_every : int
        The coarse mu scan that discovers boundaries runs at every scan_every-th alpha
        (an integer >= 1).
    executor : concurrent.futures.Executor, optional
        Runs the force grid (one chunk per alpha) and the bisections in alpha on it; the
        boundaries in mu are continued in one Fortran call (serial), in a thread of its
        own while the executor works on the force grid. Results equal the serial ones.
        The Fortran call runs in a helper thread in any case, so that Ctrl-C raises
        KeyboardInterrupt within 0.1 s (the call itself runs on to its end in the
        background, its result dropped).
    alpha_tol : float
        Relative accuracy in alpha of the boundaries crossed in alpha (``forces=True``;
        default 1e-9, in [1e-15, 0.1]; a figure needs far less, e.g. 1e-5).
    control : {"load", "gap", "both"}
        Which boundaries: load control (codes 1xx, 2xx; default), gap control (3xx
        approach, 4xx retraction: doc/theory.md, "Adhesion map") or both. Gap control
        costs about as much again as load control for DW, 5-10 times more for MD.
    progress : bool or callable, optional
        True: a progress bar on stderr (tqdm when installed, else a plain line); a
        callable: called as ``progress(done, total)``. The boundaries are one Fortran
        call that reports nothing while it runs: it counts as one step, reported when it
        ends; with ``forces=True`` each alpha column of the force grid is one more step,
        reported as it comes back (the bisections in alpha are done before the last).

    Returns
    -------
    AdhesionMap

    Raises
    ------
    InvalidArgumentError
        A model other than dw/md, a bad range or count (decreasing alpha, mu lo >= hi, a
        count that is not an integer in its range, NaN, inf, a grid of more than 1e7
        cells, ...: checked before anything is allocated, the message names the
        argument and its valid range), a control other than load/gap/both.
    InvalidTypeError
        A range, count or flag of the wrong type (a string, None, a bool as a count).
    """
    code = model_code(model)
    if code not in (MODELS["dw"], MODELS["md"]):
        raise InvalidArgumentError(f"model = {model!r}: the adhesion map is for 'dw' or 'md' "
                                   "(westergaard and jkr have one mechanism each)",
                                   INVALID_ARGUMENT)
    if not (isinstance(control, str) and control in CONTROLS):
        raise InvalidArgumentError(f"control = {control!r}: must be 'load', 'gap' or 'both'",
                                   INVALID_ARGUMENT)
    if not isinstance(forces, (bool, np.bool_)):
        raise InvalidTypeError(f"forces = {forces!r}: must be True or False",
                               INVALID_ARGUMENT)
    every = count_in(scan_every, "scan_every", 1, C_INT_MAX)
    alpha_tol = real_in(alpha_tol, "alpha_tol", 1e-15, 0.1)
    mu_lo, mu_hi, n_mu = _range3(mu_range, "mu_range", MU_MIN, MU_MAX, MAP_N_MU_MAX,
                                 _MU_FORM)
    alpha = _grid(alpha_range, "alpha_range")
    if n_mu * alpha.size > MAP_CELLS_MAX:
        raise InvalidArgumentError(
            f"mu_range n times the number of alpha values = {n_mu} x {alpha.size} = "
            f"{n_mu * alpha.size}: the grid may hold at most {MAP_CELLS_MAX} cells",
            INVALID_ARGUMENT)
    capacity = 64 * (alpha.size + 64)
    args = (n_mu, capacity, code, alpha, mu_lo, mu_hi, every, CONTROLS[control])
    report = make_progress(progress, 1 + (alpha.size if forces else 0), "adhesion_map")
    try:
        return _compute_map(model, code, alpha, mu_lo, mu_hi, n_mu, args, forces, executor,
                            alpha_tol, control, report)
    finally:
        if report is not None:
            report.close()


def _compute_map(model, code, alpha, mu_lo, mu_hi, n_mu, args, forces, executor, alpha_tol,
                 control, report):
    """adhesion_map's work once its arguments are checked (`report`: a Progress or None)."""
    pending = None
    if forces and executor is not None:
        # the force grid on the executor while a helper thread continues the boundaries
        # (the facade releases the GIL); the grid is Fortran's (checked below)
        mu_guess = np.exp(np.log(mu_lo) + (np.log(mu_hi) - np.log(mu_lo))
                          * np.arange(n_mu) / (n_mu - 1))
        call = Background(_f.fa_adhesion_map, *args)
        pending = (mu_guess, _force_grid(model, alpha, mu_guess, executor, report))
        out = call.result()
    else:
        out = call_interruptibly(_f.fa_adhesion_map, *args)   # Ctrl-C within 0.1 s
    if report is not None:
        report.update(1)
    (codes, a_out, m_out, curve, kinds, n_out, mu_grid, fc, pf, ga, gr, n_paths, status,
     message, sp_kind, sp_codes, sp_point, n_special) = out
    if status != OK:
        raise_status(status, message)
    n = int(n_out)
    boundaries = []
    for c in range(1, int(curve[:n].max(initial=0)) + 1):
        sel = np.flatnonzero(curve[:n] == c)
        if sel.size == 0:
            continue
        boundaries.append(Boundary(int(codes[sel[0]]), a_out[sel].copy(), m_out[sel].copy(),
                                   int(kinds[0, sel[0]]), int(kinds[1, sel[0]])))
    special = [SpecialPoint(SPECIAL_KINDS.get(int(sp_kind[k]), "unknown"),
                            float(sp_point[0, k]), float(sp_point[1, k]),
                            tuple(int(c) for c in sp_codes[:, k] if c != 0))
               for k in range(int(n_special))]
    result = dict(model=str(model), alpha=alpha, mu=np.asarray(mu_grid).copy(),
                  fc_region=np.asarray(fc).copy(), pf_region=np.asarray(pf).copy(),
                  boundaries=boundaries, n_paths=int(n_paths), special=special,
                  control=control)
    if control != "load":
        result.update(ga_region=np.asarray(ga).copy(), gr_region=np.asarray(gr).copy())
    if forces:
        mu = result["mu"]
        if pending is not None and np.array_equal(pending[0], mu):
            parts = pending[1]
        else:
            # (on an executor whose guessed grid missed: computed again, not counted again)
            parts = _force_grid(model, alpha, mu, executor, report if pending is None else None)
        p_fc = np.stack([p[0] for p in parts], axis=1)
        p_pf = np.stack([p[1] for p in parts], axis=1)
        # every cell computed: the exact region grid replaces the one filled from curves
        result.update(fc_region=np.stack([p[2] for p in parts], axis=1),
                      pf_region=np.stack([p[3] for p in parts], axis=1))
        jkr = np.asarray(critical_forces("jkr", alpha, 0.0).P_fc, dtype=float)
        with np.errstate(invalid="ignore"):
            result["boundaries"] = boundaries + _vertical_boundaries(
                model, alpha, result["mu"], (result["fc_region"], result["pf_region"]),
                executor, alpha_tol)
            result.update(P_fc=p_fc, P_pf=p_pf,
                          westergaard=(np.abs(p_fc - 1.0) <= 0.01) & (np.abs(p_pf) <= 0.01),
                          jkr_fc=np.abs(p_fc - jkr[None, :]) <= 0.01 * np.abs(jkr[None, :]),
                          jkr_P_fc=jkr)
    return AdhesionMap(**result)
