#!/usr/bin/env python3
"""Draw a traced branch and its load path from the CLI's csv output.

    python3 tools/figures/plot_branch.py --model dw --alpha 0.3 --mu 5 -o doc/figures/branch_dw_alpha0.3_mu5.png

Runs `wavyadhesion branch` and `wavyadhesion path` (built by fpm, release profile) and plots
P* against a*: stable pieces solid, unstable dashed, case 2 (c* = 1/2) in a second colour,
folds and case switches marked, the loading and unloading jumps as arrows.
matplotlib is imported here only; the library and the CLI never need it.
"""
import argparse
import csv
import io
import subprocess


def run_cli(*args):
    cmd = ["fpm", "run", "--profile", "release", "wavyadhesion", "--", *args, "--format", "csv"]
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    return list(csv.DictReader(io.StringIO(out)))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--model", default="dw")
    ap.add_argument("--alpha", default="0.3")
    ap.add_argument("--mu", default="5")
    ap.add_argument("-o", "--output", required=True)
    opts = ap.parse_args()
    common = ["--model", opts.model, "--alpha", opts.alpha, "--mu", opts.mu]
    branch = run_cli("branch", *common)
    path = run_cli("path", *common)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    a = [float(r["a_star"]) for r in branch]
    p = [float(r["P_star"]) for r in branch]
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    # contiguous runs of one kind (stable or not, case 1 or 2) as single polylines
    kinds = [(r_stable(branch, i), branch[i]["zone_case"] != "1" and branch[i + 1]["zone_case"] != "1")
             for i in range(len(a) - 1)]
    start = 0
    for i in range(1, len(kinds) + 1):
        if i == len(kinds) or kinds[i] != kinds[start]:
            stable, case2 = kinds[start]
            ax.plot(a[start:i + 1], p[start:i + 1], linestyle="-" if stable else (0, (4, 3)),
                    color="tab:purple" if case2 else "tab:red", lw=1.6)
            start = i
    marker = {"1": "o", "2": "s", "9": "^"}         # fold, case switch, a*-turn
    for r in branch:
        if r["event"] in marker:
            ax.plot(float(r["a_star"]), float(r["P_star"]), marker[r["event"]], color="k", ms=4)
    pts = [(int(r["stage"]), int(r["event"]), float(r["a_star"]), float(r["P_star"])) for r in path]
    for (s0, e0, a0, p0), (s1, e1, a1, p1) in zip(pts, pts[1:]):
        if s0 == s1 and e0 == 3 and abs(p0) != float("inf"):
            target = 0.0 if e1 == 7 else a1          # a pull-off jump leaves contact: to a* = 0
            ax.annotate("", xy=(target, p1), xytext=(a0, p0),
                        arrowprops=dict(arrowstyle="->", color="tab:blue" if s0 == 1 else "tab:green"))
    ax.axhline(0.0, color="0.7", lw=0.8)
    ax.set_xlabel("a* = a/L")
    ax.set_ylabel("P*")
    ax.set_title(f"{opts.model.upper()}  alpha = {opts.alpha}, mu = {opts.mu}: "
                 "branch (solid stable, dashed unstable; purple c* = 1/2),\n"
                 "folds (o), case switches (s), a*-turns (^), loading (blue) and unloading (green) jumps",
                 fontsize=8)
    ax.set_xlim(0, 0.5)
    fig.tight_layout()
    fig.savefig(opts.output, dpi=120)


def r_stable(branch, i):
    # the library's flag (stability changes only at extrema of P*, not at a*-turns): a
    # segment is stable where one of its ends is (the other may be the fold that ends it)
    return branch[i]["stable"] == "1" or branch[i + 1]["stable"] == "1"


if __name__ == "__main__":
    main()
