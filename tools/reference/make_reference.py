#!/usr/bin/env python3
"""Independent high-precision reference data for wavyadhesion (mpmath only).

Writes whitespace-separated tables into test/data/ (relative to the repository root):

  westergaard.txt    a_star P_star                                   P* = sin^2(pi a*)             (3.1)
  jkr.txt            alpha a_star P_star                             P* = sin^2(pi a*) - alpha sqrt(tan(pi a*))  (3.4)
  dw.txt             alpha mu a_star c_star gap P_star zone_case     double-Westergaard, (2.22)-(2.28)
  md.txt             alpha mu a_star c_star gap P_star zone_case     Maugis-Dugdale (2.27) + c*=1/2 extension
  dw_extended.txt, md_extended.txt                                   same columns, extended range (doc/theory.md)
  dw_nosolution.txt, md_nosolution.txt, ..._extended_nosolution.txt  alpha mu a_star where no state exists

Equations: doc/theory.md (the paper's numbers).  One row per equilibrium state: case-1 roots in increasing c*,
then the case-2 state (c* = 1/2) when it is valid.  gap = c* - a* is computed directly (no
cancellation), as are all differences below.

Numerical method (everything in mpmath; the scan that only brackets roots uses mpmath's fp
context, the roots and the printed values use mp at mp.dps = 34 (main) or 50 (extended)):

* The unknown c* is written as C = sin(pi c*) = A + s (1 - A), s in (0,1), and s = 1/(1+exp(-y)),
  q = 1 - s = 1/(1+exp(y)), y in R.  Then C - A = s(1-A), 1 - C = q(1-A), C^2 - A^2 = s(1-A)(C+A)
  and 1 - A = 2 sin^2(pi e/2), e = 1/2 - a*, are all formed without cancellation; y = +inf is C = 1.
  A uniform grid in y is log-spaced in c* - a* near a* and in 1/2 - c* near 1/2.
* DW: I* = chi1^4 J with X^2 = C^2 - chi1^2 sin^2(phi):
      J = int_0^{pi/2} sin^2 cos^2 sqrt(cC^2 + chi1^2 sin^2) / sqrt(A^2 + chi1^2 cos^2) dphi,
  cC = cos(pi c*) = sqrt((1-C)(1+C)), chi1^2 = C^2 - A^2; split at pi/4, the upper half written in
  psi = pi/2 - phi, each half graded geometrically towards its endpoint when the integrand has
  a complex singularity close to it (scales cC/chi1 and A/chi1).  Equation (2.25b) is solved as
      G = ln(16 J/(pi alpha^2)) + ln(Sigma0 chi1^2/(2 cA)) + ln(chi1 + Sigma0/(2 cA)) = 0.
* MD: Psi_c = -int_a^c ln|(chi3(c)+chi3(t))/(chi3(c)-chi3(t))| dt is split at the midpoint; the
  lower half is integrated in u = t - a*, the upper half in tau = c* - t, so that both endpoint
  singularities (sqrt at t = a*, log at t = c*) sit at 0 of their own variable, and
      chi3(c)-chi3(t) = A^2 (C^2 - S^2)/(S^2 C^2 (chi3(c)+chi3(t))),
      C^2 - S^2 = sin(pi tau) sin(pi (c+t)),  S^2 - A^2 = sin(pi u) sin(pi (t+a))
  (sin(pi x) near x = 1 from the accurately known 1 - x).  Both halves are graded
  geometrically when a*, 1 - 2a*, 1 - 2c* are small compared with the half width.
  P*_MD = A^2 - Sigma0 (2/pi) atan2(chi1, cC), chi2 = asinh(chi1/A).
  The scaled residual H = LHS(2.27b)/Dcod - 1 is scanned.
* Roots: scan y (coarse steps while the residual is still at its s -> 0 asymptote, then steps of
  0.5), sign changes are bracketed, every interior discrete extremum that does not change sign is
  checked by a golden-section search for a hidden pair of roots, and the interval (y_last, +inf)
  is checked against the value at C = 1.  Each bracket is refined by Illinois in fp, then by
  secant iterations at full precision (falls back to Illinois at full precision).

Usage:
  python3 tools/reference/make_reference.py [--only westergaard,jkr,dw,md,dw_extended,md_extended]
                                  [--jobs N] [--log /tmp/ref.log] [--full-md-extended]
  (run it in the background: nohup python3 tools/reference/make_reference.py > /tmp/ref.out 2>&1 &
   progress goes to the log; each file is written atomically when its grid is done, so a
   restart only needs --only for the missing files)
  python3 tools/reference/make_reference.py --check [--nrows 10] [--seed S]   # recompute random rows at dps 50
  python3 tools/reference/make_reference.py --verify                          # limit / cross checks
"""

import argparse
import mpmath
import math
import os
import random
import sys
import time

from mpmath import mp, fp

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))  # tools/reference/ -> the repository root
DATADIR = os.path.join(ROOT, "test", "data")

# ----------------------------------------------------------------------------------------------
# grids (the accuracy targets' main and extended ranges, doc/accuracy-performance.md)
ALPHA_MAIN = [0.01, 0.1, 0.3, 0.6, 1.0, 3.0, 10.0]
MU_MAIN = [0.001, 0.01, 0.1, 0.5, 1.0, 2.5, 3.0, 5.0, 10.0, 100.0, 1000.0]
A_MAIN = [1e-6, 1e-3, 0.01, 0.05, 0.1, 0.2, 0.25, 0.3, 0.4, 0.45, 0.49, 0.5 - 1e-6, 0.5 - 1e-9]
ALPHA_EXT = [1e-4, 1e-3]
MU_EXT = [1e4, 1e6]
A_EXT = [1e-12, 1e-9, 0.5 - 1e-12]
DPS_MAIN = 34
# md_extended.txt is thinned (MD at dps 50 costs ~3 s per point): these alpha, mu only; all a*
MD_EXT_ALPHA = [1e-4, 1e-3, 0.01, 0.3, 1.0, 10.0]
MD_EXT_MU = [0.001, 0.1, 1.0, 5.0, 100.0, 1000.0, 1e4, 1e6]
DPS_EXT = 50

LOGFILE = "/tmp/ref.log"


def log(msg):
    line = time.strftime("%H:%M:%S ") + msg
    with open(LOGFILE, "a") as f:
        f.write(line + "\n")


# ----------------------------------------------------------------------------------------------
# small helpers that work in both contexts (mp: arbitrary precision, fp: Python floats)

def asinh(ctx, x):
    return mp.asinh(x) if ctx is mp else math.asinh(x)


def sin_pi_pair(ctx, x, xc):
    """sin(pi x) for x in [0, 1] with xc = 1 - x known accurately."""
    return ctx.sinpi(x) if x <= 0.5 else ctx.sinpi(xc)


def graded(ctx, h, scale):
    """Break points 0, scale, 10 scale, ..., h (geometric grading towards 0)."""
    pts = [ctx.zero]
    if 0 < scale < h / 2:
        x = scale
        while x < h / 2:
            pts.append(x)
            x *= 10
    pts.append(h)
    return pts


class Point:
    """Fixed (alpha, mu, a*): the exact binary doubles given, evaluated in ctx."""

    def __init__(self, ctx, alpha, mu, a):
        self.ctx = ctx
        self.alpha = ctx.mpf(alpha)
        self.mu = ctx.mpf(mu)
        self.a = ctx.mpf(a)
        self.e = ctx.mpf(0.5) - self.a          # exact for doubles (fits in the working precision)
        self.A = ctx.sinpi(self.a)
        self.cA = ctx.sinpi(self.e)               # cos(pi a*)
        self.omA = 2 * ctx.sinpi(self.e / 2) ** 2   # 1 - A
        self.S0 = ctx.pi * self.mu * ctx.cbrt(self.alpha ** 2 / 32)
        self.Dcod = ctx.cbrt(self.alpha ** 4 / 2) / self.mu


class State:
    """Trial c* given by y (y = +inf: C = 1)."""

    def __init__(self, P, y):
        ctx = P.ctx
        A, cA, omA = P.A, P.cA, P.omA
        self.y = y
        if y == ctx.inf:
            s, q = ctx.one, ctx.zero
            C, cC = ctx.one, ctx.zero
            chi1sq = cA ** 2
        else:
            if y >= 0:
                ey = ctx.exp(-y)
                s, q = 1 / (1 + ey), ey / (1 + ey)
            else:
                ey = ctx.exp(y)
                s, q = ey / (1 + ey), 1 / (1 + ey)
            C = A + s * omA
            cC = ctx.sqrt(q * omA * (1 + C))
            chi1sq = s * omA * (C + A)
        self.s, self.q, self.C, self.cC = s, q, C, cC
        self.chi1sq = chi1sq
        self.chi1 = ctx.sqrt(chi1sq)
        # theta_c - theta_a, with sin = (C^2-A^2)/(C cA + A cC), cos = C A + cC cA
        self.g = ctx.atan2(chi1sq, (C * cA + A * cC) * (C * A + cC * cA)) / ctx.pi
        self.dc = ctx.atan2(cC, C) / ctx.pi          # 1/2 - c*
        self.c = ctx.atan2(C, cC) / ctx.pi


# ----------------------------------------------------------------------------------------------
# double-Westergaard

def dw_J(P, St):
    ctx = P.ctx
    A2 = P.A ** 2
    cC2 = St.cC ** 2
    k = St.chi1sq

    def f_low(p):          # phi in [0, pi/4]
        sp, cp = ctx.sin(p), ctx.cos(p)
        return (sp * cp) ** 2 * ctx.sqrt(cC2 + k * sp * sp) / ctx.sqrt(A2 + k * cp * cp)

    def f_up(p):           # psi = pi/2 - phi in [0, pi/4]
        sp, cp = ctx.cos(p), ctx.sin(p)
        return (sp * cp) ** 2 * ctx.sqrt(cC2 + k * sp * sp) / ctx.sqrt(A2 + k * cp * cp)

    h = ctx.pi / 4
    v1, e1 = ctx.quad(f_low, graded(ctx, h, St.cC / St.chi1), error=True)
    v2, e2 = ctx.quad(f_up, graded(ctx, h, P.A / St.chi1), error=True)
    return v1 + v2, e1 + e2


def dw_residual(P, St):
    """ln of the right side of (2.25b); 0 at equilibrium, -> -inf as c* -> a*."""
    ctx = P.ctx
    J, err = dw_J(P, St)
    return (ctx.log(16 * J / (ctx.pi * P.alpha ** 2)) + ctx.log(P.S0 * St.chi1sq / (2 * P.cA))
            + ctx.log(St.chi1 + P.S0 / (2 * P.cA))), err / J


def dw_load(P, St):
    return P.A ** 2 - P.S0 / 2 * St.chi1 / P.cA            # (2.25a)


# ----------------------------------------------------------------------------------------------
# Maugis-Dugdale

def md_Psi(P, St):
    ctx = P.ctx
    a, e, A = P.a, P.e, P.A
    C, g, dc, c = St.C, St.g, St.dc, St.c
    chi3c = St.chi1 / C
    A2C2 = A ** 2

    def core(t, u, tau, p):
        # t = a + u = c - tau, p = 1/2 - t; each given accurately
        S = ctx.sinpi(t)
        SmA = ctx.sinpi(u) * sin_pi_pair(ctx, t + a, e + p)       # S^2 - A^2
        CmS = ctx.sinpi(tau) * sin_pi_pair(ctx, c + t, dc + p)    # C^2 - S^2
        chi3 = ctx.sqrt(SmA) / S
        D = chi3c + chi3
        return ctx.log((D * S * C) ** 2 / (A2C2 * CmS))

    def f_low(u):
        return core(a + u, u, g - u, e - u)

    def f_up(tau):
        return core(c - tau, g - tau, tau, dc + tau)

    h = g / 2
    v1, e1 = ctx.quad(f_low, graded(ctx, h, min(a, 2 * e)), error=True)
    v2, e2 = ctx.quad(f_up, graded(ctx, h, min(2 * dc, e + dc)), error=True)
    return -(v1 + v2), e1 + e2


def md_load(P, St):
    ctx = P.ctx
    return P.A ** 2 - P.S0 * (2 / ctx.pi) * ctx.atan2(St.chi1, St.cC)   # (2.27a)


def md_lhs(P, St):
    ctx = P.ctx
    PM = md_load(P, St)
    chi2 = asinh(ctx, St.chi1 / P.A)
    Psi, err = md_Psi(P, St)
    return St.chi1 * St.C - PM * chi2 + P.S0 * Psi, P.S0 * err          # (2.27b) left side


def md_residual(P, St):
    lhs, err = md_lhs(P, St)
    return lhs / P.Dcod - 1, err / P.Dcod


def md_case2_opening(P):
    """sqrt(1-A^2) - A^2 ln((1+sqrt(1-A^2))/A), evaluated with doubled precision (cancellation
    near a* = 1/2).  Case 2 of MD is valid when this is <= Dcod."""
    with mp.workdps(2 * mp.dps + 20):
        a = mp.mpf(P.a)
        e = mp.mpf(0.5) - a
        A, cA = mp.sinpi(a), mp.sinpi(e)
        return +(cA - A ** 2 * mp.asinh(cA / A))


MODELS = {
    "dw": dict(residual=dw_residual, load=dw_load, deep=-8.0),
    "md": dict(residual=md_residual, load=md_load, deep=-0.999),
}


# ----------------------------------------------------------------------------------------------
# root finding

def _illinois(f, x0, f0, x1, f1, xtol, maxit=200):
    side = 0
    for _ in range(maxit):
        if abs(x1 - x0) <= xtol:
            break
        x2 = (x0 * f1 - x1 * f0) / (f1 - f0)
        if not (min(x0, x1) < x2 < max(x0, x1)):
            x2 = (x0 + x1) / 2
        f2 = f(x2)
        if f2 == 0:
            return x2, x2
        if (f2 > 0) == (f1 > 0):
            x1, f1 = x2, f2
            if side == -1:
                f0 /= 2
            side = -1
        else:
            x0, f0 = x2, f2
            if side == +1:
                f1 /= 2
            side = +1
    return x0, x1


def refine_root(model, alpha, mu, a, dps, y0, f0, y1, f1):
    """Root of the residual in (y0, y1) (fp values with opposite signs, y1 may be +inf)."""
    res = MODELS[model]["residual"]
    Pf = Point(fp, alpha, mu, a)
    ff = lambda y: res(Pf, State(Pf, y))[0]
    if y1 == fp.inf:           # move the open end in until the sign differs from f0
        yy = y0
        while True:
            yy = yy + 10
            fy = ff(yy)
            if (fy > 0) != (f0 > 0):
                y1, f1 = yy, fy
                break
            y0, f0 = yy, fy
            if yy > 700:
                raise RuntimeError("root at C -> 1 beyond y = 700")
    lo, hi = _illinois(ff, y0, f0, y1, f1, 1e-13 * max(1.0, abs(y0)))
    yf = (lo + hi) / 2
    # full precision: secant from the fp root, Illinois on the fp bracket as the fallback
    with mp.workdps(dps):
        P = Point(mp, alpha, mu, a)
        fm = lambda y: res(P, State(P, y))[0]
        ya = mp.mpf(yf)
        yb = ya + mp.mpf(1e-9) * max(1, abs(ya))
        fa, fb = fm(ya), fm(yb)
        tol = mp.mpf(10) ** (-dps + 4) * max(1, abs(ya))     # near the noise floor of the residual
        ok = False
        for _ in range(30):
            if fb == fa:
                break
            yc = yb - fb * (yb - ya) / (fb - fa)
            if not (min(y0, y1) < yc < max(y0, y1)):
                break
            ya, fa = yb, fb
            yb, fb = yc, fm(yc)
            if abs(yb - ya) < tol or fb == 0:
                ok = True
                break
        if not ok:
            lo, hi = _illinois(fm, mp.mpf(y0), fm(mp.mpf(y0)), mp.mpf(y1), fm(mp.mpf(y1)), tol)
            yb = (lo + hi) / 2
        St = State(P, yb)
        return St, P


def scan(model, alpha, mu, a, step=0.5, ylo=-120.0, yhi=100.0):
    """Bracket every sign change of the residual in y (fp).  Returns (brackets, f_inf, info)."""
    res = MODELS[model]["residual"]
    deep = MODELS[model]["deep"]
    P = Point(fp, alpha, mu, a)
    f = lambda y: res(P, State(P, y))[0]
    notes = []
    # left end: the residual must sit on its negative s -> 0 asymptote
    y = ylo
    fy = f(y)
    while fy >= deep:
        y -= 40
        fy = f(y)
        if y < -700:
            raise RuntimeError("residual not negative as c* -> a*")
    ys, fs = [y], [fy]
    coarse = []           # indices of points reached by a coarse step
    # coarse steps while deep on the asymptote (monotone there), then the fine grid
    while y < yhi:
        if fs[-1] < deep and y < -10:
            st = 4.0          # still on the s -> 0 asymptote
            coarse.append(len(ys))
        elif y < 30:
            st = step         # fine grid
        elif y < 60:
            st = 2 * step     # c* within ~1e-7 (1/2 - a*) of 1/2
        else:
            st = 4 * step
        y = min(y + st, yhi)
        ys.append(y)
        fs.append(f(y))
    for i in coarse:
        if fs[i] < fs[i - 1] - 1e-9 * max(1.0, abs(fs[i])):
            notes.append("non-monotone in the coarse region at y=%g" % ys[i])
    finf = f(fp.inf)
    brackets = []
    for i in range(1, len(fs)):
        if (fs[i] > 0) != (fs[i - 1] > 0):
            brackets.append((ys[i - 1], fs[i - 1], ys[i], fs[i]))
    # hidden pairs of roots at interior extrema that do not change sign
    for i in range(1, len(fs) - 1):
        same = (fs[i - 1] > 0) == (fs[i] > 0) == (fs[i + 1] > 0)
        if not same:
            continue
        if fs[i] < 0 and fs[i] >= fs[i - 1] and fs[i] >= fs[i + 1]:
            sgn = 1       # local maximum below zero
        elif fs[i] > 0 and fs[i] <= fs[i - 1] and fs[i] <= fs[i + 1]:
            sgn = -1      # local minimum above zero
        else:
            continue
        # skip flat noise, and extrema too far from zero to hide a pair of roots between samples
        var = max(abs(fs[i] - fs[i - 1]), abs(fs[i] - fs[i + 1]))
        if var <= 1e-9 * max(1.0, abs(fs[i])) or abs(fs[i]) > 10 * var:
            continue
        xa, xb = ys[i - 1], ys[i + 1]
        gr = (math.sqrt(5) - 1) / 2
        x1, x2 = xb - gr * (xb - xa), xa + gr * (xb - xa)
        g1, g2 = sgn * f(x1), sgn * f(x2)
        for _ in range(40):
            if g1 > 0 or g2 > 0:
                break
            if g1 > g2:
                xb, x2, g2 = x2, x1, g1
                x1 = xb - gr * (xb - xa)
                g1 = sgn * f(x1)
            else:
                xa, x1, g1 = x1, x2, g2
                x2 = xa + gr * (xb - xa)
                g2 = sgn * f(x2)
        if g1 > 0 or g2 > 0:
            xm, gm = (x1, g1) if g1 > 0 else (x2, g2)
            notes.append("hidden root pair near y=%g" % xm)
            brackets.append((ys[i - 1], fs[i - 1], xm, sgn * gm))
            brackets.append((xm, sgn * gm, ys[i + 1], fs[i + 1]))
    if (finf > 0) != (fs[-1] > 0) and finf != 0:
        brackets.append((ys[-1], fs[-1], fp.inf, finf))
    brackets.sort(key=lambda b: b[0])
    return brackets, finf, notes


def solve_point(task):
    """All equilibrium states of one model at (alpha, mu, a*)."""
    model, alpha, mu, a, dps = task
    t0 = time.time()
    brackets, finf, notes = scan(model, alpha, mu, a)
    states = []
    for (y0, f0, y1, f1) in brackets:
        St, P = refine_root(model, alpha, mu, a, dps, y0, f0, y1, f1)
        with mp.workdps(dps):
            Pl = MODELS[model]["load"](P, St)
            states.append(dict(c=St.c, gap=St.g, P=Pl, case=1, y=St.y))
    with mp.workdps(dps):
        P = Point(mp, alpha, mu, a)
        if model == "dw":
            case2 = finf < 0           # (2.28b): left side of (2.25b) at C = 1 below 1
            if abs(finf) < 1e-10:       # decide at full precision
                case2 = dw_residual(P, State(P, mp.inf))[0] < 0
            P2 = P.A ** 2 - P.S0 / 2                      # (2.28a)
        else:
            case2 = md_case2_opening(P) <= P.Dcod         # MD extension
            P2 = P.A ** 2 - P.S0
        if case2:
            states.append(dict(c=mp.mpf(0.5), gap=P.e, P=P2, case=2, y=mp.inf))
    states.sort(key=lambda d: (d["case"], d["c"]))
    return dict(task=task, states=states, nbr=len(brackets), finf=finf, notes=notes,
                time=time.time() - t0)


# ----------------------------------------------------------------------------------------------
# output

def num(x):
    return mp.nstr(x, 20, min_fixed=-4, max_fixed=6)


def inp(x):
    return repr(float(x))


def header(name, what, cmd, dps, cols, extra=()):
    lines = ["# wavyadhesion reference data: %s" % name, "# %s" % what,
             "# generated by: %s" % cmd, "# mpmath %s, mp.dps = %d" % (mpmath.__version__, dps)]
    lines += ["# " + l for l in extra]
    lines.append("# columns: " + " ".join(cols))
    return "\n".join(lines) + "\n"


def write_file(name, text):
    os.makedirs(DATADIR, exist_ok=True)
    path = os.path.join(DATADIR, name)
    with open(path + ".tmp", "w") as f:
        f.write(text)
    os.replace(path + ".tmp", path)
    log("wrote %s" % path)


INPUT_NOTE = ("inputs (alpha, mu, a_star) are IEEE doubles written in shortest round-trip form; the "
              "reference is computed for their exact binary values")


def make_westergaard(cmd):
    t0 = time.time()
    with mp.workdps(DPS_MAIN):
        rows = []
        for a in sorted(set(A_MAIN + A_EXT)):
            rows.append("%s %s" % (inp(a), num(mp.sinpi(mp.mpf(a)) ** 2)))
    write_file("westergaard.txt",
               header("westergaard.txt", "Westergaard (no adhesion): P* = sin^2(pi a*), (3.1)", cmd,
                      DPS_MAIN, ["a_star", "P_star"], [INPUT_NOTE]) + "\n".join(rows) + "\n")
    return len(rows), time.time() - t0


def make_jkr(cmd):
    t0 = time.time()
    with mp.workdps(DPS_MAIN):
        rows = []
        for al in sorted(set(ALPHA_MAIN + ALPHA_EXT)):
            for a in sorted(set(A_MAIN + A_EXT)):
                am = mp.mpf(a)
                A, cA = mp.sinpi(am), mp.sinpi(mp.mpf(0.5) - am)
                rows.append("%s %s %s" % (inp(al), inp(a), num(A ** 2 - mp.mpf(al) * mp.sqrt(A / cA))))
    write_file("jkr.txt",
               header("jkr.txt", "JKR (Johnson 1995): P* = sin^2(pi a*) - alpha sqrt(tan(pi a*)), (3.4)",
                      cmd, DPS_MAIN, ["alpha", "a_star", "P_star"], [INPUT_NOTE]) + "\n".join(rows) + "\n")
    return len(rows), time.time() - t0


def grid(extended):
    if not extended:
        return [(al, mu, a) for al in ALPHA_MAIN for mu in MU_MAIN for a in A_MAIN]
    als = sorted(set(ALPHA_MAIN + ALPHA_EXT))
    mus = sorted(set(MU_MAIN + MU_EXT))
    aas = sorted(set(A_MAIN + A_EXT))
    return [(al, mu, a) for al in als for mu in mus for a in aas
            if al in ALPHA_EXT or mu in MU_EXT or a in A_EXT]


def make_model(model, extended, cmd, jobs, md_thin=None):
    from multiprocessing import Pool
    t0 = time.time()
    dps = DPS_EXT if extended else DPS_MAIN
    pts = grid(extended)
    if md_thin is not None:
        pts = [p for p in pts if md_thin(p)]
    tasks = [(model, al, mu, a, dps) for (al, mu, a) in pts]
    name = "%s%s.txt" % (model, "_extended" if extended else "")
    log("start %s: %d points, dps %d, %d jobs" % (name, len(tasks), dps, jobs))
    results = []
    with Pool(jobs) as pool:
        for i, r in enumerate(pool.imap(solve_point, tasks, chunksize=1)):
            results.append(r)
            _, al, mu, a, _ = r["task"]
            desc = " ".join("%d:%s(y=%s)" % (s["case"], mp.nstr(s["c"], 8), mp.nstr(s["y"], 5)) for s in r["states"])
            log("%s %d/%d alpha=%g mu=%g a=%r  %.1fs  states: %s %s" % (
                name, i + 1, len(tasks), al, mu, a, r["time"], desc or "NONE",
                ("; " + "; ".join(r["notes"])) if r["notes"] else ""))
    rows, nosol, multi, notes = [], [], [], []
    with mp.workdps(dps):
        for r in results:
            _, al, mu, a, _ = r["task"]
            if not r["states"]:
                nosol.append((al, mu, a))
            n1 = sum(1 for s in r["states"] if s["case"] == 1)
            if len(r["states"]) > 1:
                multi.append((al, mu, a, n1, len(r["states"]) - n1))
            for n in r["notes"]:
                notes.append("alpha=%r mu=%r a*=%r: %s" % (al, mu, a, n))
            for s in r["states"]:
                rows.append("%s %s %s %s %s %s %d" % (inp(al), inp(mu), inp(a), num(s["c"]),
                                                     num(s["gap"]), num(s["P"]), s["case"]))
    elapsed = time.time() - t0
    what = {"dw": "double-Westergaard equilibria (the paper's (2.22)-(2.28), doc/theory.md): case 1 a*<c*<1/2, "
                  "case 2 c*=1/2 where (2.28b) holds",
            "md": "Maugis-Dugdale equilibria ((2.27a,b), Hui et al. 2001) plus the c*=1/2 extension "
                  "(P* = A^2 - Sigma0, valid while sqrt(1-A^2) - A^2 ln((1+sqrt(1-A^2))/A) <= Dcod)"}[model]
    extra = [INPUT_NOTE,
             "Sigma0 = pi mu (alpha^2/32)^(1/3), Dcod = (alpha^4/2)^(1/3)/mu, gap = c_star - a_star "
             "(computed directly)",
             "one row per equilibrium state: case-1 roots in increasing c_star, then the case-2 state",
             "grid: alpha in %s, mu in %s, a_star in %s%s" % (
                 sorted(set(p[0] for p in pts)), sorted(set(p[1] for p in pts)),
                 sorted(set(p[2] for p in pts)),
                 " (combinations with at least one extended value)" if extended else ""),
             "points with more than one state (alpha mu a_star n_case1 n_case2): %d" % len(multi)]
    extra += ["  %r %r %r %d %d" % m for m in multi]
    extra.append("points with no state at all: %d (listed in %s)" % (len(nosol), name.replace(".txt", "_nosolution.txt")))
    extra += ["note: " + n for n in notes]
    extra.append("generation time %.0f s" % elapsed)
    write_file(name, header(name, what, cmd, dps,
                            ["alpha", "mu", "a_star", "c_star", "gap", "P_star", "zone_case"], extra)
               + "\n".join(rows) + "\n")
    ns = name.replace(".txt", "_nosolution.txt")
    write_file(ns, header(ns, "(alpha, mu, a*) of %s where neither a case-1 root nor a valid case-2 state "
                              "exists (may be empty)" % name, cmd, dps, ["alpha", "mu", "a_star"], [INPUT_NOTE])
               + "".join("%r %r %r\n" % p for p in nosol))
    return dict(rows=len(rows), time=elapsed, multi=multi, nosol=nosol, notes=notes)


# ----------------------------------------------------------------------------------------------
# checks

def read_table(name):
    rows = []
    with open(os.path.join(DATADIR, name)) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            rows.append(line.split())
    return rows


def relerr(x, ref, absfloor=mp.mpf("1e-300")):
    return abs(x - ref) / max(abs(ref), absfloor)


def check(nrows, seed):
    """Recompute random points at dps 50 (main files) / 65 (extended files, made at 50) with a
    fresh scan and refinement, and compare every state.  A third of the MD points are drawn from
    the points with more than one state."""
    random.seed(seed)
    worst = {}
    for name in ("dw.txt", "md.txt", "dw_extended.txt", "md_extended.txt"):
        if not os.path.exists(os.path.join(DATADIR, name)):
            continue
        rows = read_table(name)
        model = name.split("_")[0].split(".")[0]
        keys = sorted(set((r[0], r[1], r[2]) for r in rows))
        multi = sorted(k for k in keys if sum(1 for r in rows if (r[0], r[1], r[2]) == k) > 1)
        nm = min(len(multi), nrows // 3)
        pick = random.sample(multi, nm)
        pick += random.sample([k for k in keys if k not in pick], min(nrows - nm, len(keys) - nm))
        cdps = 65 if "extended" in name else 50
        fdps = DPS_EXT if "extended" in name else DPS_MAIN
        wfull = dict(c=mp.mpf(0), gap=mp.mpf(0), P=mp.mpf(0))
        wc = wg = wp = mp.mpf(0)
        for k in pick:
            al, mu, a = (float(x) for x in k)
            old = [r for r in rows if (r[0], r[1], r[2]) == k]
            r = solve_point((model, al, mu, a, cdps))
            r0 = solve_point((model, al, mu, a, fdps))
            with mp.workdps(cdps):
                if not (len(r["states"]) == len(old) == len(r0["states"])):
                    print("%s %s: number of states differs: %d (dps %d) vs %d (dps %d) vs %d (table)" % (
                        name, k, len(r["states"]), cdps, len(r0["states"]), fdps, len(old)))
                    continue
                for s, s0 in zip(r["states"], r0["states"]):
                    for key, w in (("c", "c"), ("gap", "gap"), ("P", "P")):
                        d = relerr(s0[key], s[key]) if key != "P" or abs(s["P"]) > 1e-3 else abs(s0["P"] - s["P"])
                        wfull[w] = max(wfull[w], d)
                for s, o in zip(r["states"], old):
                    ec = relerr(mp.mpf(o[3]), s["c"])
                    eg = relerr(mp.mpf(o[4]), s["gap"])
                    ep = relerr(mp.mpf(o[5]), s["P"]) if abs(s["P"]) > 1e-3 else abs(mp.mpf(o[5]) - s["P"])
                    wc, wg, wp = max(wc, ec), max(wg, eg), max(wp, ep)
                    print("%s alpha=%s mu=%s a*=%s case %s: c* %s (rel %s) gap rel %s P* %s (%s %s)" % (
                        name, k[0], k[1], k[2], o[6], mp.nstr(s["c"], 22), mp.nstr(ec, 3),
                        mp.nstr(eg, 3), mp.nstr(s["P"], 22), "abs" if abs(s["P"]) <= 1e-3 else "rel",
                        mp.nstr(ep, 3)))
        worst[name] = (wc, wg, wp)
        print("%s: max rel diff (table, 20 digits, vs dps %d) c* %s, gap %s, P* %s" % (
            name, cdps, mp.nstr(wc, 3), mp.nstr(wg, 3), mp.nstr(wp, 3)))
        print("%s: max rel diff of the full-precision values, dps %d vs dps %d: c* %s, gap %s, P* %s "
              "(P* absolute where |P*| < 1e-3)" % (name, fdps, cdps, mp.nstr(wfull["c"], 3),
                                                  mp.nstr(wfull["gap"], 3), mp.nstr(wfull["P"], 3)))
        sys.stdout.flush()
    return worst


def verify():
    """Independent cross checks of the integral forms and of the limits."""
    print("== precision of the residuals: dps 30 vs dps 50 at trial c*")
    for model in ("dw", "md"):
        for (al, mu, a, y) in ((0.3, 1.0, 0.2, 0.3), (0.01, 1000.0, 1e-6, -20.0), (10.0, 0.001, 0.49, 5.0),
                               (1.0, 3.0, 0.5 - 1e-9, 2.0), (1e-4, 1e6, 1e-12, -25.0)):
            vals = []
            for d in (30, 50):
                with mp.workdps(d):
                    P = Point(mp, al, mu, a)
                    vals.append(MODELS[model]["residual"](P, State(P, mp.mpf(y)))[0])
            with mp.workdps(50):
                print("%s alpha=%g mu=%g a*=%r y=%g: residual %s, |dps30-dps50| = %s" % (
                    model, al, mu, a, y, mp.nstr(vals[1], 20), mp.nstr(abs(vals[0] - vals[1]), 3)))
    print("== DW: I* by the phi-substitution vs direct quadrature in X (dps 50)")
    with mp.workdps(50):
        for (a, y) in ((0.2, 0.0), (0.05, 3.0), (0.3, -4.0), (0.2, mp.inf)):
            P = Point(mp, 0.3, 1.0, a)
            St = State(P, mp.mpf(y) if y != mp.inf else y)
            J, _ = dw_J(P, St)
            I1 = St.chi1sq ** 2 * J
            A, C = P.A, St.C
            I2 = mp.quad(lambda X: mp.sqrt(1 - X * X) * mp.sqrt(C * C - X * X) * mp.sqrt(X * X - A * A),
                         [A, (A + C) / 2, C])
            line = "a*=%g y=%s: I* %s direct %s rel diff %s" % (a, y, mp.nstr(I1, 25), mp.nstr(I2, 25),
                                                              mp.nstr(abs(I1 / I2 - 1), 3))
            if y == mp.inf:
                cA = P.cA
                IA = cA * (2 + A * A) / 8 - A * A * (4 - A * A) * mp.asinh(cA / A) / 8
                line += "; closed-form I_A* %s rel diff %s" % (mp.nstr(IA, 25), mp.nstr(abs(I1 / IA - 1), 3))
            print(line)
    print("== MD: Psi_c by the (u, tau) split vs the w = chi3(t) substitution (dps 50)")
    with mp.workdps(50):
        for (a, y) in ((0.2, 0.0), (0.05, 3.0), (0.3, -4.0), (0.01, 1.0)):
            P = Point(mp, 0.3, 1.0, a)
            St = State(P, mp.mpf(y))
            Psi1, _ = md_Psi(P, St)
            A, C = P.A, St.C
            wc = St.chi1 / C
            r2 = (A * St.cC / C) ** 2          # 1 - A^2 - wc^2

            def fw(v):                         # v = wc - w
                w = wc - v
                return (mp.log(2 * wc - v) - mp.log(v)) * A * w / (
                    mp.pi * (1 - w * w) * mp.sqrt(r2 + v * (2 * wc - v)))
            Psi2 = -mp.quad(fw, [0, wc / 2, wc])
            print("a*=%g y=%g (c*=%s): Psi_c %s, w-form %s, rel diff %s" % (
                a, y, mp.nstr(St.c, 10), mp.nstr(Psi1, 25), mp.nstr(Psi2, 25), mp.nstr(abs(Psi1 / Psi2 - 1), 3)))
    print("== MD: left side of (2.27b) as c* -> 1/2 vs sqrt(1-A^2) - A^2 ln((1+sqrt(1-A^2))/A)")
    with mp.workdps(40):
        for a in (1e-6, 0.05, 0.2, 0.4, 0.49, 0.5 - 1e-6):
            P = Point(mp, 0.3, 1.0, a)
            expr = md_case2_opening(P)
            out = []
            for y in (10, 20, 40, mp.inf):
                St = State(P, mp.mpf(y) if y != mp.inf else y)
                lhs, _ = md_lhs(P, St)
                out.append("y=%s: %s" % (y, mp.nstr(lhs / expr - 1, 3)))
            St = State(P, mp.inf)
            Psi, _ = md_Psi(P, St)
            chi2 = mp.asinh(St.chi1 / P.A)
            print("a*=%r: expr %s; LHS/expr-1 at %s; Psi_c(1/2)+chi2 = %s" % (
                a, mp.nstr(expr, 15), ", ".join(out), mp.nstr(Psi + chi2, 3)))
    print("== limits: mu -> inf (JKR) and mu -> 0 (Westergaard)")
    for model in ("dw", "md"):
        for (al, mu, a) in ((0.3, 1e6, 0.2), (0.3, 1e-6, 0.2), (1.0, 1e6, 0.1)):
            r = solve_point((model, al, mu, a, 30))
            with mp.workdps(30):
                A = mp.sinpi(mp.mpf(a))
                jkr = A ** 2 - mp.mpf(al) * mp.sqrt(mp.tan(mp.pi * mp.mpf(a)))
                print("%s alpha=%g mu=%g a*=%g: P* %s (case %s); JKR %s; Westergaard %s" % (
                    model, al, mu, a, [mp.nstr(s["P"], 12) for s in r["states"]],
                    [s["case"] for s in r["states"]], mp.nstr(jkr, 12), mp.nstr(A ** 2, 12)))


# ----------------------------------------------------------------------------------------------

def main():
    global LOGFILE
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--only", default="westergaard,jkr,dw,md,dw_extended,md_extended",
                    help="comma-separated subset of westergaard,jkr,dw,md,dw_extended,md_extended")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--log", default=LOGFILE)
    ap.add_argument("--check", action="store_true", help="recompute random rows at dps 50")
    ap.add_argument("--nrows", type=int, default=10, help="rows per file for --check")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--verify", action="store_true", help="cross checks of integral forms and limits")
    ap.add_argument("--full-md-extended", action="store_true",
                    help="do not thin the md_extended grid (alpha %s, mu %s by default)" % (MD_EXT_ALPHA, MD_EXT_MU))
    args = ap.parse_args()
    LOGFILE = args.log
    if args.check:
        check(args.nrows, args.seed)
        return
    if args.verify:
        verify()
        return
    only = [s.strip() for s in args.only.split(",") if s.strip()]
    cmd = "python3 tools/reference/make_reference.py --only %s" % ",".join(only)
    summary = []
    for item in only:
        if item == "westergaard":
            n, t = make_westergaard(cmd)
            summary.append("%s: %d rows, %.1f s" % (item, n, t))
        elif item == "jkr":
            n, t = make_jkr(cmd)
            summary.append("%s: %d rows, %.1f s" % (item, n, t))
        elif item in ("dw", "md", "dw_extended", "md_extended"):
            model = item.split("_")[0]
            thin = None
            if item == "md_extended" and not args.full_md_extended:
                thin = lambda p: p[0] in MD_EXT_ALPHA and p[1] in MD_EXT_MU
            r = make_model(model, item.endswith("extended"), cmd, args.jobs, thin)
            summary.append("%s: %d rows, %.0f s, %d points with >1 state, %d with none" % (
                item, r["rows"], r["time"], len(r["multi"]), len(r["nosol"])))
        else:
            ap.error("unknown file set %r" % item)
        log("SUMMARY " + summary[-1])
    print("\n".join(summary))


if __name__ == "__main__":
    main()
