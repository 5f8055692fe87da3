#!/usr/bin/env python3
"""Draw the energy lost per cycle under gap control (issue 11): the energy map and P*-gbar* loops.

    .venv/bin/python tools/figures/plot_energy.py --outdir doc/figures

Writes two PNGs:
* energy_lost_dw_md.png: W* (units p* Delta per unit area) and W*/(pi alpha^2/2) (the fraction
  of the work of adhesion lost per cycle) against mu for alpha in {0.3, 0.6, 1}, DW and MD,
  with the JKR values (mu -> infinity limit of DW) as dotted lines; the counterpart of the
  paper's Figs. 9-10 in energy. Values from `wavyadhesion.gap_law` (W_star, W_fraction).
* gap_loops_alpha0.3.png: P* against the mean gap gbar* on approach and on retraction for
  alpha = 0.3, mu in {1, 5}, DW and MD; left the whole range, right a zoom near full
  contact. Curves from `wavyadhesion.gap_law` on a dense grid; the jumps at constant gbar*
  from the events of `wavyadhesion path --control gap` (fpm run, release profile), drawn as
  vertical segments with arrows.
Uses the installed Python package (`pip install ./python`); matplotlib is imported here only.
Prints its running time and the numbers quoted in doc/user-guide.md.
"""
import argparse
import csv
import io
import subprocess
import time

import numpy as np

import wavyadhesion as wa

ALPHAS = (0.3, 0.6, 1.0)
COLOURS = {0.3: "tab:blue", 0.6: "tab:orange", 1.0: "tab:green"}
MODEL_COLOURS = {"dw": "tab:blue", "md": "tab:red"}


def energy_map(mus):
    """{(model, alpha): (W*, W fraction)} arrays over mus (NaN where the path fails)."""
    out = {}
    for model in ("dw", "md"):
        for alpha in ALPHAS:
            w = np.full(mus.shape, np.nan)
            f = np.full(mus.shape, np.nan)
            for i, mu in enumerate(mus):
                try:
                    law = wa.gap_law(model, alpha, mu, [0.5])
                except (wa.ConvergenceError, ValueError):
                    continue
                w[i], f[i] = law.W_star, law.W_fraction
            out[model, alpha] = (w, f)
    return out


def gap_events(model, alpha, mu):
    """Rows (stage, event, P*, gbar*) of `wavyadhesion path --control gap`."""
    cmd = ["fpm", "run", "--profile", "release", "wavyadhesion", "--", "path", "--control", "gap",
           "--model", model, "--alpha", str(alpha), "--mu", str(mu), "--format", "csv"]
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    return [(int(r["stage"]), int(r["event"]), float(r["P_star"]), float(r["gbar"]))
            for r in csv.DictReader(io.StringIO(out))]


def jumps(events):
    """[(stage, gbar*, P_from, P_to)] of the jumps at constant gbar* (event 3 then 4)."""
    out = []
    for (s0, e0, p0, g0), (s1, e1, p1, g1) in zip(events, events[1:]):
        if s0 == s1 and e0 in (3, 12) and e1 == 4:
            out.append((s0, g0, p0, p1))
    return out


def plot_energy_map(plt, mus, data, path):
    fig, (ax0, ax1) = plt.subplots(1, 2, figsize=(10.5, 4.3), constrained_layout=True)
    for alpha in ALPHAS:
        colour = COLOURS[alpha]
        for model, style in (("dw", "-"), ("md", "--")):
            w, f = data[model, alpha]
            pos = w > 0
            ax0.loglog(mus[pos], w[pos], style, color=colour, lw=1.5)
            ax1.semilogx(mus, f, style, color=colour, lw=1.5)
        jkr = wa.gap_law("jkr", alpha, 1.0, [0.5])
        ax0.axhline(jkr.W_star, color=colour, ls=":", lw=1.0)
        ax1.axhline(jkr.W_fraction, color=colour, ls=":", lw=1.0)
    ax0.set_xlabel("transition parameter μ")
    ax0.set_ylabel("W* = −∮ P* dḡ*   (units p*Δ per unit area)")
    ax0.set_title("(a) energy lost per cycle under gap control", fontsize=10)
    ax0.set_ylim(1e-9, 2)
    ax1.set_xlabel("transition parameter μ")
    ax1.set_ylabel("W* / (πα²/2)   (fraction of the work of adhesion)")
    ax1.set_title("(b) fraction of the work of adhesion lost per cycle", fontsize=10)
    ax1.set_ylim(0, 0.56)
    for ax in (ax0, ax1):
        ax.set_xlim(mus[0], mus[-1])
        ax.grid(True, which="major", color="0.9", lw=0.6)
    handles = [plt.Line2D([], [], color=COLOURS[a], lw=2, label=f"α = {a:g}") for a in ALPHAS]
    handles += [plt.Line2D([], [], color="0.3", ls="-", label="DW"),
                plt.Line2D([], [], color="0.3", ls="--", label="MD"),
                plt.Line2D([], [], color="0.3", ls=":", label="JKR (μ → ∞ of DW)")]
    ax1.legend(handles=handles, loc="upper left", fontsize=8.5, frameon=True)
    fig.savefig(path, dpi=120)
    plt.close(fig)


def arrow_along(ax, x, y, colour, i):
    """An arrow head on the polyline (x, y) at index i, pointing to i + 1."""
    ax.annotate("", xy=(x[i + 1], y[i + 1]), xytext=(x[i], y[i]),
                arrowprops=dict(arrowstyle="-|>", color=colour, lw=0, mutation_scale=13))


def draw_loops(ax, model, alpha, mu, gmax, ylim, arrows):
    """P* on approach (solid) and retraction (dashed) up to gbar* = gmax; arrows = (fractions of
    gmax where approach arrows go, fractions for retraction arrows)."""
    colour = MODEL_COLOURS[model]
    events = gap_events(model, alpha, mu)
    js = jumps(events)
    g_events = sorted({g for (_, _, _, g) in events if g > 0})
    grid = np.linspace(0.0, gmax, 1601)[1:]
    extra = [g * (1 + s * 1e-12) for g in g_events for s in (-1, 1) if g < gmax]
    grid = np.unique(np.concatenate([grid, extra]))
    law = wa.gap_law(model, alpha, mu, grid)
    full = [p for (s, e, p, g) in events if e == 5][0]          # P* where full contact is reached
    for stage, p_curve, style in ((1, law.P_approach, "-"), (2, law.P_retract, "--")):
        # break the polyline at the jumps (no slanted segment across a jump)
        p = p_curve.copy()
        g = grid.copy()
        for (s, gj, _, _) in js:
            if s == stage and gj < gmax:
                k = np.searchsorted(g, gj)
                g = np.insert(g, k, gj)
                p = np.insert(p, k, np.nan)
        g = np.concatenate([[0.0], g])
        p = np.concatenate([[full], p])
        ax.plot(g, p, style, color=colour, lw=1.5)
        if arrows:
            # direction: approach towards smaller gbar*, retraction towards larger
            for frac in arrows[stage - 1]:
                i = int(frac * (len(g) - 2))
                while i < len(g) - 2 and not (np.isfinite(p[i]) and np.isfinite(p[i + 1])
                                              and ylim[0] < p[i] < ylim[1]):
                    i += 1
                if i < len(g) - 2:
                    if stage == 1:
                        arrow_along(ax, g[::-1], p[::-1], colour, len(g) - 2 - i)
                    else:
                        arrow_along(ax, g, p, colour, i)
    for (s, gj, p0, p1) in js:
        if gj > gmax:
            continue
        ax.annotate("", xy=(gj, p1), xytext=(gj, p0),
                    arrowprops=dict(arrowstyle="-|>", color=colour, lw=1.1,
                                    ls="-" if s == 1 else "--", shrinkA=0, shrinkB=0))
    # full contact: the vertical axis gbar* = 0, P* >= P*(a* -> 1/2)
    ax.plot([0, 0], [full, ylim[1]], color=colour, lw=3, alpha=0.5, solid_capstyle="butt")
    return law.W_star, js


def plot_loops(plt, path, alpha=0.3, mus=(1.0, 5.0)):
    fig, axes = plt.subplots(len(mus), 2, figsize=(10.5, 7.6), constrained_layout=True,
                             gridspec_kw={"width_ratios": [1.5, 1]})
    zoom = {1.0: (0.1, (-0.05, 0.65)), 5.0: (0.012, (-1.45, 0.25))}
    report = []
    for row, mu in enumerate(mus):
        ax, axz = axes[row]
        for model in ("dw", "md"):
            w, js = draw_loops(ax, model, alpha, mu, 1.5, (-0.16, 0.5), arrows=((0.4, 0.93), (0.25, 0.86)))
            gz, ylz = zoom[mu]
            draw_loops(axz, model, alpha, mu, gz, ylz, arrows=((0.3,), (0.7,)))
            report.append((model, mu, w, js))
        ax.set_xlim(-0.02, 1.5)
        ax.set_ylim(-0.16, 0.5)
        axz.set_xlim(-0.02 * zoom[mu][0], zoom[mu][0])
        axz.set_ylim(*zoom[mu][1])
        ax.axhline(0, color="0.75", lw=0.7, zorder=0)
        axz.axhline(0, color="0.75", lw=0.7, zorder=0)
        ax.set_title(f"α = {alpha:g}, μ = {mu:g}: whole range (P* clipped above 0.5)", fontsize=10)
        axz.set_title(f"α = {alpha:g}, μ = {mu:g}: near full contact", fontsize=10)
        for a in (ax, axz):
            a.set_xlabel("mean gap ḡ* = ḡ/Δ")
            a.set_ylabel("P*  (mean traction / p*)")
    handles = [plt.Line2D([], [], color=MODEL_COLOURS["dw"], lw=2, label="DW"),
               plt.Line2D([], [], color=MODEL_COLOURS["md"], lw=2, label="MD"),
               plt.Line2D([], [], color="0.3", ls="-", label="approach (ḡ* falling)"),
               plt.Line2D([], [], color="0.3", ls="--", label="retraction (ḡ* rising)"),
               plt.Line2D([], [], color="0.3", lw=3, alpha=0.5, label="full contact (ḡ* = 0)")]
    axes[0, 0].legend(handles=handles, loc="upper right", fontsize=8.5)
    fig.suptitle("Gap control: P* against the mean gap; jumps at constant ḡ* (vertical arrows); "
                 "W* = area between approach and retraction", fontsize=10)
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return report


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--outdir", default="doc/figures")
    ap.add_argument("--points", type=int, default=37, help="mu values (log-spaced, 1e-3..1e3)")
    opts = ap.parse_args()
    t0 = time.time()

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    mus = np.logspace(-3, 3, opts.points)
    data = energy_map(mus)
    plot_energy_map(plt, mus, data, f"{opts.outdir}/energy_lost_dw_md.png")
    t1 = time.time()
    report = plot_loops(plt, f"{opts.outdir}/gap_loops_alpha0.3.png")
    t2 = time.time()
    print(f"energy map {t1 - t0:.1f} s, loops {t2 - t1:.1f} s")
    for model in ("dw", "md"):
        for alpha in ALPHAS:
            w, f = data[model, alpha]
            k = int(np.nanargmax(f))
            print(f"{model} alpha {alpha:g}: max W*/(pi alpha^2/2) = {f[k]:.4f} at mu = {mus[k]:.3g};"
                  f" mu = 1: {np.interp(0.0, np.log(mus), f):.4f}; mu = 1e3: {f[-1]:.4f};"
                  f" failed: {int(np.isnan(f).sum())}")
    # "smaller waviness induces more energy loss", in energy: the loss per unit area is
    # W*/(pi alpha^2/2) * work of adhesion; at fixed materials and period a smaller amplitude
    # raises alpha ~ 1/Delta and mu ~ Delta^(-1/3) ~ alpha^(1/3)
    for mu0 in (0.3, 1.0, 3.0, 10.0, 1000.0):
        for model in ("dw", "md"):
            fixed = [wa.gap_law(model, a, mu0, [0.5]).W_fraction for a in ALPHAS]
            line = [wa.gap_law(model, a, mu0 * (a / ALPHAS[0]) ** (1 / 3), [0.5]).W_fraction
                    for a in ALPHAS]
            print(f"{model} W*/(pi alpha^2/2) at alpha 0.3, 0.6, 1: mu = {mu0:g} fixed: "
                  + ", ".join(f"{f:.4f}" for f in fixed)
                  + f"; mu = {mu0:g} (alpha/0.3)^(1/3): " + ", ".join(f"{f:.4f}" for f in line))
    print("jkr W*/(pi alpha^2/2) at alpha 0.3, 0.6, 1, 3, 10, 30: " + ", ".join(
        f"{wa.gap_law('jkr', a, 1.0, [0.5]).W_fraction:.4f}" for a in (0.3, 0.6, 1, 3, 10, 30)))
    for model, mu, w, js in report:
        print(f"{model} alpha 0.3 mu {mu:g}: W* = {w:.6g}; jumps (stage, gbar*, P from -> to): "
              + "; ".join(f"{s} {g:.5g} {p0:.4g} -> {p1:.4g}" for s, g, p0, p1 in js))


if __name__ == "__main__":
    main()
