#!/usr/bin/env python3
"""Draw the paper's Fig. 5 from the library: DW, MD and the smooth Lennard-Jones model (LJ).

    .venv/bin/python tools/figures/plot_fig5_lj.py --outdir doc/figures

Writes fig5_dw_md_lj.png (into --outdir, default the current directory): for each
(alpha, mu) in PANELS, on top P* against b* and below P* against the mean gap gbar*, for
DW and MD (curves of `wavyadhesion.trace_branch`) and LJ (`trace_branch("lj", ...)` at the
automatic grid). b* is the paper's convention for comparing a cohesive zone with a smooth
law: b* = a* + 0.4 (c* - a*) for DW and MD, and for LJ the position of the peak tension
(half the measure of {h <= 3^(1/6) eps}); gbar* needs no edge convention. The LJ law has
the same work of adhesion and the range eps = dgamma/sigma0 (the MD opening), so mu means
the same for the three models (LJ's peak tension is then 16/(9 sqrt 3) sigma0).
The paper does not state Fig. 5's alpha and mu; PANELS are those of its Figs. 4, 6 and 7
(alpha 0.3 and 0.6, mu 1 and 3), covering its remark that the models agree for small
alpha and large mu and differ for large alpha and small mu. LJ curves are drawn from
contact (a* > 0) and from far apart up to gbar* = 1.6 (the trace starts at 500 eps).
Uses the installed Python package (`pip install ./python`); matplotlib is imported here only.
Prints the grid N and P_fc, P_pf with their error estimates for each panel.
"""
import argparse
import time
from pathlib import Path

import numpy as np

import wavyadhesion as wa

PANELS = ((0.3, 1.0), (0.3, 3.0), (0.6, 1.0), (0.6, 3.0))
STYLE = {"dw": ("tab:blue", "-", "DW"), "md": ("tab:red", "--", "MD"),
         "lj": ("black", "-", "LJ")}
GBAR_MAX = 1.6


def curves(alpha, mu):
    """{model: (b*, gbar*, P*)} of the three models at (alpha, mu)."""
    out = {}
    for model in ("dw", "md", "lj"):
        b = wa.trace_branch(model, alpha, mu)
        out[model] = (b.b_star, b.gbar, b.P_star)
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--outdir", default=".", help="directory of the PNG (default: cwd)")
    args = parser.parse_args()
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    start = time.perf_counter()
    fig, axes = plt.subplots(2, len(PANELS), figsize=(4 * len(PANELS), 7.2))
    for k, (alpha, mu) in enumerate(PANELS):
        data = curves(alpha, mu)
        c = wa.critical_forces("lj", alpha, mu)
        print(f"alpha = {alpha}, mu = {mu}: LJ N = {int(c.N)}, P_fc = {float(c.P_fc):.10f} "
              f"+- {float(c.P_fc_err):.1e}, P_pf = {float(c.P_pf):.10f} "
              f"+- {float(c.P_pf_err):.1e}")
        top, bottom = axes[0, k], axes[1, k]
        for model, (b_star, gbar, p_star) in data.items():
            colour, line, label = STYLE[model]
            with np.errstate(invalid="ignore"):
                near = gbar <= GBAR_MAX
            top.plot(b_star, p_star, color=colour, ls=line, lw=1.2, label=label)
            bottom.plot(np.where(near, gbar, np.nan), p_star, color=colour, ls=line,
                        lw=1.2, label=label)
        top.set_title(rf"$\alpha$ = {alpha}, $\mu$ = {mu}")
        top.set_xlabel(r"$b^*$ (DW, MD: $a^* + 0.4(c^* - a^*)$; LJ: peak tension)")
        bottom.set_xlabel(r"mean gap $\bar g^*$")
        top.set_xlim(0, 0.5)
        bottom.set_xlim(0, GBAR_MAX)
        for ax in (top, bottom):
            ax.axhline(0, color="0.7", lw=0.6)
            ax.grid(alpha=0.3)
        if k == 0:
            top.set_ylabel(r"$P^*$")
            bottom.set_ylabel(r"$P^*$")
            top.legend(loc="upper left")
    fig.suptitle("P* against b* and against the mean gap: DW, MD and Lennard-Jones "
                 "(same work of adhesion, range = MD opening)")
    fig.tight_layout()
    out = Path(args.outdir) / "fig5_dw_md_lj.png"
    fig.savefig(out, dpi=110)
    print(f"wrote {out} in {time.perf_counter() - start:.1f} s")


if __name__ == "__main__":
    main()
