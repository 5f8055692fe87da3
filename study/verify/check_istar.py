#!/usr/bin/env python3
"""Reference values of the double-Westergaard elliptic integrals (mpmath only).

    W(A,C) = I*(A,C)/(C^2-A^2)^2,   I*(A,C) = int_A^C sqrt(1-X^2) sqrt(C^2-X^2) sqrt(X^2-A^2) dX
    I_A*(A) = int_A^1 (1-X^2) sqrt(X^2-A^2) dX                      (2.25b), (2.28c), doc/theory.md

The Fortran routine istar_scaled(a, c, d2, omc2) takes the four doubles A, C, C^2-A^2, 1-C^2.
Each reference below is W for exactly those four doubles, i.e. (E1) of src/wa_elliptic.f90,

    W = int_0^{pi/2} s^2 k^2 sqrt(a1 k^2 + b1 s^2)/sqrt(a2 k^2 + b2 s^2) dphi,
    a1 = omc2, b1 = omc2 + d2, a2 = c^2, b2 = a^2       (s = sin phi, k = cos phi),

evaluated at mp.dps = 40 by tanh-sinh quadrature (mpmath.quad) in the variable u = ln(tan^2 phi),
with breakpoints at ln y, 0, ln x (y = a1/b1, x = a2/b2), where the integrand changes scale:

    W = (1/2) sqrt(b1/b2) int_{-oo}^{oo} t sqrt(t (t+y)/(t+x)) / (1+t)^3 du,   t = e^u.

Checks printed by default (no arguments):
  * the u-form against the phi-form (E1) at moderate parameters,
  * the closed form in Carlson's R_F, R_D, R_J (module header of src/wa_elliptic.f90) against
    the quadrature, and the factor by which its three terms cancel (why it is not used),
  * I_A* by quadrature against its closed form (E4) at 80 digits and the series (E5),
  * the reference table.
With --fortran it prints the table as Fortran data for test/unit/test_elliptic.f90.
"""
import argparse

from mpmath import mp, mpf, sqrt, quad, inf, exp, log, pi, sin, cos, atanh
from mpmath import elliprf, elliprd, elliprj

mp.dps = 40


def w_reference(a, c, d2, omc2):
    """W for the exact double inputs, by tanh-sinh quadrature in u = ln t."""
    a, c, d2, omc2 = (mpf(v) for v in (a, c, d2, omc2))
    b1 = omc2 + d2
    x = c * c / (a * a)
    y = omc2 / b1

    def f(u):
        t = exp(u)
        return t * sqrt(t * (t + y) / (t + x)) / (1 + t) ** 3

    breaks = sorted({mpf(0), log(x)} | ({log(y)} if y > 0 else set()))
    return sqrt(b1) / (2 * a) * quad(f, [-inf] + breaks + [inf])


def w_phi_form(a, c, d2, omc2):
    """(E1) directly; only for moderate parameters (no near-singular endpoint layers)."""
    a, c, d2, omc2 = (mpf(v) for v in (a, c, d2, omc2))
    a1, b1, a2, b2 = omc2, omc2 + d2, c * c, a * a

    def f(p):
        s2, k2 = sin(p) ** 2, cos(p) ** 2
        return s2 * k2 * sqrt(a1 * k2 + b1 * s2) / sqrt(a2 * k2 + b2 * s2)

    return quad(f, [0, pi / 4, pi / 2])


def w_carlson(a, c, d2, omc2):
    """The closed form in Carlson's integrals; returns (W, cancellation factor)."""
    a, c, d2, omc2 = (mpf(v) for v in (a, c, d2, omc2))
    b1 = omc2 + d2
    x, y = c * c / (a * a), omc2 / b1
    al = (x * y - 2 * x + 1) / (8 * (x - 1) * (y - 1))
    be = -x * (x - y) * (x * y - 2 * x + 2 * y - 1) / (8 * (x - 1) ** 2 * (y - 1))
    ga = (x**2 * y**2 - 4 * x * y**2 + 6 * x * y - 4 * x + 1) / (8 * (x - 1) ** 2 * (y - 1))
    terms = [2 * al * elliprf(0, x, y), 2 * be / 3 * elliprd(0, y, x),
             2 * ga / 3 * elliprj(0, x, y, 1)]
    g = sum(terms)
    return sqrt(b1) / (2 * a) * g, sum(abs(t) for t in terms) / abs(g)


def ia_quadrature(a, oma2):
    """I_A* from (2.28c) with X^2 = A^2 + z w, z = 1 - A^2 (oma2 if A^2 >= 1/2, else 1 - a^2)."""
    z = mpf(oma2) if oma2 <= 0.5 else 1 - mpf(a) ** 2
    f = lambda w: (1 - w) * sqrt(w) / sqrt(1 - z * (1 - w))
    return z**2 * sqrt(z) / 2 * quad(f, [0, 1])


def ia_closed(z):
    with mp.workdps(80):
        z = mpf(z)
        s = sqrt(z)
        return (s * (3 - z) - (1 - z) * (3 + z) * atanh(s)) / 8


def case(A, C=None, omc2=None):
    """Doubles (a, c, d2, omc2) for A <= C <= 1 given in mpmath by C or by 1 - C^2."""
    if C is None:
        C2 = 1 - omc2
        C = sqrt(C2)
    else:
        C2 = C * C
        omc2 = 1 - C2
    return float(A), float(C), float(C2 - A * A), float(omc2)


def case_near_one(oma2, frac):
    """A^2 = 1 - oma2, 1 - C^2 = frac * oma2 (A and C both within 1e-17 of 1 possible)."""
    oma2 = mpf(oma2)
    A, C = sqrt(1 - oma2), sqrt(1 - frac * oma2)
    return float(A), float(C), float(oma2 * (1 - frac)), float(frac * oma2)


def table():
    """The reference grid: interior, C -> A, C = 1, A -> 0, A -> 1 and the corners."""
    rows = []
    for A in ["1e-12", "1e-6", "0.001", "0.1", "0.5", "0.9", "0.999"]:
        A = mpf(A)
        for rel in ["1e-16", "1e-8", "1e-3", "0.5"]:
            C = A * (1 + mpf(rel))
            if C < 1:
                rows.append(case(A, C))
        for omc2 in ["0.5", "1e-6", "1e-20", "1e-40"]:      # 1 - C^2, C -> 1
            if 1 - mpf(omc2) > A * A:
                rows.append(case(A, omc2=mpf(omc2)))
        rows.append(case(A, mpf(1)))                        # C = 1 exactly
    for oma2 in ["1e-9", "1e-17"]:                          # A -> 1
        for frac in ["0", "1e-6", "0.5", "0.999999"]:
            rows.append(case_near_one(oma2, mpf(frac)))
    return rows


def ia_table():
    rows = []
    for oma2 in ["1e-17", "1e-9", "1e-3", "0.05", "0.1", "0.3", "0.5", "0.7", "0.99"]:
        z = mpf(oma2)
        rows.append((float(sqrt(1 - z)), float(z)))
    for A in ["1e-3", "1e-6", "1e-12"]:
        A = mpf(A)
        rows.append((float(A), float(1 - A * A)))
    return rows


def checks():
    print("u-form vs phi-form (E1) and Carlson closed form:")
    print(f"{'A':>10} {'C':>10} {'W':>24} {'phi/u-1':>9} {'Carl/u-1':>9} {'cancel':>8}")
    for A, C in [("0.3", "0.5"), ("0.3", "0.9"), ("0.01", "0.5"), ("0.5", "0.51"),
                 ("0.9", "0.95"), ("0.99", "0.999"), ("0.5", "0.999999"), ("1e-6", "0.9")]:
        cs = case(mpf(A), mpf(C))
        w = w_reference(*cs)
        wc, amp = w_carlson(*cs)
        print(f"{A:>10} {C:>10} {mp.nstr(w, 20):>24} {mp.nstr(w_phi_form(*cs) / w - 1, 2):>9}"
              f" {mp.nstr(wc / w - 1, 2):>9} {mp.nstr(amp, 3):>8}")
    print("\nlimit C -> A: W -> pi sqrt(1-A^2)/(16 A)")
    for A in ["1e-6", "0.5", "0.999"]:
        A = mpf(A)
        cs = case(A, A * (1 + mpf("1e-12")))
        lim = pi * sqrt(1 - A * A) / (16 * A)
        print(f"  A = {mp.nstr(A, 4):>8}: W/limit - 1 = {mp.nstr(w_reference(*cs) / lim - 1, 3)}")
    print("\nI_A*: quadrature vs closed form (E4) at 80 digits:")
    for a, oma2 in ia_table():
        iq = ia_quadrature(a, oma2)
        z = mpf(oma2) if oma2 <= 0.5 else 1 - mpf(a) ** 2
        print(f"  1-A^2 = {oma2:9.3g}: I_A* = {mp.nstr(iq, 20):>26}"
              f"  (E4)/quad - 1 = {mp.nstr(ia_closed(z) / iq - 1, 2)}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--fortran", action="store_true", help="print Fortran data statements")
    args = parser.parse_args()
    rows = [(cs, w_reference(*cs)) for cs in table()]
    ia_rows = [(r, ia_quadrature(*r)) for r in ia_table()]
    if args.fortran:
        fmt = lambda v: f"{float(v):.17e}_wp"
        for cs, w in rows:
            print("      w_case(" + ", ".join(fmt(v) for v in cs[:3]) + ", &")
            print("             " + fmt(cs[3]) + ", " + fmt(w) + "), &")
        print()
        for r, ia in ia_rows:
            print("      ia_case(" + ", ".join(fmt(v) for v in r) + ", " + fmt(ia) + "), &")
        return
    checks()
    print(f"\n{'a':>24} {'c':>24} {'d2 = C^2-A^2':>24} {'omc2 = 1-C^2':>24} {'W':>24}")
    for cs, w in rows:
        print(" ".join(f"{v:24.17e}" for v in cs), f"{float(w):24.17e}")
    print(f"\n{'a':>24} {'oma2 = 1-A^2':>24} {'I_A*':>24}")
    for r, ia in ia_rows:
        print(" ".join(f"{v:24.17e}" for v in r), f"{float(ia):24.17e}")


if __name__ == "__main__":
    main()
