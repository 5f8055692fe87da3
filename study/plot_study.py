#!/usr/bin/env python3
"""Work-precision plot of the study (doc/accuracy-performance.md) from the tables that
`fpm run --profile release wavyadhesion-study` writes into build/study:

  python3 study/plot_study.py [build/study] [doc/figures]

writes doc/figures/work_precision.png: error against time per equilibrium point, log-log,
DW (left) and MD (right); top row the worst error over the point set, bottom row the median;
each numerical choice is one series (its tolerance sweep joined by a line), the library's
default is the star, the dashed staircase is the Pareto front of the worst error.
Failed points (no state, wrong case) count as error 1 (top edge).
"""
import os
import shlex
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

STYLE = {
    "dw": [("agm", "AGM closed form, Brent xtol 1e-4..1e-15", "C0", "o"),
           ("carlson", "Carlson form (GSL R_F, R_D, R_J)", "C3", "s"),
           ("tanh-sinh", "tanh-sinh quadrature, rtol 1e-4..1e-15", "C2", "^"),
           ("qag", "GSL QAG of (E1), epsrel 1e-4..1.2e-14", "C1", "v")],
    "md": [("lib-rules", "fixed Gauss rules (library), Brent xtol 1e-4..1e-15", "C0", "o"),
           ("gauss", "Gauss-log + Gauss-Legendre, 16/32/64 nodes", "C4", "D"),
           ("qaws", "GSL QAWS + QAG, epsrel 1e-6..1.2e-14", "C2", "^"),
           ("qag", "GSL QAG, epsrel 1e-6..1.2e-14", "C1", "v"),
           ("qags", "GSL QAGS, epsrel 1e-6..1.2e-14", "C3", "s")],
}


def read_rows(path):
    rows, npts = [], 0
    with open(path) as f:
        for line in f:
            if line.startswith("# work-precision,"):
                npts = int(line.split()[2])
            if line.startswith("#") or not line.strip():
                continue
            w = shlex.split(line)
            rows.append(dict(method=w[0], tol=float(w[1]), xtol=float(w[2]), lib=w[3] == "T",
                             max=min(float(w[4]), 1.0), med=min(float(w[5]), 1.0),
                             time=float(w[8]), label=w[10]))
    return rows, npts


def pareto(points):
    """Non-dominated (time, err) points, sorted by time."""
    front = []
    for t, e in sorted(points):
        if not front or e < front[-1][1]:
            front.append((t, e))
    return front


def main():
    src = sys.argv[1] if len(sys.argv) > 1 else "build/study"
    dst = sys.argv[2] if len(sys.argv) > 2 else "doc/figures"
    fig, axes = plt.subplots(2, 2, figsize=(12, 10), sharex="col")
    for col, model in enumerate(("dw", "md")):
        rows, npts = read_rows(os.path.join(src, "wp_%s.txt" % model))
        peer = []
        if model == "dw" and os.path.exists(os.path.join(src, "peer_summary.txt")):
            with open(os.path.join(src, "peer_summary.txt")) as f:
                for line in f:
                    if line.startswith("scipy"):
                        w = line.split()
                        peer.append((w[0], min(float(w[1]), 1.0), min(float(w[2]), 1.0), float(w[5])))
        for row, key in enumerate(("max", "med")):
            ax = axes[row, col]
            for method, label, color, marker in STYLE[model]:
                sel = [r for r in rows if r["method"] == method and not r["lib"]
                       and "replica" not in r["label"] and "their defaults" not in r["label"]]
                sel.sort(key=lambda r: r["time"])
                ax.plot([r["time"] for r in sel], [r[key] for r in sel], marker=marker, color=color,
                        label=label, lw=1, ms=5)
            lib = [r for r in rows if r["lib"]][0]
            ax.plot([lib["time"]], [lib[key]], "*", color="k", ms=16, zorder=5,
                    label="library default (%s call)" % ("dw_equilibrium" if model == "dw" else "md_equilibrium"))
            for name, emax, emed, t in peer:
                ax.plot([t], [emax if key == "max" else emed], "P", ms=10,
                        color="C5" if "default" in name else "C6",
                        label="%s (study/peer_scipy.py)" % name.replace("-", " "))
            pts = [(r["time"], r[key]) for r in rows] + [(p[3], p[1] if key == "max" else p[2]) for p in peer]
            front = pareto(pts)
            xs, ys = [], []
            for t, e in front:
                if xs:
                    xs.append(t); ys.append(ys[-1])
                xs.append(t); ys.append(e)
            ax.plot(xs + [ax.get_xlim()[1] * 10], ys + [ys[-1]], "k--", lw=0.8, label="Pareto front")
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.axhline(1e-12, color="grey", lw=0.6, ls=":")
            ax.set_ylim(1e-16, 3)
            ax.set_xlim(0.3 if model == "dw" else 2, 5e3 if model == "dw" else 2e3)
            ax.grid(True, which="major", lw=0.3)
            if row == 1:
                ax.set_xlabel("time per equilibrium point [µs] (one core, best pass)")
            ax.set_ylabel(("worst" if key == "max" else "median") + " error over the points (accuracy-target measure)")
            n = {"dw": "DW: %d case-1 points of test/data/dw.txt" % npts,
                 "md": "MD: %d points of test/data/md.txt" % npts}[model]
            ax.set_title("%s — %s error" % (n, "worst" if key == "max" else "median"), fontsize=10)
            if row == 1:
                ax.legend(fontsize=7.5, loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=2)
    fig.tight_layout()
    os.makedirs(dst, exist_ok=True)
    out = os.path.join(dst, "work_precision.png")
    fig.savefig(out, dpi=110)
    print("wrote", out)


if __name__ == "__main__":
    main()
