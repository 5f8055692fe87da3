#!/usr/bin/env python3
"""Independent mpmath reference for the MD no-contact crest gap and mean gap near c* = 1/2.

Prints the values that test/unit/test_separation.f90 (test_crest_near_half) compares with:
the crest gap H(c*) = h(0)/Delta and the mean gap of the no-contact MD state (zone |x*| < c*
around the crest, doc/theory.md "MD, no contact") at large Sigma0, where the two-term Clausen
form loses every digit next to c* = 1/2, and the closures (zeros of H) at the reproducer of the
wrong-status defect (alpha = 194144313374.73993, mu = 256617602357780.94).

Everything is computed at 60 digits for the exact double inputs.  H and gbar come from the
Clausen closed forms (evaluated at 60 digits the rounding of 4 pi c* next to 2 pi is harmless);
--verify checks both against their definitions, the gap slope integrated from the Dugdale
condition h(c*) = 2 Dcod and the mean of h over the period, by quadrature (30 digits).

Usage: python3 tools/reference/make_crest_reference.py [--verify]
"""

import sys

from mpmath import mp, mpf, pi, sin, log, clsin, quad, findroot

mp.dps = 60

# the reproducer, and a case whose no-contact states exist within 3e-14 of c* = 1/2
# (Sigma0 = 2.1e8, Dcod = 36.8)
REPRO = (194144313374.73993, 256617602357780.94)
NEAR = (1.0e5, 1.0e5)


def params(alpha, mu):
    al, m = mpf(alpha), mpf(mu)
    sigma0 = pi * m * (al ** 2 / 32) ** (mpf(1) / 3)
    dcod = (al ** 4 / 2) ** (mpf(1) / 3) / m
    return sigma0, dcod


def crest(sigma0, dcod, c):
    c = mpf(c)
    return 2 * dcod - 2 * sin(pi * c) ** 2 + sigma0 / pi * (clsin(2, 4 * pi * c) - 2 * clsin(2, 2 * pi * c))


def gbar(sigma0, dcod, c):
    return crest(sigma0, dcod, c) + 1 + 2 * sigma0 / pi * clsin(2, 2 * pi * mpf(c))


def slope(sigma0, c, s):
    """dh/dx at x* = s (the periodic Hilbert transform of the traction -Sigma0 on |x*| < c*)."""
    den = sin(pi * (s - c))
    if den == 0:
        return mpf(0)        # the log-singular point (measure zero for the quadrature)
    return 2 * pi * sin(2 * pi * s) + 2 * sigma0 * log(abs(sin(pi * (s + c)) / den))


def verify():
    """H = h(0) = 2 Dcod - int_0^c slope; gbar = 2 int_0^(1/2) h = H + 2 int_0^(1/2) (1/2 - s) slope."""
    for alpha, mu, c in [(0.3, 0.01, 0.45), (NEAR[0], NEAR[1], 0.5 - 2.0 ** -36),
                         (NEAR[0], NEAR[1], 1e-12)]:
        s0, dc = params(alpha, mu)
        c = mpf(c)
        h0 = 2 * dc - quad(lambda s: slope(s0, c, s), [0, c])
        g = h0 + 2 * quad(lambda s: (mpf(1) / 2 - s) * slope(s0, c, s), [0, c, mpf(1) / 2])
        print(f"verify alpha={alpha} mu={mu} c={mp.nstr(c, 17)}: H rel diff "
              f"{mp.nstr(abs(h0 / crest(s0, dc, c) - 1), 3)}, gbar rel diff "
              f"{mp.nstr(abs(g / gbar(s0, dc, c) - 1), 3)}")


def main():
    if "--verify" in sys.argv:
        with mp.workdps(30):
            verify()
    s0, dc = params(*REPRO)
    print("reproducer alpha, mu =", REPRO, " Sigma0 =", mp.nstr(s0, 20), " Dcod =", mp.nstr(dc, 20))
    for c in [0.5, 0.5 - 2.0 ** -52, 0.5 - 2.0 ** -40, 0.5 - 2.0 ** -20, 0.4, 0.3]:
        print(f"  H({c!r}) = {mp.nstr(crest(s0, dc, c), 20)}")
    # the closures: H(c*) = 0 near 0 and (reopening) near 1/2, the latter in d = 1/2 - c*
    c1 = findroot(lambda c: crest(s0, dc, c), mpf("3e-22"))
    d2 = findroot(lambda d: crest(s0, dc, mpf(1) / 2 - d), mpf("3e-24"))
    print(f"  c_close(1) = {mp.nstr(c1, 20)}, 1/2 - c_close(2) = {mp.nstr(d2, 20)}")
    s0, dc = params(*NEAR)
    print("near-half alpha, mu =", NEAR, " Sigma0 =", mp.nstr(s0, 20), " Dcod =", mp.nstr(dc, 20))
    for c in [0.5 - 2.0 ** -45, 0.5 - 2.0 ** -36, 1e-12]:
        print(f"  c = {c!r}: H = {mp.nstr(crest(s0, dc, c), 20)}, gbar = {mp.nstr(gbar(s0, dc, c), 20)}")
    print(f"  c = 0.4: H = {mp.nstr(crest(s0, dc, 0.4), 20)}")


if __name__ == "__main__":
    main()
