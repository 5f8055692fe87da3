#!/usr/bin/env python3
"""mpmath reference values for the Maugis-Dugdale model (src/wa_md.f90, test/unit/test_md.f90).

Independent of the library's reformulation: the equations are evaluated in the paper's own
variables c*, with 32 significant digits,
  P*  = A^2 - Sigma0 [1 - (2/pi) arcsin(cos(pi c*)/cos(pi a*))]           (2.27a)
  F   = chi1 C - P* chi2 + Sigma0 Psi_c - Dcod                             (2.27b)
  Psi_c = -int_a^c ln|(chi3(c)+chi3(t))/(chi3(c)-chi3(t))| dt              (2.27d)
Psi_c is integrated after w = chi3(t) = chi3(c) r (checked against the t-integral itself
by `psi_check`):  Psi_c = -(2 A chi3c^2/pi) int_0^1 artanh(r) r/((1-chi3c^2 r^2)
sqrt(1-A^2-chi3c^2 r^2)) dr, with r = sqrt(1-y^2) near r = 1 and geometric break points.
Roots: a scan in g = c*-a* (logistic in ln, 1e-30 .. 1/2-a* - 1e-30), each sign change
refined by mp.findroot (Anderson), then verified by bisection bounds.

Usage:
  python3 tools/reference/md_reference.py psi  A_STAR GAP [...]            -> Psi_c
  python3 tools/reference/md_reference.py roots ALPHA MU A_STAR            -> rows: c* gap P* zone
  python3 tools/reference/md_reference.py table FILE < cases.txt          (alpha mu a_star per line)
"""
import sys
import mpmath as mp

mp.mp.dps = 32


def consts(alpha, mu):
    alpha, mu = mp.mpf(alpha), mp.mpf(mu)
    sigma0 = mp.pi * mu * mp.cbrt(alpha ** 2 / 32)
    dcod = mp.cbrt(alpha ** 4 / 2) / mu
    return sigma0, dcod


def psi_c(a, gap):
    """Psi_c(c*, a*), c* = a* + gap (mp numbers)."""
    a, gap = mp.mpf(a), mp.mpf(gap)
    c = a + gap
    A = mp.sin(mp.pi * a)
    C = mp.sin(mp.pi * c)
    # exact identities, so that nothing cancels for tiny gaps or c* -> 1/2:
    # 1 - chi3c^2 = A^2/C^2,  1 - A^2 - chi3c^2 = A^2 cos^2(pi c)/C^2
    k2 = mp.sin(mp.pi * gap) * mp.sin(mp.pi * (c + a)) / C ** 2
    omk2 = A ** 2 / C ** 2
    qmk2 = (A * mp.cos(mp.pi * c) / C) ** 2
    f = lambda r: mp.atanh(r) * r / ((omk2 + k2 * (1 - r * r)) * mp.sqrt(qmk2 + k2 * (1 - r * r)))
    rs = mp.sqrt(mp.mpf(1) / 2)
    # outer part in y = sqrt(1 - r^2): artanh r = ln(1+r) - ln y, r dr = -y dy
    g = lambda y: (mp.log(1 + mp.sqrt(1 - y * y)) - mp.log(y)) * y / (
        (omk2 + k2 * y * y) * mp.sqrt(qmk2 + k2 * y * y))
    # break points down to a sixteenth of the distance of the nearest singularity
    # (pole and branch point at y = +-i sqrt(1-k2)/k, +-i sqrt(q2-k2)/k)
    h = mp.sqrt(min(omk2, qmk2) / k2)
    levels = max(0, int(mp.ceil(mp.log(16 * rs / h, 4))))
    pts = [0] + [rs * mp.mpf(4) ** (-j) for j in range(levels, -1, -1)]
    total = mp.quad(f, [0, rs / 2, rs]) + mp.quad(g, pts)
    return -(2 * A * k2 / mp.pi) * total


def psi_check(a, gap):
    """Psi_c straight from (2.27d) (slow; for checking psi_c)."""
    a, gap = mp.mpf(a), mp.mpf(gap)
    c = a + gap
    A = mp.sin(mp.pi * a)
    chi3 = lambda e: mp.sqrt(1 - A ** 2 / mp.sin(mp.pi * e) ** 2)
    x3c = chi3(c)
    f = lambda t: mp.log(abs((x3c + chi3(t)) / (x3c - chi3(t))))
    return -mp.quad(f, [a, a + gap / 2, c])


def load(sigma0, a, gap):
    """(2.27a); 1 - (2/pi) arcsin(z) = (4/pi) arcsin(sqrt((1-z)/2)), z = cos(pi c)/cos(pi a),
    1 - z = 2 sin(pi (c+a)/2) sin(pi gap/2)/cos(pi a) (exact, no cancellation)."""
    a, gap = mp.mpf(a), mp.mpf(gap)
    c = a + gap
    A = mp.sin(mp.pi * a)
    one_minus_z = 2 * mp.sin(mp.pi * (c + a) / 2) * mp.sin(mp.pi * gap / 2) / mp.cos(mp.pi * a)
    return A ** 2 - sigma0 * (4 / mp.pi) * mp.asin(mp.sqrt(one_minus_z / 2))


def residual(sigma0, dcod, a, gap):
    a, gap = mp.mpf(a), mp.mpf(gap)
    c = a + gap
    A = mp.sin(mp.pi * a)
    C = mp.sin(mp.pi * c)
    chi1 = mp.sqrt(mp.sin(mp.pi * gap) * mp.sin(mp.pi * (c + a)))   # sqrt(C^2 - A^2)
    chi2 = mp.log((C + chi1) / A)
    return chi1 * C - load(sigma0, a, gap) * chi2 + sigma0 * psi_c(a, gap) - dcod


def midgap_opening(a):
    A = mp.sin(mp.pi * mp.mpf(a))
    q = mp.sqrt(1 - A ** 2)
    return q - A ** 2 * mp.log((1 + q) / A)


def roots(alpha, mu, a, step=0.5):
    """All equilibria at a*: [(c*, gap, P*, zone_case)], case-1 by increasing c*."""
    sigma0, dcod = consts(alpha, mu)
    a = mp.mpf(a)
    width = mp.mpf(1) / 2 - a
    gap_of = lambda u: width / (1 + mp.exp(-u))
    out = []
    us = [mp.mpf(-60) + step * i for i in range(int(120 / step) + 1)]
    fs = [residual(sigma0, dcod, a, gap_of(u)) for u in us]
    for i in range(len(us) - 1):
        if (fs[i] < 0) != (fs[i + 1] < 0):
            u = mp.findroot(lambda v: residual(sigma0, dcod, a, gap_of(v)),
                            (us[i], us[i + 1]), solver='anderson')
            g = gap_of(u)
            out.append((a + g, g, load(sigma0, a, g), 1))
    if midgap_opening(a) <= dcod:
        out.append((mp.mpf(1) / 2, width, mp.sin(mp.pi * a) ** 2 - sigma0, 2))
    return out


def main(argv):
    # inputs are taken as the doubles nearest to them, as the Fortran code sees them
    num = lambda text: mp.mpf(float(text))
    if argv[1] == "psi":
        for i in range(2, len(argv), 2):
            print(mp.nstr(psi_c(num(argv[i]), num(argv[i + 1])), 25))
    elif argv[1] == "roots":
        for c, g, p, z in roots(*map(num, argv[2:5])):
            print(mp.nstr(c, 20), mp.nstr(g, 20), mp.nstr(p, 20), z)
    elif argv[1] == "table":
        with open(argv[2], "w") as out:
            out.write("# alpha mu a_star c_star gap P_star zone_case  (tools/reference/md_reference.py)\n")
            for line in sys.stdin:
                if not line.strip() or line.startswith("#"):
                    continue
                al, mu, a = line.split()
                for c, g, p, z in roots(num(al), num(mu), num(a)):
                    out.write(f"{al} {mu} {a} {mp.nstr(c, 20)} {mp.nstr(g, 20)} "
                              f"{mp.nstr(p, 20)} {z}\n")
                out.flush()


if __name__ == "__main__":
    main(sys.argv)
