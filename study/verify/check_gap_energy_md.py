#!/usr/bin/env python3
"""Independent check of the energy lost per cycle W* under gap control (MD), with mpmath.

    .venv/bin/python study/verify/check_gap_energy_md.py [--dps 20] [--cases 0.3:1,10:63]
                                                  [--verify-gap] [--balance] [--verbose]

Everything but the starting guesses is computed here from the equations of
doc/theory.md (sections "Maugis-Dugdale", "Separation", "Gap control"), in mpmath:

* the Maugis-Dugdale contact states (case 1) from (2.27a,b), with Psi_c evaluated in the
  variable u of sin(pi t) = A cosh(u) (then chi3 = tanh u and the kernel is
  ln(sinh(u_c + u)/sinh(u_c - u)): no cancellation, one log endpoint) by tanh-sinh;
  the case-2 states (c* = 1/2): P* = A^2 - Sigma0, gbar* = g_W(A^2), from the switch a_sw
  where sqrt(1-A^2) - A^2 ln((1+sqrt(1-A^2))/A) = Dcod;
* the no-contact states (a* = 0) from their Fourier series, derived here:
  gbar* = 1 + 2 Dcod - 2 sin^2(pi c) + (Sigma0/pi) Cl2(4 pi c), P* = -2 Sigma0 c, up to the
  first zero c_close of the crest gap
  H(c) = 2 Dcod - 2 sin^2(pi c) + (Sigma0/pi) (Cl2(4 pi c) - 2 Cl2(2 pi c));
* the mean gap of a contact state, gbar* = 2 int_a^{1/2} h dx with Hui's gap
  h/Delta = 2 [S r - P* chi2(x) + Sigma0 Psi(x)]; the x-integral of the kernel is done in
  closed form (int_a^{1/2} ln|..| dx = acosh(sin(pi t)/A), checked here by a double
  quadrature with --verify-gap), so gbar* = g_W(A^2) - Sigma0 Phi ln A^2
  - 4 Sigma0 int_a^c acosh(sin(pi t)/A) dt, and along the curve
  dgbar* = ln(A^2) dP* - 4 Sigma0 acosh(C/A) dc* (differentiating under the integral);
  dc*/da* (or da*/dc*) along the curve from the implicit function theorem with the partial
  derivatives of (2.27b) by central differences;
* the walk: the chain far apart (P* = 0, gbar* >= 1 + 2 Dcod) -> no-contact states
  (c* from 0 to c_close) -> case 1 (a* from 0 to a_sw, parametrised piecewise by a* or c*,
  whichever moves more between the library's branch points) -> case 2 (a* to 1/2) -> full
  contact (gbar* = 0). The chain is cut into stretches monotone in gbar* (extrema located by
  a root of dgbar*/dtau); the approach takes, stretch by stretch, the part below the running
  minimum of gbar* (a jump at constant gbar* lands where gbar* equals it), the retraction,
  from full contact backwards, the part above the running maximum; then
  W* = -oint P* dgbar* = -(sum_approach int P dgbar - sum_retraction int P dgbar), where a
  stretch walked both ways is integrated only where the two intervals differ, each
  int P* dgbar*/dtau dtau by tanh-sinh.
The library supplies only the branch points used as starting guesses and to choose the
parameter (`wavyadhesion.trace_branch`), and its W* (`wavyadhesion.gap_law`) for comparison.
With --balance it also prints the two parts of the energy balance (doc/theory.md, "W* can
exceed the work of adhesion"), at 12 digits: the energy lost on approach,
D_app = int_0^inf P_app dgbar* - 1/4 + pi alpha^2/2, and on retraction,
D_ret = 1/4 - pi alpha^2/2 - int_0^inf P_ret dgbar* (each >= 0; D_app + D_ret = W*).
Near c* = 1/2 (alpha = 10) 1/2 - c* ~ 1e-8 costs digits of c*: compare --dps 20 and 30.
"""
import argparse
import time

import mpmath as mp
import numpy as np

import wavyadhesion as wa


def cos_of(A, C, uc):
    """d -> cos(pi t) at u = uc - d (sin(pi t) = A cosh u <= C = A cosh uc), without
    cancellation near C = 1: 1 - A cosh u = (1 - C) + 2 A sinh(uc - d/2) sinh(d/2)."""
    def cos_t(d):
        one_minus = (1 - C) + 2 * A * mp.sinh(uc - d / 2) * mp.sinh(d / 2)
        return mp.sqrt(one_minus * (1 + A * mp.cosh(uc - d)))
    return cos_t


def u_quad(f, uc):
    """int_0^uc F(u) du for F given as f(d) with d = uc - u, in w = sqrt(d): the distance to
    the end u = uc (a log singularity, and 1/sqrt where C = 1) is exact at every node."""
    return mp.quad(lambda w: 2 * w * f(w * w), [0, mp.sqrt(uc) / 2, mp.sqrt(uc)])


class MD:
    def __init__(self, alpha, mu):
        self.alpha, self.mu = mp.mpf(alpha), mp.mpf(mu)
        self.s0 = mp.pi * self.mu * (self.alpha ** 2 / 32) ** (mp.mpf(1) / 3)
        self.dcod = (self.alpha ** 4 / 2) ** (mp.mpf(1) / 3) / self.mu
        self.wad = mp.pi * self.alpha ** 2 / 2

    # ---------------- case 1 -----------------------------------------------------------
    def phi(self, a, c):
        return 1 - 2 / mp.pi * mp.asin(mp.cos(mp.pi * c) / mp.cos(mp.pi * a))

    def load(self, a, c):
        return mp.sin(mp.pi * a) ** 2 - self.s0 * self.phi(a, c)

    def psi_c(self, a, c):
        """Psi_c = -int_a^c ln|(chi3(c)+chi3(t))/(chi3(c)-chi3(t))| dt in u: sin(pi t) = A cosh u."""
        A = mp.sin(mp.pi * a)
        uc = mp.acosh(mp.sin(mp.pi * c) / A)

        cos_t = cos_of(A, mp.sin(mp.pi * c), uc)

        def f(d):
            return (mp.log(mp.sinh(2 * uc - d) / mp.sinh(d)) * A * mp.sinh(uc - d)
                    / (mp.pi * cos_t(d)))
        return -u_quad(f, uc)

    def opening(self, a, c):
        """Left side of (2.27b) minus Dcod."""
        A, C = mp.sin(mp.pi * a), mp.sin(mp.pi * c)
        chi1 = mp.sqrt((C - A) * (C + A))
        chi2 = mp.acosh(C / A)
        return chi1 * C - self.load(a, c) * chi2 + self.s0 * self.psi_c(a, c) - self.dcod

    def jint(self, a, c):
        """int_a^c acosh(sin(pi t)/A) dt, in u."""
        A = mp.sin(mp.pi * a)
        uc = mp.acosh(mp.sin(mp.pi * c) / A)
        cos_t = cos_of(A, mp.sin(mp.pi * c), uc)
        return u_quad(lambda d: (uc - d) * A * mp.sinh(uc - d) / (mp.pi * cos_t(d)), uc)

    def gbar1(self, a, c):
        s = mp.sin(mp.pi * a) ** 2
        return 1 - s + s * mp.log(s) - self.s0 * self.phi(a, c) * mp.log(s) - 4 * self.s0 * self.jint(a, c)

    def partials(self, a, c):
        """(F_a, F_c) of the opening by central differences, steps 10^(-dps/3) of the
        distance to the nearest singularity (truncation and rounding both ~10^(-2 dps/3))."""
        rel = mp.mpf(10) ** (-mp.mp.dps / mp.mpf(3))
        ha = rel * min(a, mp.mpf(0.5) - a, c - a)
        hc = rel * min(c - a, mp.mpf(0.5) - c)
        F = self.opening
        return ((F(a + ha, c) - F(a - ha, c)) / (2 * ha),
                (F(a, c + hc) - F(a, c - hc)) / (2 * hc))

    def dload(self, a, c):
        """(P_a, P_c), analytic."""
        q, cc = mp.cos(mp.pi * a), mp.cos(mp.pi * c)
        z = cc / q
        dz = 2 / (mp.pi * mp.sqrt(1 - z ** 2))          # d Phi = +dz * ... with Phi = 1 - (2/pi) asin z
        z_a = cc * mp.pi * mp.sin(mp.pi * a) / q ** 2
        z_c = -mp.pi * mp.sin(mp.pi * c) / q
        phi_a, phi_c = -dz * z_a, -dz * z_c
        return mp.pi * mp.sin(2 * mp.pi * a) - self.s0 * phi_a, -self.s0 * phi_c

    # ---------------- no contact, case 2 --------------------------------------------------
    def h00(self, c):
        return (2 * self.dcod - 2 * mp.sin(mp.pi * c) ** 2
                + self.s0 / mp.pi * (mp.clsin(2, 4 * mp.pi * c) - 2 * mp.clsin(2, 2 * mp.pi * c)))

    def gbar0(self, c):
        return 1 + 2 * self.dcod - 2 * mp.sin(mp.pi * c) ** 2 + self.s0 / mp.pi * mp.clsin(2, 4 * mp.pi * c)

    def dgbar0(self, c):
        return -2 * mp.pi * mp.sin(2 * mp.pi * c) - 4 * self.s0 * mp.log(2 * mp.sin(2 * mp.pi * c))

    def a_switch(self):
        def f(a):
            A = mp.sin(mp.pi * a)
            r = mp.sqrt(1 - A ** 2)
            return r - A ** 2 * mp.log((1 + r) / A) - self.dcod
        return mp.findroot(f, (mp.mpf("1e-12"), mp.mpf(0.5) - mp.mpf("1e-12")), solver="anderson")


def gw(s):
    return 1 - s + s * mp.log(s)


class Piece:
    """One stretch of the chain with a parameter tau (increasing along the chain)."""

    def __init__(self, name, t0, t1, state, dstate):
        self.name, self.t0, self.t1 = name, t0, t1
        self.state, self.dstate = state, dstate     # tau -> (P, gbar); tau -> (P, dgbar/dtau)


def root(f, g, lo, hi):
    """The root of f near the guess g in (lo, hi): secant from g, else a bracket grown
    around g (the two case-1 roots at one a* are never within the guess error here)."""
    try:
        x = mp.findroot(f, (g, g + (hi - g) * mp.mpf("1e-9")), solver="secant")
        if isinstance(x, mp.mpf) and lo < x < hi and abs(x - g) < mp.mpf("1e-2") * (hi - lo):
            return x
    except (ValueError, ZeroDivisionError):
        pass
    # brackets [g - d (g - lo), g] and [g, g + d (hi - g)], d growing to 1: the narrower
    # one with a sign change wins (near c* = 1/2 the root sits within 1e-8 of hi)
    fg = f(g)
    for k in range(16):
        d = min(mp.mpf("1e-9") * 4 ** k, 1 - mp.mpf("1e-30")) if k < 15 else mp.mpf(1)
        found = []
        for x in (g - d * (g - lo), g + d * (hi - g)):
            if lo < x <= hi:
                fx = f(x)
                if isinstance(fx, mp.mpf) and fx * fg <= 0:
                    found.append((abs(x - g), x, fx))
        if found:
            _, x, fx = min(found)
            r = mp.findroot(f, (min(x, g), max(x, g)), solver="anderson", verify=False)
            # near c* = 1/2, 1/2 - c* ~ 1e-8 keeps only dps - 8 digits: the residual is
            # judged against the bracket's values too (run at a larger --dps to check)
            res = abs(f(r))
            if lo < r <= hi and (res <= mp.mpf(10) ** (-mp.mp.dps + 6)
                                 or res <= mp.mpf("1e-9") * max(abs(fg), abs(fx))):
                return r
    raise ValueError(f"no root bracketed near {g} in ({lo}, {hi})")


def case1_pieces(md, lib_a, lib_c, c_close, a_sw):
    """Cut the case-1 curve into pieces with parameter a* (sign +-1) or c*."""
    da, dc = np.abs(np.diff(lib_a)), np.abs(np.diff(lib_c))
    use_c = dc > da
    sgn = np.sign(np.diff(lib_a))
    runs, start = [], 0
    for i in range(1, len(use_c) + 1):
        if i == len(use_c) or use_c[i] != use_c[start] or (not use_c[i] and sgn[i] != sgn[start]):
            runs.append((start, i, "c" if use_c[start] else "a"))
            start = i
    pieces = []
    a_prev, c_prev = mp.mpf(0), c_close
    for k, (i0, i1, kind) in enumerate(runs):
        last = k == len(runs) - 1
        xa, xc = lib_a[i0:i1 + 1], lib_c[i0:i1 + 1]
        if kind == "a":
            s = 1 if xa[-1] > xa[0] else -1
            t0 = s * a_prev
            t1 = s * (a_sw if last else mp.mpf(float(xa[-1])))
            order = np.argsort(xa)

            def solve(t, s=s, xa=xa[order], xc=xc[order]):
                a = s * t
                if a == a_sw:
                    return a, mp.mpf(0.5)
                g = mp.mpf(float(np.interp(float(a), xa, xc)))
                return a, root(lambda c: md.opening(a, c), g, a, mp.mpf(0.5))
        else:
            t0 = c_prev
            t1 = mp.mpf(0.5) if last else mp.mpf(float(xc[-1]))

            def solve(t, xa=xa, xc=xc):
                g = mp.mpf(float(np.interp(float(t), xc, xa)))
                return root(lambda a: md.opening(a, t), g, mp.mpf(0), t), t
        piece = make_piece(md, kind, t0, t1, solve, s if kind == "a" else 1)
        pieces.append(piece)
        a_prev, c_prev = piece.solve(t1) if not last else (a_sw, mp.mpf(0.5))
    return pieces


def make_piece(md, kind, t0, t1, solve_raw, s):
    memo = {}

    def solve(t):
        if t not in memo:
            memo[t] = solve_raw(t)
        return memo[t]

    def state(t):
        a, c = solve(t)
        return md.load(a, c), md.gbar1(a, c)

    def dstate(t):
        a, c = solve(t)
        fa, fc = md.partials(a, c)
        pa, pc = md.dload(a, c)
        if kind == "a":                          # tau = s a*
            da, dc = s, -s * fa / fc
        else:
            da, dc = -fc / fa, 1
        dp = pa * da + pc * dc
        A = mp.sin(mp.pi * a)
        dg = mp.log(A ** 2) * dp - 4 * md.s0 * mp.acosh(mp.sin(mp.pi * c) / A) * dc
        return md.load(a, c), dg
    p = Piece("case1-" + kind, t0, t1, state, dstate)
    p.solve = solve
    return p


def build_chain(md, alpha, mu):
    b = wa.trace_branch("md", float(alpha), float(mu))
    z = b.zone_case
    lib_a, lib_c = b.a_star[z == 1], b.c_star[z == 1]
    # no-contact states: c from 0 to the first zero of the crest gap
    cs = [mp.mpf(k) / 2000 for k in range(1, 1000)]
    k = next(i for i, c in enumerate(cs) if md.h00(c) < 0)
    # + rounds the roots to the working precision (findroot returns extra bits)
    c_close = +mp.findroot(md.h00, (cs[k - 1], cs[k]), solver="anderson")
    chain = [Piece("no-contact", mp.mpf(0), c_close,
                   lambda c: (-2 * md.s0 * c, md.gbar0(c)),
                   lambda c: (-2 * md.s0 * c, md.dgbar0(c)))]
    a_sw = +md.a_switch()
    chain += case1_pieces(md, lib_a, lib_c, c_close, a_sw)
    chain.append(Piece("case2", a_sw, mp.mpf(0.5),
                       lambda a: (mp.sin(mp.pi * a) ** 2 - md.s0, gw(mp.sin(mp.pi * a) ** 2)),
                       lambda a: (mp.sin(mp.pi * a) ** 2 - md.s0,
                                  mp.log(mp.sin(mp.pi * a) ** 2) * mp.pi * mp.sin(2 * mp.pi * a))))
    return chain, c_close, a_sw, b


def stretches(piece, nsample=16):
    """Split a piece into gbar*-monotone stretches: [(t_start, t_end, g_start, g_end)]."""
    t0, t1 = piece.t0, piece.t1
    # sample dgbar/dtau on Chebyshev points of the open interval and next to both ends (an
    # extremum between an end and the first Chebyshev point is otherwise missed: alpha = 10)
    eps = mp.mpf("1e-6")
    ts = ([t0 + (t1 - t0) * eps]
          + [t0 + (t1 - t0) * (1 - mp.cos(mp.pi * (k + mp.mpf(0.5)) / nsample)) / 2
             for k in range(nsample)]
          + [t1 - (t1 - t0) * eps])
    nsample = len(ts)
    ds = [piece.dstate(t)[1] for t in ts]
    cuts = [t0]
    for i in range(nsample - 1):
        if mp.sign(ds[i]) != mp.sign(ds[i + 1]):
            t = mp.findroot(lambda t: piece.dstate(t)[1], (ts[i], ts[i + 1]), solver="anderson",
                            verify=False)
            assert min(ts[i], ts[i + 1]) <= t <= max(ts[i], ts[i + 1]), "extremum outside its bracket"
            cuts.append(t)
    cuts.append(t1)
    g = [end_gbar(piece, t) for t in cuts]
    return [(cuts[i], cuts[i + 1], g[i], g[i + 1]) for i in range(len(cuts) - 1)]


def end_gbar(piece, t):
    if piece.name == "no-contact" and t == 0:
        return None                                    # filled by the caller (1 + 2 Dcod)
    if piece.name.startswith("case1") and t == 0:
        return None                                    # a* -> 0: continuous with no-contact end
    return piece.state(t)[1]


def integral(piece, ta, tb):
    if ta == tb:
        return mp.mpf(0)
    f = lambda t: (lambda pd: pd[0] * pd[1])(piece.dstate(t))
    return mp.quad(f, [ta, tb])


def land(piece, ts, te, target):
    """tau in [ts, te] where gbar* = target."""
    f = lambda t: piece.state(t)[1] - target
    lo, hi = ts, te
    flo = f(lo)
    for _ in range(12):                                # bisection to 2^-12 of the stretch
        mid = (lo + hi) / 2
        fm = f(mid)
        if fm * flo > 0:
            lo, flo = mid, fm
        else:
            hi = mid
    t = mp.findroot(f, (lo, hi), solver="anderson", verify=False)
    assert min(ts, te) <= t <= max(ts, te), "landing outside its stretch"
    if abs(f(t)) > mp.mpf(10) ** (-mp.mp.dps + 5) * (1 + abs(target)):
        raise ValueError(f"landing at gbar* = {target} on {piece.name}: residual {f(t)}")
    return t


def walk(md, chain, balance, verbose=False):
    """The approach and the retraction over the chain; returns the events, W* and, with
    balance, int P* dgbar* along the approach and along the retraction (at 12 digits)."""
    segs = []           # [piece, t_start, t_end, g_start, g_end]
    g_touch = 1 + 2 * md.dcod
    prev_end = g_touch
    for piece in chain:
        for (ts, te, gs, ge) in stretches(piece):
            segs.append([piece, ts, te, prev_end if gs is None else gs, ge])
            prev_end = ge
            if verbose:
                print("   stretch", piece.name, mp.nstr(ts, 8), mp.nstr(te, 8),
                      "gbar", mp.nstr(segs[-1][3], 12), "->", mp.nstr(ge, 12), flush=True)
    tol = mp.mpf(10) ** (-mp.mp.dps + 5)
    events, app, ret = [], {}, {}
    # approach: descending stretches, the part below the running minimum of gbar*
    run_min = g_touch
    for k, (piece, ts, te, gs, ge) in enumerate(segs):
        if ge >= gs or ge >= run_min:
            continue
        t = ts
        if gs > run_min * (1 + tol):
            t = land(piece, ts, te, run_min)
            events.append(("approach jump lands", piece.name, run_min, piece.state(t)[0]))
        app[k] = (t, te)
        run_min = ge
    # retraction, backwards from full contact: the part above the running maximum
    run_max = mp.mpf(0)
    for k in reversed(range(len(segs))):
        piece, ts, te, gs, ge = segs[k]
        if gs <= ge or gs <= run_max:
            continue
        t = te
        if ge < run_max * (1 - tol):
            t = land(piece, ts, te, run_max)
            events.append(("retraction jump lands", piece.name, run_max, piece.state(t)[0]))
        ret[k] = (ts, t)
        run_max = gs
    events.append(("interaction lost", "", run_max, mp.mpf(0)))
    # -oint P dgbar = -(int_app - int_ret) in the forward parameter; a stretch walked both
    # ways contributes only where the two intervals differ: int_x1^y1 + int_y2^x2
    total = mp.mpf(0)
    for k in set(app) | set(ret):
        piece = segs[k][0]
        if k in app and k in ret:
            (x1, x2), (y1, y2) = app[k], ret[k]
            total += integral(piece, x1, y1) + integral(piece, y2, x2)
        elif k in app:
            total += integral(piece, *app[k])
        else:
            total -= integral(piece, *ret[k])
    i_app = i_ret = None
    if balance:
        with mp.workdps(12):
            i_app = sum(integral(segs[k][0], *app[k]) for k in app)
            i_ret = -sum(integral(segs[k][0], *ret[k]) for k in ret)
    return events, -total, i_app, i_ret, segs


def verify_gap(md, a, c):
    """gbar* of the MD traction at (a*, c*) two ways: 2 int_a^{1/2} h dx with Hui's gap
    h/Delta = 2 [S r - P* chi2(x) + Sigma0 Psi(x)] by a double quadrature (t in the variable
    u, split at the log singularity t = x), and the closed form used in the walk."""
    A = mp.sin(mp.pi * a)
    uc = mp.acosh(mp.sin(mp.pi * c) / A)
    p = md.load(a, c)

    def psi(x):
        ux = mp.acosh(mp.sin(mp.pi * x) / A)

        def f(u):
            if u == ux:
                return mp.mpf(0)                 # a node on the log singularity (weight ~0)
            return (mp.log(abs(mp.sinh(ux + u) / mp.sinh(ux - u))) * A * mp.sinh(u)
                    / (mp.pi * mp.sqrt((1 - A * mp.cosh(u)) * (1 + A * mp.cosh(u)))))
        pts = [0, ux, uc] if ux < uc else [0, uc]
        return -mp.quad(f, pts)

    def h(x):
        S = mp.sin(mp.pi * x)
        return 2 * (S * mp.sqrt(S ** 2 - A ** 2) - p * mp.acosh(S / A) + md.s0 * psi(x))
    direct = 2 * mp.quad(h, [a, c, mp.mpf(0.5)])
    return direct, md.gbar1(a, c)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--dps", type=int, default=20)
    ap.add_argument("--cases", default="0.3:1,0.3:5,0.6:1,10:63")
    ap.add_argument("--verbose", action="store_true")
    ap.add_argument("--balance", action="store_true",
                    help="also the energy lost on approach and on retraction (12 digits, slow)")
    ap.add_argument("--verify-gap", action="store_true",
                    help="check the mean-gap formula against a double quadrature of Hui's gap")
    opts = ap.parse_args()
    mp.mp.dps = opts.dps
    if opts.verify_gap:
        with mp.workdps(15):
            for alpha, mu, a, c in [(0.3, 1, 0.2, 0.3), (10, 63, 0.1, 0.1005)]:
                d, f = verify_gap(MD(alpha, mu), mp.mpf(a), mp.mpf(c))
                print(f"mean gap, alpha {alpha} mu {mu} a* {a} c* {c}: double quadrature "
                      f"{mp.nstr(d, 15)}, closed form {mp.nstr(f, 15)}, rel. diff "
                      f"{mp.nstr(abs(d - f) / abs(f), 3)}", flush=True)
    for case in opts.cases.split(","):
        t_start = time.time()
        alpha, mu = (float(x) for x in case.split(":"))
        md = MD(alpha, mu)
        chain, c_close, a_sw, branch = build_chain(md, alpha, mu)
        events, w, i_app, i_ret, segs = walk(md, chain, opts.balance, opts.verbose)
        lib = wa.gap_law("md", alpha, mu, [0.5])
        rel = abs(lib.W_star - w) / w
        if opts.verbose:
            for e in events:
                print("   ", e[0], e[1], "gbar =", mp.nstr(e[2], 14), "P =", mp.nstr(e[3], 10))
        print(f"md alpha {alpha:g} mu {mu:g}: W* (mpmath) = {mp.nstr(w, 18)}  library = "
              f"{lib.W_star!r}  rel. diff = {mp.nstr(rel, 3)}  W*/(pi alpha^2/2) = "
              f"{mp.nstr(w / md.wad, 12)}")
        if opts.balance:
            print(f"   energy lost on approach {mp.nstr(-i_app + md.wad - mp.mpf(1) / 4, 10)}, on "
                  f"retraction {mp.nstr(mp.mpf(1) / 4 - md.wad - i_ret, 10)} (sum "
                  f"{mp.nstr(-i_app - i_ret, 10)}); int_0^inf P_app dgbar* = {mp.nstr(-i_app, 10)}, "
                  f"int_0^inf P_ret dgbar* = {mp.nstr(i_ret, 10)}")
        print(f"   work of adhesion {mp.nstr(md.wad, 12)}; c_close = {mp.nstr(c_close, 12)}, a_sw = "
              f"{mp.nstr(a_sw, 12)}; {time.time() - t_start:.0f} s", flush=True)


if __name__ == "__main__":
    main()
