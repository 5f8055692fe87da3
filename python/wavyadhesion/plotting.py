"""Matplotlib helpers that redraw the figures of the double-Westergaard paper from the
library (optional: matplotlib is imported when a helper is called, never by
``import wavyadhesion``).

- :func:`figure4`: P*-a* curves (a* < c* < 1/2) of DW and MD for several mu, with the
  Westergaard and JKR curves, one panel per alpha (paper Fig. 4a, b).
- :func:`figure6`: a* and c* against P* for one alpha and several mu, with the
  load-controlled path (paper Fig. 6a-e for alpha = 0.3).
- :func:`figures9_10`: P_fc* and P_pf* against mu for several alpha, line style by
  mechanism (paper Figs. 9 and 10).

Every helper returns the matplotlib Figure(s); saving is the caller's business::

    from wavyadhesion import plotting
    plotting.figure6().savefig("fig6.png", dpi=100)

The example scripts in ``python/examples/`` write ``doc/figures/*.png`` this way.
"""

from __future__ import annotations

import warnings

from typing import TYPE_CHECKING, List, Optional, Sequence, Tuple

import numpy as np
from numpy.typing import ArrayLike

from ._branch import trace_branch
from ._equilibrium import jkr_load, westergaard_load
from ._errors import WavyAdhesionError
from ._loadpath import MECHANISMS, critical_forces, load_path

__all__ = ["figure4", "figure6", "figures9_10", "mechanism_runs", "adhesion_map"]

if TYPE_CHECKING:                       # matplotlib is optional: names for annotations only
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from ._energy import EnergyLost
    from ._map import AdhesionMap

# Line styles of the paper: solid where the zone is inside the period (case 1) or a
# jump from case 1, dash-dot for c* = 1/2 (case 2) or a gradual change, dashed for a
# jump from case 2.
_CASE_STYLE = {1: "-", 2: "-."}
_MECHANISM_STYLE = {"gradual": "-.", "jump_case1": "-", "jump_case2": "--", "snap": ":"}


def _pyplot():
    try:
        import matplotlib.pyplot as plt
    except ImportError as exc:       # pragma: no cover - depends on the environment
        raise ImportError("wavyadhesion.plotting needs matplotlib: "
                          "pip install matplotlib") from exc
    return plt


def _by_case(values: np.ndarray, zone_case: np.ndarray, case: int) -> np.ndarray:
    """`values` where the zone case is `case` (and at the junction points next to such
    runs, so that consecutive pieces meet), NaN elsewhere."""
    keep = zone_case == case
    keep = keep | np.r_[keep[1:], False] | np.r_[False, keep[:-1]]
    if case == 1:                        # full contact (case 3) belongs to neither piece
        keep &= zone_case != 3
    return np.where(keep, values, np.nan)


def _trace_or_warn(model, alpha, mu):
    try:
        return trace_branch(model, alpha, mu)
    except WavyAdhesionError as exc:
        warnings.warn(f"{model} alpha={alpha} mu={mu}: {exc}; curve left out", stacklevel=3)
        return None


def figure4(alphas: ArrayLike = (0.3, 0.6), mus: ArrayLike = (0.3, 1.0, 3.0, 10.0), *,
            models: Sequence[str] = ("dw", "md")) -> "Figure":
    """Equilibrium P*-a* curves with a* < c* < 1/2 (paper Fig. 4).

    Parameters
    ----------
    alphas : sequence of float
        One panel per alpha (the paper: 0.3 and 0.6).
    mus : sequence of float
        Transition parameters, one colour each.
    models : sequence of str
        Cohesive models drawn: DW solid, MD dashed.

    Returns
    -------
    matplotlib.figure.Figure
    """
    plt = _pyplot()
    fig, axes = plt.subplots(1, len(alphas), figsize=(5.0 * len(alphas), 4.2), squeeze=False)
    a = np.linspace(1e-4, 0.5 - 1e-4, 400)
    colours = plt.cm.viridis(np.linspace(0.0, 0.85, len(mus)))
    styles = {"dw": "-", "md": "--"}
    for ax, alpha in zip(axes[0], alphas):
        ax.plot(a, westergaard_load(a), color="0.4", lw=1.2, label="Westergaard")
        ax.plot(a, jkr_load(alpha, a), color="k", lw=1.2, ls="-.", label="JKR")
        for colour, mu in zip(colours, mus):
            for model in models:
                b = _trace_or_warn(model, alpha, mu)
                if b is None:
                    continue
                case1 = _by_case(b.P_star, b.zone_case, 1)
                if not np.any(np.isfinite(case1)):   # no state with a* < c* < 1/2: no entry
                    continue
                extent = float(np.nanmax(np.where(np.isfinite(case1), b.a_star, np.nan)))
                note = f" ($a^*$<{extent:.2g}, hidden)" if extent < 0.05 else ""
                ax.plot(b.a_star, case1, color=colour, ls=styles.get(model, ":"), lw=1.4,
                        label=f"{model.upper()} $\\mu$={mu:g}{note}")
        ax.set_xlim(0.0, 0.5)
        ax.set_ylim(-1.2, 1.1)
        ax.axhline(0.0, color="0.8", lw=0.6, zorder=0)
        ax.set_xlabel("$a^*$")
        ax.set_ylabel("$P^*$")
        ax.set_title(f"$\\alpha$ = {alpha:g}")
    axes[0][0].legend(fontsize=7, ncol=2, loc="lower left")
    fig.suptitle("Equilibrium $P^*$-$a^*$ curves with $a < c < L/2$ (cf. paper Fig. 4)",
                 fontsize=10)
    fig.tight_layout()
    return fig


def figure6(alpha: float = 0.3, mus: ArrayLike = (0.1, 1.0, 2.5, 3.0, 5.0), model: str = "dw",
            paper_figure: int = 6) -> "Figure":
    """Contact and interaction-zone half-widths against the load (paper Fig. 6).

    a* in red and c* in black, solid where a* < c* < 1/2 and dash-dot where c* = 1/2
    (the paper's convention); the load-controlled path is overlaid in blue (jumps as
    dotted lines at constant load, P_fc and P_pf marked).

    Parameters
    ----------
    alpha : float
        Johnson's parameter (the paper: 0.3).
    mus : sequence of float
        One panel per mu (the paper: 0.1, 1, 2.5, 3, 5).
    model : str
        "dw" (the paper) or "md".
    paper_figure : int
        The paper's figure this one corresponds to (6, 7 or 8), named in the title.

    Returns
    -------
    matplotlib.figure.Figure
    """
    plt = _pyplot()
    ncol = min(3, len(mus))
    nrow = -(-len(mus) // ncol)
    fig, axes = plt.subplots(nrow, ncol, figsize=(4.2 * ncol, 3.4 * nrow), squeeze=False)
    for ax in axes.flat[len(mus):]:
        ax.set_visible(False)
    for ax, mu in zip(axes.flat, mus):
        b = _trace_or_warn(model, alpha, mu)
        if b is None:
            continue
        for case, ls in _CASE_STYLE.items():
            ax.plot(_by_case(b.P_star, b.zone_case, case), b.a_star, color="tab:red",
                    ls=ls, lw=1.4)
            ax.plot(_by_case(b.P_star, b.zone_case, case), b.c_star, color="k", ls=ls,
                    lw=1.0)
        _overlay_path(ax, model, alpha, mu)
        ax.set_ylim(0.0, 0.52)
        ax.set_xlabel("$P^*$")
        ax.set_ylabel("$a^*$ (red), $c^*$ (black)")
        ax.set_title(f"$\\alpha$ = {alpha:g}, $\\mu$ = {mu:g}", fontsize=10)
    from matplotlib.lines import Line2D
    handles = [Line2D([], [], color="tab:red", lw=1.4, label="$a^*$"),
               Line2D([], [], color="k", lw=1.0, label="$c^*$"),
               Line2D([], [], color="0.4", ls=_CASE_STYLE[1], label="$a^* < c^* < 1/2$"),
               Line2D([], [], color="0.4", ls=_CASE_STYLE[2], label="$c^* = 1/2$"),
               Line2D([], [], color="tab:blue", ls=":", label="jump (load control)")]
    fig.legend(handles=handles, loc="lower center", ncol=5, fontsize=8, frameon=False)
    fig.suptitle(f"{model.upper()}: half-widths against load, path in blue "
                 f"(cf. paper Fig. {paper_figure})", fontsize=10)
    fig.tight_layout(rect=(0, 0.06, 1, 1))
    return fig


def _overlay_path(ax, model, alpha, mu):
    """Jumps of the load path as dotted lines at constant load, P_fc and P_pf marked."""
    try:
        path = load_path(model, alpha, mu)
    except WavyAdhesionError as exc:
        warnings.warn(f"{model} alpha={alpha} mu={mu}: {exc}; path left out", stacklevel=3)
        return
    ev = path.events
    for start, end in zip(ev[:-1], ev[1:]):
        if start.kind == "jump_start" and end.kind in ("jump_end", "full_contact_reached",
                                                         "pull_off"):
            a_end = 0.0 if end.kind == "pull_off" else end.a_star
            ax.plot([start.P_star, end.P_star], [start.a_star, a_end], color="tab:blue",
                    ls=":", lw=1.2)
    label = dict(fontsize=9, color="tab:blue", zorder=5,
                 bbox=dict(boxstyle="round,pad=0.15", fc="white", ec="none", alpha=0.85))
    ax.plot([path.P_fc], [0.5], "v", color="tab:blue", ms=6, zorder=5)
    if np.isfinite(path.P_pf):
        ax.plot([path.P_pf], [0.0], "^", color="tab:blue", ms=6, zorder=5)
        ax.text(path.P_pf, 0.04, "$P_{pf}$", ha="center", va="bottom", **label)
    ax.text(path.P_fc, 0.44, "$P_{fc}$", ha="center", va="top", **label)


def mechanism_runs(mechanism: ArrayLike) -> List[Tuple[int, int, int]]:
    """Split an array of mechanism codes into runs: (start, stop, code) with stop one
    past the run's last index, extended by one point into the next run (so that
    consecutive pieces drawn with different styles meet)."""
    runs = []
    n = len(mechanism)
    start = 0
    for i in range(1, n + 1):
        if i == n or mechanism[i] != mechanism[start]:
            runs.append((start, min(i + 1, n), int(mechanism[start])))
            start = i
    return runs


def figures9_10(alphas: ArrayLike = (0.3, 0.6, 1.0), mu: Optional[ArrayLike] = None,
                model: str = "dw") -> Tuple["Figure", "Figure"]:
    """Critical forces against the transition parameter (paper Figs. 9 and 10).

    Line style by mechanism: dash-dot where full contact is reached (contact is lost)
    gradually, solid for a jump from a case-1 state (or the snap into full contact at
    P* = 0, dotted), dashed for a jump from a case-2 state (c* = 1/2).

    Parameters
    ----------
    alphas : sequence of float
        One colour each (the paper: 0.3, 0.6, 1).
    mu : array_like, optional
        Transition parameters (default: 200 values, log-spaced from 0.01 to 10).
    model : str
        "dw" (the paper) or "md".

    Returns
    -------
    (matplotlib.figure.Figure, matplotlib.figure.Figure)
        Fig. 9 (P_fc*) and Fig. 10 (P_pf*).
    """
    plt = _pyplot()
    mu = np.logspace(-2, 1, 200) if mu is None else np.asarray(mu, dtype=float)
    fig9, ax9 = plt.subplots(figsize=(5.2, 4.0))
    fig10, ax10 = plt.subplots(figsize=(5.2, 4.0))
    colours = plt.cm.plasma(np.linspace(0.0, 0.75, len(alphas)))
    for colour, alpha in zip(colours, alphas):
        crit = critical_forces(model, alpha, mu, errors="nan")
        for ax, values, mech in ((ax9, crit.P_fc, crit.fc_mechanism),
                                 (ax10, crit.P_pf, crit.pf_mechanism)):
            for start, stop, code in mechanism_runs(mech):
                if code < 0:
                    continue
                ax.semilogx(mu[start:stop], values[start:stop], color=colour, lw=1.5,
                            ls=_MECHANISM_STYLE[MECHANISMS[code]])
            ax.plot([], [], color=colour, label=f"$\\alpha$ = {alpha:g}")
        p_jkr = _jkr_full_contact(alpha)    # thin and faint: not a "snap" segment
        ax9.axhline(p_jkr, color=colour, lw=0.8, ls=(0, (8, 3, 1, 3, 1, 3)), alpha=0.45)
    for ax in (ax9, ax10):
        for name, ls in _MECHANISM_STYLE.items():
            if ax is ax10 and name == "snap":
                continue
            ax.plot([], [], color="0.3", ls=ls, label=name.replace("_", " "))
        ax.set_xlabel("$\\mu$")
        ax.legend(fontsize=7)
        ax.set_xlim(mu.min(), mu.max())
    ax9.set_ylabel("$P^*_{fc}$")
    ax9.set_title(f"{model.upper()}: load to reach full contact (cf. paper Fig. 9)\n"
                  "faint dash-dot-dot: JKR value", fontsize=9)
    ax10.set_ylabel("$P^*_{pf}$")
    ax10.set_title(f"{model.upper()}: pull-off load (cf. paper Fig. 10)", fontsize=9)
    fig9.tight_layout()
    fig10.tight_layout()
    return fig9, fig10


def _jkr_full_contact(alpha):
    """JKR P_fc* (the value the cohesive models reach at large mu)."""
    return float(critical_forces("jkr", alpha, 1.0).P_fc)


#: Short names of the mechanisms in map labels.
_MAP_SHORT = ("gradual", "jump c1", "jump c2", "snap")
#: Gap control (approach, retraction): short names in map labels
_GAP_SHORT = (("gradual", "jump-in", "grad.+inner", "jump-in+inner"),
              ("gradual", "jump-out", "inner+grad.", "inner+jump-out"))


#: Colour of the W* contours (distinct from the greys and black of the map's lines).
_ENERGY_COLOUR = "#7b2d8e"


def _pchip(x, y, xf):
    """Monotone cubic (Fritsch-Carlson) interpolation of y(x) along the last axis of `y`
    at `xf`; NaN-aware: an interval with a NaN end is NaN, and a node next to a NaN takes
    the one-sided slope (a failed point leaves a hole of its own cells only)."""
    x = np.asarray(x, dtype=float)
    h = np.diff(x)
    delta = np.diff(y, axis=-1) / h
    d = np.zeros_like(y)
    left, right = delta[..., :-1], delta[..., 1:]
    w1, w2 = 2 * h[1:] + h[:-1], h[1:] + 2 * h[:-1]
    with np.errstate(divide="ignore", invalid="ignore"):
        harmonic = (w1 + w2) / (w1 / left + w2 / right)
    same = np.isfinite(left) & np.isfinite(right) & (left * right > 0)
    inner = np.where(same, harmonic, 0.0)
    inner = np.where(np.isfinite(left) & ~np.isfinite(right), left, inner)
    inner = np.where(~np.isfinite(left) & np.isfinite(right), right, inner)
    d[..., 1:-1] = inner
    d[..., 0], d[..., -1] = delta[..., 0], delta[..., -1]
    k = np.clip(np.searchsorted(x, xf, side="right") - 1, 0, x.size - 2)
    t = (xf - x[k]) / h[k]
    y0, y1, d0, d1 = y[..., k], y[..., k + 1], d[..., k] * h[k], d[..., k + 1] * h[k]
    out = (y0 * (2 * t**3 - 3 * t**2 + 1) + d0 * (t**3 - 2 * t**2 + t)
           + y1 * (-2 * t**3 + 3 * t**2) + d1 * (t**3 - t**2))
    # at a node its own value (finite next to a hole, where NaN * 0 would spoil it)
    return np.where(t == 0, y0, np.where(t == 1, y1, out))


def _energy_grid(energy, refine):
    """(alpha, mu, W*/(pi alpha^2/2)) of an EnergyLost computed on a grid (alpha along
    axis 1, mu along axis 0), refined `refine` times per cell by monotone cubic
    interpolation in (log alpha, log mu)."""
    frac = np.asarray(energy.W_fraction, dtype=float)
    if frac.ndim != 2 or min(frac.shape) < 2:
        raise ValueError("energy: need an energy_lost result on a grid (alpha of shape "
                         f"(1, n), mu of shape (m, 1), n, m >= 2); got shape {frac.shape}")
    la = np.log10(np.asarray(energy.alpha, dtype=float)[0, :])
    lm = np.log10(np.asarray(energy.mu, dtype=float)[:, 0])
    if not (np.all(np.diff(la) > 0) and np.all(np.diff(lm) > 0)):
        raise ValueError("energy: alpha and mu of the grid must increase")
    refine = max(1, int(refine))
    la_f = np.linspace(la[0], la[-1], refine * (la.size - 1) + 1)
    lm_f = np.linspace(lm[0], lm[-1], refine * (lm.size - 1) + 1)
    fine = _pchip(la, frac, la_f)                       # along alpha, every mu row
    fine = _pchip(lm, fine.T, lm_f).T                   # then along mu
    return 10 ** la_f, 10 ** lm_f, fine


def _energy_label_points(cs, levels, ax):
    """One label point per level: on its contour where the contour is nearest the top
    of the axes (log mu within 92 % of the visible span), so that the labels sit in a row
    above the region labels; a level whose contour does not get there is labelled at its
    highest point."""
    lo, hi = np.log10(ax.get_ylim())
    target = lo + 0.92 * (hi - lo)
    points = []
    for k, level in enumerate(cs.levels):
        if level not in levels:
            continue
        segs = [s for s in cs.allsegs[k] if len(s) >= 2]
        if not segs:
            continue
        best = None
        for seg in segs:
            ly = np.log10(seg[:, 1])
            i = int(np.argmin(np.abs(ly - min(target, ly.max()))))
            score = abs(ly[i] - target)
            if best is None or score < best[0]:
                best = (score, seg[i])
        points.append((float(best[1][0]), float(best[1][1])))
    return points


def _draw_energy(ax, energy, levels, refine):
    """W*/(pi alpha^2/2) contours (thin, coloured), one label per level; failed points
    marked with a small cross. Returns the number of failed points."""
    alpha_f, mu_f, fine = _energy_grid(energy, refine)
    with np.errstate(invalid="ignore"):
        cs = ax.contour(alpha_f, mu_f, fine, levels=sorted(levels), colors=_ENERGY_COLOUR,
                        linewidths=0.9, linestyles="solid", zorder=1.9)
    points = _energy_label_points(cs, cs.levels, ax)
    if points:
        texts = ax.clabel(cs, fmt=lambda v: f"{v:g}", fontsize=7.5, inline=True,
                          inline_spacing=3, manual=points, colors=_ENERGY_COLOUR)
        for text in texts:     # all read upwards (a vertical line may come out at 270)
            r = text.get_rotation() % 180
            text.set_rotation(r - 180 if r > 91 else r)
    failed = ~np.asarray(energy.ok)
    if failed.any():
        ax.plot(np.asarray(energy.alpha)[failed], np.asarray(energy.mu)[failed], ls="none",
                marker="x", ms=4, mew=0.9, color=_ENERGY_COLOUR, zorder=4)
    return int(failed.sum())


def adhesion_map(amap: "AdhesionMap", ax: Optional["Axes"] = None, *,
                 pull_off_levels: Optional[ArrayLike] = None, labels: bool = True,
                 energy: Optional["EnergyLost"] = None,
                 energy_levels: ArrayLike = (0.1, 0.3, 0.5, 0.7, 0.9),
                 energy_refine: int = 6) -> "Figure":
    """Draw an :class:`~wavyadhesion.AdhesionMap` in the style of Johnson and Greenwood's
    map: log axes (alpha horizontal, mu vertical), one shade per region (full-contact and
    pull-off mechanism pair, labelled), the boundary curves as sharp lines (full contact
    solid, pull-off dashed), and, when the map holds forces (``forces=True``), the region
    where Westergaard predicts both critical forces within 1 % (hatched), the edge of the
    region where JKR's P_fc is within 1 % (thick grey line; JKR's pull-off, -inf, is
    wrong everywhere) and contours of -P_pf (thin, labelled). Gap-control boundaries
    (maps with ``control`` "gap" or "both") are drawn in red (approach solid, retraction
    dashed); a map with ``control="gap"`` is shaded by its gap regions (AP = how contact
    is made on the approach, RE = how it is lost on the retraction).

    ``energy``: an :func:`~wavyadhesion.energy_lost` result on a grid (``alpha`` of shape
    (1, n), ``mu`` of shape (m, 1), both increasing; it may cover part of the map) adds
    contours of W*/(pi alpha^2/2), the fraction of the work of adhesion lost per
    gap-controlled cycle, at ``energy_levels`` (purple, one label per level in a row near
    the top), interpolated ``energy_refine`` times per cell by monotone cubics in
    (log alpha, log mu); points where the cycle failed (NaN) leave a hole, marked x.

    Returns the figure.
    """
    plt = _pyplot()
    from matplotlib.colors import ListedColormap

    if ax is None:
        fig, ax = plt.subplots(figsize=(8.0, 6.4), layout="constrained")
    else:
        fig = ax.figure
    alpha, mu = amap.alpha, amap.mu
    gap_only = getattr(amap, "control", "load") == "gap"
    reg_a, reg_b = ((amap.ga_region, amap.gr_region) if gap_only else
                    (amap.fc_region, amap.pf_region))
    short_a, short_b = _GAP_SHORT if gap_only else (_MAP_SHORT, _MAP_SHORT)
    tag_a, tag_b = ("AP", "RE") if gap_only else ("FC", "PO")
    pair = np.where((reg_a >= 0) & (reg_b >= 0), 4 * reg_b + reg_a, -1)
    present = [int(v) for v in np.unique(pair) if v >= 0]
    index = np.full(pair.shape, np.nan)
    for k, v in enumerate(present):
        index[pair == v] = k
    palette = ["#fde0c5", "#cfe8f3", "#e2f0cb", "#f3d1e4", "#fff2b3", "#d9d2f0",
               "#c9ead9", "#f6cfc4", "#dfe7ef", "#efe3c8", "#d0e0c0", "#e8d5c4"]
    cmap = ListedColormap([palette[k % len(palette)] for k in range(max(len(present), 1))])
    # cell edges halfway between grid values (log space)
    def edges(v):
        lv = np.log10(v)
        mid = 0.5 * (lv[1:] + lv[:-1])
        return 10 ** np.concatenate([[2 * lv[0] - mid[0]], mid, [2 * lv[-1] - mid[-1]]])
    ax.pcolormesh(edges(alpha), edges(mu), index, cmap=cmap, vmin=-0.5,
                  vmax=max(len(present), 1) - 0.5, shading="flat", rasterized=True)
    if amap.westergaard is not None:
        ax.contourf(alpha, mu, amap.westergaard.astype(float), levels=[0.5, 1.5],
                    colors="none", hatches=["////"])
        ax.contour(alpha, mu, amap.westergaard.astype(float), levels=[0.5], colors="0.35",
                   linewidths=0.8)
        ax.contour(alpha, mu, amap.jkr_fc.astype(float), levels=[0.5], colors="0.45",
                   linewidths=3.0, alpha=0.7)
        levels = pull_off_levels or [0.01, 0.03, 0.1, 0.3, 1.0, 3.0]
        with np.errstate(invalid="ignore"):
            cs = ax.contour(alpha, mu, -amap.P_pf, levels=levels, colors="0.25",
                            linewidths=0.6, linestyles="dotted")
        ax.clabel(cs, fmt=lambda v: f"$-P_{{pf}}^*$={v:g}", fontsize=7, inline=True)
    for b in amap.boundaries:
        which = b.code % 1000 // 100
        ax.plot(b.alpha, b.mu, color="k" if which < 3 else "tab:red", lw=1.6,
                ls="-" if which in (1, 3) else "--")
    markers = {"meet": ("o", "k"), "turn": ("D", "tab:red"), "end": ("s", "tab:blue"),
               "load path fails": ("x", "tab:orange")}
    for p in getattr(amap, "special", []):
        m, c = markers.get(p.kind, ("o", "k"))
        ax.plot([p.alpha], [p.mu], ls="none", marker=m, ms=6, mfc=c, mec="white" if
                m != "x" else c, mew=0.8, zorder=5)
    if labels:
        la, lm = np.log10(alpha), np.log10(mu)
        for k, v in enumerate(present):
            jj, ii = np.nonzero((index == k).T)
            if jj.size < 6:
                continue
            # the cell of the region farthest inside it (largest distance to other cells)
            mask = index == k
            best, where = -1, None
            for i, j in zip(ii, jj):
                d = 0
                while (i - d >= 0 and i + d < mask.shape[0] and j - d >= 0 and
                       j + d < mask.shape[1] and mask[i - d:i + d + 1, j - d:j + d + 1].all()):
                    d += 1
                if d > best:
                    best, where = d, (i, j)
            i, j = where
            ax.text(10 ** la[j], 10 ** lm[i],
                    f"{tag_a} {short_a[v % 4]}\n{tag_b} {short_b[v // 4]}", ha="center",
                    va="center", fontsize=8, bbox=dict(boxstyle="round,pad=0.2", fc="white",
                                                       ec="none", alpha=0.75))
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlim(alpha[0], alpha[-1])
    ax.set_ylim(mu[0], mu[-1])
    n_energy_failed = None if energy is None else _draw_energy(ax, energy, energy_levels,
                                                               energy_refine)
    ax.set_xlabel(r"$\alpha$ (adhesion vs. elasticity)")
    ax.set_ylabel(r"$\mu$ (range of adhesive stress)")
    ax.set_title(f"Adhesion map, {amap.model.upper()}: FC = how full contact is reached, "
                 f"PO = how contact is lost" if not gap_only else
                 f"Adhesion map under gap control, {amap.model.upper()}: AP = how contact "
                 f"is made, RE = how it is lost", fontsize=10)
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch
    whiches = {b.code % 1000 // 100 for b in amap.boundaries}
    handles = [Line2D([], [], color="k", lw=1.6, label="full-contact boundary"),
               Line2D([], [], color="k", lw=1.6, ls="--", label="pull-off boundary")]
    if gap_only:
        handles = []
    if 3 in whiches:
        handles.append(Line2D([], [], color="tab:red", lw=1.6, label="gap approach boundary"))
    if 4 in whiches:
        handles.append(Line2D([], [], color="tab:red", lw=1.6, ls="--",
                              label="gap retraction boundary"))
    kinds = sorted({p.kind for p in getattr(amap, "special", [])})
    handles += [Line2D([], [], ls="none", marker=markers[k][0], mfc=markers[k][1],
                       mec=markers[k][1], label={"meet": "boundaries meet",
                                                 "turn": "boundary turns back in alpha",
                                                 "end": "boundary ends (region closes)",
                                                 "load path fails": "load path fails"}[k])
                for k in kinds if k in markers]
    if amap.westergaard is not None:
        handles += [Patch(fc="none", ec="0.35", hatch="////",
                          label="Westergaard within 1 % (P_fc and P_pf)"),
                    Line2D([], [], color="0.45", lw=3, alpha=0.7,
                           label="edge of: JKR P_fc within 1 %"),
                    Line2D([], [], color="0.25", lw=0.6, ls="dotted",
                           label="contours of -P_pf")]
    if energy is not None:
        handles.append(Line2D([], [], color=_ENERGY_COLOUR, lw=0.9,
                              label=r"$W^*/(\pi\alpha^2/2)$ lost per gap cycle"))
        if n_energy_failed:
            handles.append(Line2D([], [], ls="none", marker="x", ms=4, mew=0.9,
                                  color=_ENERGY_COLOUR,
                                  label=f"$W^*$ failed: hole ({n_energy_failed})"))
    ax.legend(handles=handles, loc="lower left", fontsize=7, framealpha=0.85,
              ncol=2 if len(handles) > 7 else 1)
    return fig
