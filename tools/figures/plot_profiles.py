#!/usr/bin/env python3
"""Draw traction and gap profiles of DW and MD states (cf. the paper's Figs. 2-3).

    .venv/bin/python tools/figures/plot_profiles.py -o doc/figures/profiles_alpha0.3_mu1.png

Uses the installed Python package (`pip install ./python`): wavyadhesion.profile for the
principal state at each a*. Top row: traction p/p* against x*; bottom row: gap h/Delta.
Left DW, right MD; one colour per a*; the contact edges +-a* and the zone edges +-c* are
marked on the gap axes. matplotlib is imported here only.
"""
import argparse

import numpy as np
import wavyadhesion as wa


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--alpha", type=float, default=0.3)
    ap.add_argument("--mu", type=float, default=1.0)
    ap.add_argument("--a-star", type=float, nargs="+", default=[0.2, 0.3])
    ap.add_argument("-o", "--output", required=True)
    opts = ap.parse_args()

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    x = np.linspace(-0.5, 0.5, 2001)
    fig, axes = plt.subplots(2, 2, figsize=(9.0, 6.2), sharex=True, sharey="row",
                             constrained_layout=True)
    colours = ["tab:blue", "tab:orange", "tab:green", "tab:red"]
    for col, model in enumerate(("dw", "md")):
        for k, a in enumerate(opts.a_star):
            eq = wa.equilibrium(model, opts.alpha, opts.mu, a)
            _, t, h = wa.profile(model, opts.alpha, opts.mu, a, x=x)
            colour = colours[k % len(colours)]
            label = (f"a* = {a:g}: c* = {float(eq.c_star):.3f}, P* = {float(eq.P_star):.3f}, "
                     f"gbar* = {float(eq.gbar):.3f}")
            axes[0, col].plot(x, t, color=colour, lw=1.4, label=label)
            axes[1, col].plot(x, h, color=colour, lw=1.4, label=label)
            for edge, style in ((a, "-"), (float(eq.c_star), ":")):
                for sign in (-1, 1):
                    axes[1, col].axvline(sign * edge, color=colour, lw=0.7, ls=style, alpha=0.6)
        axes[0, col].axhline(0.0, color="0.5", lw=0.6)
        axes[0, col].set_title(f"{model.upper()}, alpha = {opts.alpha:g}, mu = {opts.mu:g}")
        axes[1, col].legend(fontsize=7.5, loc="upper center", title_fontsize=7.5,
                            title="vertical lines: contact edges +-a* (solid), zone edges +-c* "
                                  "(dotted)", framealpha=0.95)
        axes[1, col].set_xlabel("x* = x/L (crest at 0)")
        axes[1, col].set_xlim(-0.5, 0.5)
    axes[0, 0].set_ylabel("traction p/p* (compressive > 0)")
    axes[1, 0].set_ylabel("gap h/Delta")
    axes[1, 0].set_ylim(top=1.75)
    fig.savefig(opts.output, dpi=110)


if __name__ == "__main__":
    main()
