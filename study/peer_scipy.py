#!/usr/bin/env python3
"""The peer a user would otherwise write: the double-Westergaard equilibrium at given a*
straight from the paper's equations ((2.22)-(2.28), doc/theory.md) with scipy.integrate.quad
and scipy.optimize.brentq, one point at a time. Used by wavyadhesion-study (study/main.f90),
which times it in the same run as the library and computes its error against mpmath.

  Case 1 (a* < c* < 1/2): find C = sin(pi c*) in (A, 1) with
      F(C) = lam (1 + lam) (16/(pi alpha^2)) I*(A, C) - 1 = 0,
      lam = Sigma0 / (2 sqrt(1-A^2) sqrt(C^2-A^2)),
      I*  = int_A^C sqrt(1-X^2) sqrt(C^2-X^2) sqrt(X^2-A^2) dX          (scipy quad)
  then c* = asin(C)/pi and P* = A^2 - (Sigma0/2) sqrt((C^2-A^2)/(1-A^2)).
  Case 2 (c* = 1/2, P* = A^2 - Sigma0/2) where F(1) <= 0.

Configurations: "default" = scipy's default tolerances (quad epsabs = epsrel = 1.49e-8,
brentq xtol = 2e-12, rtol = 8.9e-16); "tight" = quad epsabs = 0, epsrel = 1e-13, limit 200,
brentq xtol = 1e-300 (relative tolerance 4 eps only).

  python3 study/peer_scipy.py points IN OUT [--config default|tight] [--repeat 3]
      IN: lines "alpha mu a_star" ('#' comments); OUT: one line per point
      "alpha mu a_star c_star P_star zone_case status seconds" (status 0 ok, 1 failed),
      seconds = wall time of that point's solve (time.perf_counter), the best of --repeat
      solves (the machine may be shared; the library is timed the same way).
"""
import argparse
import math
import sys
import time

from scipy.integrate import quad
from scipy.optimize import brentq

CONFIGS = {
    "default": dict(quad=dict(), brentq=dict()),
    "tight": dict(quad=dict(epsabs=0.0, epsrel=1e-13, limit=200),
                  brentq=dict(xtol=1e-300, rtol=4 * 2.220446049250313e-16, maxiter=200)),
}


def dw_point(alpha, mu, a_star, cfg):
    """(c*, P*, zone_case) of the principal DW state at a* (case 1 if it exists)."""
    qopt, bopt = cfg["quad"], cfg["brentq"]
    sigma0 = math.pi * mu * (alpha ** 2 / 32.0) ** (1.0 / 3.0)
    A = math.sin(math.pi * a_star)

    def istar(C):
        f = lambda X: math.sqrt(1 - X * X) * math.sqrt(C * C - X * X) * math.sqrt(X * X - A * A)
        return quad(f, A, C, **qopt)[0]

    def F(C):
        lam = sigma0 / (2 * math.sqrt(1 - A * A) * math.sqrt(C * C - A * A))
        return lam * (1 + lam) * 16 / (math.pi * alpha ** 2) * istar(C) - 1

    if F(1.0) <= 0:                                      # (2.28b): case 2
        return 0.5, A * A - sigma0 / 2, 2
    lo = A * (1 + 1e-15) + 1e-300                        # just above C = A, where F -> -1
    C = brentq(F, lo, 1.0, **bopt)
    P = A * A - sigma0 / 2 * math.sqrt((C * C - A * A) / (1 - A * A))
    return math.asin(C) / math.pi, P, 1


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("what", choices=["points"])
    ap.add_argument("inp")
    ap.add_argument("out")
    ap.add_argument("--config", choices=sorted(CONFIGS), default="default")
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    cfg = CONFIGS[args.config]
    pts = []
    with open(args.inp) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            pts.append(tuple(float(x) for x in line.split()[:3]))
    lines = ["# scipy peer (%s): quad %s, brentq %s" % (args.config, cfg["quad"] or "defaults",
                                                        cfg["brentq"] or "defaults"),
             "# alpha mu a_star c_star P_star zone_case status seconds"]
    total = 0.0
    import warnings
    warnings.simplefilter("ignore")                      # quad's IntegrationWarning: the peer goes on
    for (al, mu, a) in pts:
        dt = float("inf")
        for _ in range(max(1, args.repeat)):
            t0 = time.perf_counter()
            try:
                c, p, zc = dw_point(al, mu, a, cfg)
                st = 0
            except Exception:                            # no bracket, NaN, ...: counted as failed
                c, p, zc, st = float("nan"), float("nan"), 0, 1
            dt = min(dt, time.perf_counter() - t0)
        total += dt
        lines.append("%r %r %r %r %r %d %d %.9e" % (al, mu, a, c, p, zc, st, dt))
    lines.append("# total %.6f s (sum of the best per-point times), %d points" % (total, len(pts)))
    with open(args.out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
