#!/usr/bin/env python3
"""Independent check of the energy lost per cycle W* under gap control (DW), with mpmath.

    .venv/bin/python study/verify/check_gap_energy.py [--dps 25]

For DW at alpha = 0.3, mu = 1 (and 0.6, 1) the mean gap falls monotonically along the
contact curve, so the gap-controlled cycle is: approach without interaction down to the
touch at gbar* = 1, a jump onto the curve (a* = a1, gbar* = 1), the curve down to full
contact and back up to a* -> 0 (gbar* = g0), and a jump to P* = 0. Hence
    W* = -oint P* dgbar* = int_0^a1 P*(a) dgbar*/da da.
Every quantity is computed here from the equations of doc/theory.md in mpmath: the case-1
root C(A) of (2.25b) with I* by tanh-sinh quadrature (the library only supplies the starting
guess), P* from (2.25a), gbar* = (1+lambda) g_W(A^2) - lambda g_W(C^2), dgbar*/da by
mpmath's numerical differentiation, the integral by tanh-sinh. It prints W* beside the
library's (`wavyadhesion path --control gap`) and their relative difference.
"""
import argparse
import subprocess

import mpmath as mp

import wavyadhesion as wa


def dw_state(alpha, mu, a_star, c_guess):
    """(C, lambda, P*, gbar*) of the DW case-1 state at a*, by mpmath."""
    s0 = mp.pi * mu * (alpha ** 2 / 32) ** (mp.mpf(1) / 3)
    A = mp.sin(mp.pi * a_star)

    def istar(C):
        return mp.quad(lambda X: mp.sqrt(1 - X ** 2) * mp.sqrt(C ** 2 - X ** 2)
                       * mp.sqrt(X ** 2 - A ** 2), [A, C])

    def lam(C):
        return s0 / (2 * mp.sqrt(1 - A ** 2) * mp.sqrt(C ** 2 - A ** 2))

    def g(C):
        lm = lam(C)
        return mp.log(lm * (1 + lm) * 16 / (mp.pi * alpha ** 2) * istar(C))

    # bracket the root tightly around the guess (a secant step may leave (A, 1))
    c0 = mp.sin(mp.pi * mp.mpf(c_guess))
    lo, hi = A + (c0 - A) * (1 - mp.mpf("1e-6")), c0 + (1 - c0) * mp.mpf("1e-6")
    C = mp.findroot(g, (lo, hi), solver="anderson")
    lm = lam(C)
    p = A ** 2 - lm * (C ** 2 - A ** 2)

    def gw(s):
        return 1 - s + (s * mp.log(s) if s > 0 else 0)

    return C, lm, p, (1 + lm) * gw(A ** 2) - lm * gw(C ** 2)


def energy(alpha, mu, a_guess):
    alpha, mu = mp.mpf(alpha), mp.mpf(mu)

    def state(a):
        c = wa.equilibrium("dw", float(alpha), float(mu), float(a)).c_star
        return dw_state(alpha, mu, a, float(c))

    # the touch: gbar*(a1) = 1
    a1 = mp.findroot(lambda a: state(a)[3] - 1, (a_guess * 0.999, a_guess * 1.001))
    integrand = lambda a: state(a)[2] * mp.diff(lambda x: state(x)[3], a)
    return a1, mp.quad(integrand, [mp.mpf("1e-30"), a1 / 4, a1])


def library_w(alpha, mu):
    """The library's W* and the a* where its approach lands at the touch (a guess only)."""
    out = subprocess.run(["wavyadhesion", "path", "--control", "gap", "--model", "dw",
                          "--alpha", str(alpha), "--mu", str(mu)], check=True,
                         capture_output=True, text=True).stdout
    line = [l for l in out.splitlines() if l.startswith("# W* = ")][0]
    landing = [l.split() for l in out.splitlines() if l.startswith("1 4 ")][0]
    return mp.mpf(line.split()[3]), float(landing[2])


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--dps", type=int, default=25)
    opts = ap.parse_args()
    mp.mp.dps = opts.dps
    for alpha, mu in [(0.3, 1.0), (0.6, 1.0)]:
        lib, a_guess = library_w(alpha, mu)
        a1, w = energy(alpha, mu, a_guess)
        print(f"dw alpha {alpha} mu {mu}: a1 = {mp.nstr(a1, 15)}  W* (mpmath) = "
              f"{mp.nstr(w, 18)}  library = {mp.nstr(lib, 17)}  rel. diff = "
              f"{mp.nstr(abs(lib - w) / w, 3)}")


if __name__ == "__main__":
    main()
