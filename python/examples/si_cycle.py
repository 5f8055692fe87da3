"""From SI inputs to SI results, with no unit factor written by hand: a soft wavy
elastomer against a rigid flat (Maugis-Dugdale model). Prints the pull-off force in N/m,
the energy lost per gap-controlled cycle in J/m^2, and plots the cycle (force per unit
length against the mean gap in m) to si_cycle.png.

    python python/examples/si_cycle.py [--out DIR]

DIR defaults to the current directory. Needs the installed package (pip install
./python); the plot needs matplotlib (skipped, with a note, without it).
"""

import argparse
from pathlib import Path

import numpy as np

import wavyadhesion as wa


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path.cwd(),
                        help="folder for si_cycle.png (default: the current directory)")
    out = parser.parse_args().out

    # --- the problem in SI units -------------------------------------------------------
    params = wa.Params.from_dimensional(
        Estar=1e6,               # reduced modulus E* [Pa]
        period=1e-3,             # period L [m]
        amplitude=1e-5,          # amplitude Delta [m]
        work_of_adhesion=0.05,   # [J/m^2]
        peak_stress=1e5,         # peak adhesive stress [Pa]
    )
    print(f"alpha = {params.alpha:.4f}, mu = {params.mu:.4f}")

    # --- load control: the pull-off force ----------------------------------------------
    crit = wa.critical_forces("md", params.alpha, params.mu).to_si(params)
    print(f"pull-off force: {crit.F_pf:.4f} {crit.units['F_pf']}"
          f" (mean traction {crit.P_pf:.1f} {crit.units['P_pf']})")

    # --- gap control: the cycle and the energy it loses ---------------------------------
    path = wa.gap_path("md", params.alpha, params.mu)
    law = wa.gap_law("md", params.alpha, params.mu,
                     np.linspace(0.0, 1.1 * max(path.g_touch, path.gbar.max()), 801))
    cycle = law.to_si(params)
    print(f"energy lost per cycle: {cycle.W:.4g} {cycle.units['W']}"
          f" ({law.W_fraction:.1%} of the work of adhesion)")

    try:
        import matplotlib
    except ImportError:
        print("matplotlib is not installed: no plot")
        return
    matplotlib.use("Agg")                 # headless: only a file is written
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(cycle.gbar, cycle.F_approach, label="approach")
    ax.plot(cycle.gbar, cycle.F_retract, "--", label="retraction")
    ax.axhline(0.0, color="0.7", lw=0.8)
    ax.set_xlabel(rf"mean gap $\bar g$ [{cycle.units['gbar']}]")
    ax.set_ylabel(f"force per unit length [{cycle.units['F_approach']}]")
    ax.set_title(f"MD, gap control: W = {cycle.W:.3g} {cycle.units['W']} per cycle")
    ax.legend()
    fig.tight_layout()
    out.mkdir(parents=True, exist_ok=True)
    path_png = out / "si_cycle.png"
    fig.savefig(path_png, dpi=100)
    print(f"wrote {path_png}")


if __name__ == "__main__":
    main()
