#!/usr/bin/env python3
"""Summary of the tamaas cross-check's per-point rows (study/results/bem_md_points.txt).

    python study/bem/summarize_bem.py study/results/bem_md_points.txt

For each case (alpha, mu) and N: the lattice-trapping width (the largest |P*_approach -
P*_retract| of the BEM at the grid points where the library has a single state and no
event is near, i.e. where the two BEM sweeps would coincide without the grid), the
largest |dP*| of approach, retraction and their average there, and for each case the
least-squares convergence order p of max|dP*| ~ N^-p over all N.  Only numpy.
"""
import sys
from collections import defaultdict

import numpy as np


def main(path):
    rows = defaultdict(dict)  # (alpha, mu, N) -> {(stage, gbar): fields}
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            t = line.split()
            alpha, mu, n, stage, g = float(t[0]), float(t[1]), int(t[2]), t[3], float(t[4])
            rows[(alpha, mu, n)][(stage, g)] = dict(
                p=float(t[5]), pl=float(t[6]), a=float(t[7]), al=float(t[8]),
                c=float(t[9]), cl=float(t[10]), near=int(t[12]))
    out = defaultdict(list)
    print("# alpha mu N  trapping_width  max|dP*| approach retract average  "
          "max|da*| average  max|dc*| average  (single-valued points away from events)  "
          "max|dP*| near events (either sweep)")
    for (alpha, mu, n), r in sorted(rows.items()):
        gs = sorted({g for (_, g) in r})
        trap, dpa, dpr, dpm, dam, dcm = [], [], [], [], [], []
        near = [abs(v["p"] - v["pl"]) for v in r.values() if v["near"]]
        for g in gs:
            ap, re = r[("approach", g)], r[("retract", g)]
            if ap["near"] or re["near"] or abs(ap["pl"] - re["pl"]) > 1e-12:
                continue
            trap.append(abs(ap["p"] - re["p"]))
            dpa.append(abs(ap["p"] - ap["pl"]))
            dpr.append(abs(re["p"] - re["pl"]))
            dpm.append(abs(0.5 * (ap["p"] + re["p"]) - ap["pl"]))
            dam.append(abs(0.5 * (ap["a"] + re["a"]) - ap["al"]))
            dcm.append(abs(0.5 * (ap["c"] + re["c"]) - ap["cl"]))
        vals = [max(v) for v in (trap, dpa, dpr, dpm, dam, dcm)]
        out[(alpha, mu)].append((n, vals))
        print(f"{alpha:g} {mu:g} {n:6d}  {vals[0]:.2e}  {vals[1]:.2e} {vals[2]:.2e} "
              f"{vals[3]:.2e}  {vals[4]:.1e}  {vals[5]:.1e}  {max(near):.2e}  "
              f"({len(trap)} points)")
    print("# least-squares order p in max ~ N^-p over the N of each case")
    names = ("trapping", "dP approach", "dP retract", "dP average", "da average",
             "dc average")
    for (alpha, mu), lst in out.items():
        n = np.log([x[0] for x in lst])
        orders = []
        for j in range(6):
            y = np.log([x[1][j] for x in lst])
            orders.append(-np.polyfit(n, y, 1)[0])
        print(f"{alpha:g} {mu:g}: " + ", ".join(f"{nm} {o:.2f}" for nm, o in zip(names, orders)))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "study/results/bem_md_points.txt")
