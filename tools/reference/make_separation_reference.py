#!/usr/bin/env python3
"""Independent mpmath reference for the separation of solved states (doc/theory.md, "Separation").

Writes test/data/separation_{westergaard,jkr,dw,md,md_nocontact}.txt, one row per (state, x*):

    alpha mu a_star c_star gap_width p_star zone_case gbar_in x_star traction gap gbar

(traction p/p*, gap h/Delta at x*, gbar = mean gap / Delta of the state; gbar_in = -1 except for
MD no-contact states with c* = 1/2, which are identified by their gbar).  Inputs are IEEE doubles
in shortest round-trip form; everything is computed in mpmath for those exact values.

Nothing here uses the library's closed forms for the mean gap, the MD gap (phi form), the JKR
mean gap or the no-contact Clausen forms.  The definitions used:
  * Westergaard: pressure (2.3a), gap (2.15a); gbar = 2 int_a^{1/2} h dx (quadrature).
  * JKR: Westergaard plus the periodic flat-punch term, traction (P*-A^2) cos(pi x)/sqrt(A^2-S^2),
    gap 2 (A^2-P*) asinh(r/A) (checked against the periodic Hilbert transform of the traction by
    --verify); gbar by quadrature.
  * DW: (1+lambda) x Westergaard(a) - lambda x Westergaard(c), lambda = Sigma0/(2 q chi1), formed
    naively at high precision; gbar by quadrature.
  * MD (contact): gap from Hui et al.'s form, h = 2 [S r - P* asinh(r/A) + Sigma0 Psi(x)],
    Psi(x) = -int_a^c ln|(chi3(x)+chi3(t))/(chi3(x)-chi3(t))| dt, P* from (2.27a);
    contact traction p_W(a) - (2 Sigma0/pi) sqrt(A^2-S^2) cos(pi x)
    int_A^C tau dtau/(sqrt(1-tau^2) sqrt(tau^2-A^2) (tau^2-S^2)) by quadrature;
    gbar = 2 int_a^{1/2} h dx, a nested quadrature.
  * MD (no contact): h(x) = 2 Dcod + int_c^x [2 pi sin(2 pi s) + 2 Sigma0 ln|sin(pi(s+c))/sin(pi(s-c))|] ds
    (the gap slope from the periodic Hilbert transform of the traction -Sigma0 on |x| < c);
    gbar by nested quadrature.

Usage: python3 tools/reference/make_separation_reference.py [--only westergaard,jkr,dw,md,md_nocontact]
       [--per-model N] [--verify] [--refresh-md-profiles]
The tables in test/data were made with: --only westergaard,jkr,dw,md_nocontact --per-model 250;
--only md --per-model 100; then --refresh-md-profiles (MD: ~15 CPU-minutes, nested quadrature).
"""

import argparse
import os
import random
import sys
import time

import mpmath
from mpmath import mp, mpf, sin, cos, tan, sqrt, asinh, log, atan, asin, pi, quad, clsin

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))  # tools/reference/ -> the repository root
DATADIR = os.path.join(ROOT, "test", "data")
DPS = 24
# digits for the nested MD mean-gap quadrature (the tables are checked to 1e-12)
GDPS_MD = 17
# digits for the MD profile columns (--refresh-md-profiles)
DPS_PROFILE = 34
DPS_DW = 50
# the no-contact table is thinned (nested quadrature): these alpha, mu
NC_ALPHA = [0.01, 0.3, 1.0, 10.0]
NC_MU = [0.001, 0.1, 1.0, 10.0, 1000.0]

ALPHA_MAIN = [0.01, 0.1, 0.3, 0.6, 1.0, 3.0, 10.0]
MU_MAIN = [0.001, 0.01, 0.1, 0.5, 1.0, 2.5, 3.0, 5.0, 10.0, 100.0, 1000.0]
A_MAIN = [1e-6, 1e-3, 0.01, 0.05, 0.1, 0.2, 0.25, 0.3, 0.4, 0.45, 0.49, 0.5 - 1e-6, 0.5 - 1e-9]

HEADER = "alpha mu a_star c_star gap_width p_star zone_case gbar_in x_star traction gap gbar"


def fmt(x):
    return mp.nstr(x, 20, min_fixed=-5, max_fixed=5) if not isinstance(x, (int, str)) else str(x)


def params(alpha, mu):
    al, m = mpf(alpha), mpf(mu)
    sigma0 = pi * m * (al ** 2 / 32) ** (mpf(1) / 3)
    dcod = (al ** 4 / 2) ** (mpf(1) / 3) / m
    return sigma0, dcod


def graded(lo, hi, scale, ratio=32):
    """Break points from lo to hi, geometric from lo at `scale` (for near-singularities)."""
    pts = [lo]
    d = scale
    while lo + d < hi and d < (hi - lo) / 4:
        pts.append(lo + d)
        d *= ratio
    pts.append(hi)
    return pts


def hw(A, S):
    if S <= A:
        return mpf(0)
    r = sqrt((S - A) * (S + A))
    return 2 * (S * r - A * A * asinh(r / A)) if A > 0 else 2 * S * S


def pw(A, x):
    S = sin(pi * x)
    return 2 * cos(pi * x) * sqrt(A * A - S * S) if S < A else mpf(0)


def mean_gap(h, a, pts_extra=()):
    """2 int_a^{1/2} h(x) dx (h = 0 on |x| < a); tanh-sinh copes with the endpoint
    singularities at a ((x-a)^{3/2}) and at the extra points (MD: (x-c) ln|x-c| at c)."""
    pts = sorted(set([mpf(a)] + [mpf(p) for p in pts_extra if a < p < 0.5] + [mpf(0.5)]))
    return 2 * quad(h, pts)


# ------------------------------------------------------------------ models

def westergaard_state(a):
    A = sin(pi * a)
    return dict(A=A, P=A * A)


def westergaard_row(a, x):
    A = sin(pi * a)
    return pw(A, x), hw(A, sin(pi * x))


def jkr_funcs(alpha, a):
    A = sin(pi * a)
    P = A * A - mpf(alpha) * sqrt(tan(pi * a))

    def trac(x):
        S = sin(pi * x)
        if S >= A:
            return mpf(0)
        return pw(A, x) + (P - A * A) * cos(pi * x) / sqrt(A * A - S * S)

    def gap(x):
        S = sin(pi * x)
        if S <= A:
            return mpf(0)
        r = sqrt(S * S - A * A)
        return hw(A, S) + 2 * (A * A - P) * asinh(r / A)
    return P, trac, gap


def dw_funcs(sigma0, a, gap_w):
    c = a + gap_w       # the state's c* (the tabulated c_star may be half an ulp off)
    A, C = sin(pi * a), sin(pi * c)
    q = cos(pi * a)
    d2 = sin(pi * gap_w) * sin(pi * (a + c))
    lam = sigma0 / (2 * q * sqrt(d2))

    def trac(x):
        return (1 + lam) * pw(A, x) - lam * pw(C, x)

    def gap(x):
        S = sin(pi * x)
        return (1 + lam) * hw(A, S) - lam * hw(C, S)
    return A * A - lam * d2, trac, gap


def md_funcs(sigma0, a, gap_w):
    c = a + gap_w
    A, C = sin(pi * a), sin(pi * c)
    qa, qc = cos(pi * a), cos(pi * c)
    P = A * A - sigma0 * (1 - 2 / pi * asin(qc / qa))

    def chi3(x):
        return sqrt(sin(pi * (x - a)) * sin(pi * (x + a))) / sin(pi * x)

    def psi(x):
        cx = chi3(x)

        sx = sin(pi * x)

        def f(t):
            ct = chi3(t)
            st = sin(pi * t)
            # chi3(x) - chi3(t) = A^2 sin(pi(x-t)) sin(pi(x+t)) / (S_x^2 S_t^2 (chi3(x)+chi3(t)))
            diff = A * A * sin(pi * (x - t)) * sin(pi * (x + t)) / (sx * sx * st * st * (cx + ct))
            if diff == 0:
                return mpf(0)
            return log(abs((cx + ct) / diff))
        # chi3 turns on the scale a* near t = a* (and the log on the scale |x - t|)
        pts = graded(a, c, min(a, c - a) / 16, ratio=4)
        if a < x < c:
            pts = sorted(set(pts + [x]))
        return -quad(f, pts)

    def gap(x):
        if x <= a:
            return mpf(0)
        S = sin(pi * x)
        r = sqrt(sin(pi * (x - a)) * sin(pi * (x + a)))
        return 2 * (S * r - P * asinh(r / A) + sigma0 * psi(x))

    def trac(x):
        if x < a:
            S = sin(pi * x)
            m = sqrt(sin(pi * (a - x)) * sin(pi * (a + x)))

            def g(t):   # tau = sin(pi t): the integral over tau in t
                st = sin(pi * t)
                ra = sin(pi * (t - a)) * sin(pi * (t + a))
                if ra <= 0:
                    return mpf(0)
                return pi * st / (sqrt(ra) * (st * st - S * S))
            integral = quad(g, graded(mpf(a), c, (c - a) * mpf(2) ** -30))
            return pw(A, x) - 2 * sigma0 / pi * m * cos(pi * x) * integral
        if x <= c:
            return -sigma0
        return mpf(0)
    return P, trac, gap


def nocontact_funcs(sigma0, dcod, c):
    c = mpf(c)

    def slope(s):
        den = sin(pi * (s - c))
        if c == 0 or den == 0:
            return 2 * pi * sin(2 * pi * s)
        return 2 * pi * sin(2 * pi * s) + 2 * sigma0 * log(abs(sin(pi * (s + c)) / den))

    def gap(x):
        x = mpf(x)
        if x == c:
            return 2 * dcod
        return 2 * dcod + quad(slope, [c, x])

    def trac(x):
        return -sigma0 if x <= c else mpf(0)
    return -2 * sigma0 * c, trac, gap


def crest_clausen(sigma0, dcod, c):
    """Only used to choose c* inside the family (the values come from nocontact_funcs)."""
    return 2 * dcod - 2 * sin(pi * c) ** 2 + sigma0 / pi * (clsin(2, 4 * pi * c) - 2 * clsin(2, 2 * pi * c))


# ------------------------------------------------------------------ rows

def xs_for(a, c):
    xs = []
    if a > 0:
        xs.append(a / 2)
    if c > a:
        xs.append(a + 0.3 * (c - a))
        xs.append(c)
    elif a > 0:
        xs.append(a + 0.1 * (0.5 - a))
    xs += [(c + 0.5) / 2, 0.5, 0.37, -0.81]
    return [float(x) for x in xs]


def reduced(x):
    x = mpf(x)
    return abs(x - mp.nint(x))


def write(name, rows, note):
    path = os.path.join(DATADIR, "separation_%s.txt" % name)
    with open(path + ".tmp", "w") as f:
        f.write("# wavyadhesion separation reference: %s\n" % name)
        f.write("# generated by: python3 tools/reference/make_separation_reference.py --only %s\n" % name)
        f.write("# mpmath %s, mp.dps = %d; %s\n" % (mpmath.__version__, DPS, note))
        f.write("# " + HEADER + "\n")
        for r in rows:
            f.write(" ".join(fmt(v) for v in r) + "\n")
    os.replace(path + ".tmp", path)
    print("wrote", path, len(rows), "rows", flush=True)


def read_table(name):
    rows = []
    with open(os.path.join(DATADIR, name)) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            t = line.split()
            rows.append((float(t[0]), float(t[1]), float(t[2]), float(t[3]), float(t[4]),
                         int(t[6])))
    return rows


def contact_rows(model, alpha, mu, a, c, gap_w, zone, P, trac, gap, singular, gdps=None):
    if gdps:                 # the nested MD quadrature: fewer digits for the mean
        with mp.workdps(gdps):
            g = mean_gap(lambda x: gap(x), a, singular)
    else:
        g = mean_gap(lambda x: gap(x), a, singular)
    out = []
    for x in xs_for(a, c):
        xr = reduced(x)
        out.append((alpha, mu, a, c, gap_w, P, zone, -1, x, trac(xr), gap(xr), g))
    return out


def run_westergaard():
    rows = []
    for a in [0.0] + A_MAIN:
        am = mpf(a)
        A = sin(pi * am)
        g = mean_gap(lambda x: hw(A, sin(pi * x)), am) if a > 0 else mpf(1)
        for x in xs_for(a, a):
            t, h = westergaard_row(am, reduced(x))
            rows.append((0, 0, a, a, 0.0, A * A, 1, -1, x, t, h, g))
    write("westergaard", rows, "alpha, mu unused (written 0)")


def run_jkr():
    rows = []
    for alpha in ALPHA_MAIN:
        for a in A_MAIN:
            P, trac, gap = jkr_funcs(alpha, mpf(a))
            rows += contact_rows("jkr", alpha, 0, a, a, 0.0, 1, P, trac, gap, [])
    write("jkr", rows, "mu unused (written 0)")


def run_table(model, per_model):
    table = [r for r in read_table("%s.txt" % model) if r[5] in (1, 2) and r[2] < 0.5]
    rnd = random.Random(12345)
    pick = sorted(rnd.sample(range(len(table)), min(per_model, len(table))))
    rows = []
    t0 = time.time()
    for k, i in enumerate(pick):
        alpha, mu, a, c, gap_w, zone = table[i]
        sigma0, dcod = params(alpha, mu)
        am, gm = mpf(a), mpf(gap_w)
        if model == "dw":       # lambda reaches 1e20: (1+lambda) W(a) - lambda W(c) needs digits
            mp.dps = DPS_DW
            sigma0, dcod = params(alpha, mu)
            am, gm = mpf(a), mpf(gap_w)
            P, trac, gap = dw_funcs(sigma0, am, gm)
        else:
            P, trac, gap = md_funcs(sigma0, am, gm)
        rows += contact_rows(model, alpha, mu, a, c, gap_w, zone, P, trac, gap, [am + gm],
                             gdps=(GDPS_MD if model == "md" else None))
        if k % 10 == 0:
            print(model, k, len(pick), "%.0f s" % (time.time() - t0), flush=True)
    write(model, rows, "states sampled from test/data/%s.txt" % model)


def run_nocontact():
    rows = []
    for alpha in NC_ALPHA:
        for mu in NC_MU:
            sigma0, dcod = params(alpha, mu)
            # first closure of the crest gap (choice of c only)
            hi = mpf(1) / 3
            while crest_clausen(sigma0, dcod, hi) > 0 and hi < 0.5 - 1e-12:
                hi = (hi + 0.5) / 2
            if crest_clausen(sigma0, dcod, hi) > 0:
                c_close = mpf(0.5)
            else:
                c_close = mp.findroot(lambda c: crest_clausen(sigma0, dcod, c), (mpf(0), hi),
                                      solver="anderson")
            for frac in (0.0, 0.05, 0.5, 0.97):
                c = float(c_close * frac)
                P, trac, gap = nocontact_funcs(sigma0, dcod, c)
                with mp.workdps(GDPS_MD):
                    g = 2 * quad(gap, sorted(set([mpf(0), mpf(c), mpf(0.5)])))
                for x in [0.0, c / 2, c, (c + 0.5) / 2, 0.5, -0.81]:
                    xr = reduced(x)
                    rows.append((alpha, mu, 0.0, c, c, P, 0, -1, x, trac(xr), gap(xr), g))
            if dcod > 1:                     # the stretch c* = 1/2: gbar identifies the state
                for crest in (0.0, float(dcod - 1)):
                    g_in = 1 + crest
                    for x in [0.0, 0.2, 0.5]:
                        rows.append((alpha, mu, 0.0, 0.5, 0.5, -sigma0, 0, g_in, x, -sigma0,
                                     crest + 2 * sin(pi * mpf(x)) ** 2, g_in))
        print("nocontact alpha", alpha, flush=True)
    write("md_nocontact", rows, "a* = 0, Dugdale zone |x*| < c*, c* = fraction x first closure")


def refresh_md_profiles():
    """Recompute the MD traction and gap columns of separation_md.txt at DPS_PROFILE digits
    (cheap), keeping the mean gap (the expensive nested quadrature)."""
    path = os.path.join(DATADIR, "separation_md.txt")
    lines = open(path).read().splitlines()
    out = []
    with mp.workdps(DPS_PROFILE):
        for line in lines:
            if line.startswith("#"):
                out.append(line.replace("mp.dps = %d;" % DPS, "mp.dps = %d (profiles %d);"
                                        % (DPS, DPS_PROFILE)))
                continue
            t = line.split()
            alpha, mu, a, c, gap_w, x = (float(t[0]), float(t[1]), float(t[2]), float(t[3]),
                                         float(t[4]), float(t[8]))
            sigma0, dcod = params(alpha, mu)
            P, trac, gap = md_funcs(sigma0, mpf(a), mpf(gap_w))
            xr = reduced(x)
            t[9] = fmt(trac(xr))
            t[10] = fmt(gap(xr))
            out.append(" ".join(t))
    with open(path + ".tmp", "w") as f:
        f.write("\n".join(out) + "\n")
    os.replace(path + ".tmp", path)
    print("refreshed", path, flush=True)


def verify():
    """JKR gap slope against the periodic Hilbert transform of the JKR traction."""
    alpha, a = 0.4, mpf("0.17")
    P, trac, gap = jkr_funcs(alpha, a)
    for x in [mpf("0.25"), mpf("0.4")]:
        # dh/dx = 2 pi sin(2 pi x) - 2 pi int p(xi) cot(pi(x - xi)) dxi
        hil = quad(lambda xi: trac(xi) * (1 / tan(pi * (x - xi)) + 1 / tan(pi * (x + xi))), [0, a])
        print("jkr slope", mp.diff(gap, x), 2 * pi * sin(2 * pi * x) - 2 * pi * hil)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--only", default="westergaard,jkr,dw,md,md_nocontact")
    ap.add_argument("--per-model", type=int, default=200)
    ap.add_argument("--verify", action="store_true")
    ap.add_argument("--refresh-md-profiles", action="store_true",
                    help="recompute the traction and gap columns of separation_md.txt at "
                         "DPS_PROFILE digits, keeping its gbar column")
    args = ap.parse_args()
    mp.dps = DPS
    if args.verify:
        verify()
        return
    if args.refresh_md_profiles:
        refresh_md_profiles()
        return
    for name in args.only.split(","):
        if name == "westergaard":       # S - A cancels near a* = 1/2: closed forms at dps 50
            with mp.workdps(DPS_DW):
                run_westergaard()
        elif name == "jkr":
            with mp.workdps(DPS_DW):
                run_jkr()
        elif name in ("dw", "md"):
            run_table(name, args.per_model)
        elif name == "md_nocontact":
            run_nocontact()
        else:
            sys.exit("unknown table " + name)


if __name__ == "__main__":
    main()
