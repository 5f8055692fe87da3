#!/usr/bin/env python3
"""Generate the fixed quadrature rules of src/wa_md.f90 (Fortran parameter constants).

Psi_c of (2.27d) is computed there as
    Psi_c = -(2 A q sin s / pi) K,
    K = int_0^1 artanh(r) r dr / ((1 - k^2 r^2) sqrt(1 - sin^2 s r^2)),
split at r = y = 1/sqrt(2) (y = sqrt(1 - r^2)):
  * inner part, r in [0, 1/sqrt 2]: Gauss-Legendre (N_INNER nodes) with artanh(r) r
    folded into the weights;
  * outer part, y in [0, 1/sqrt 2], integrand (ln(1+r) - ln y) y / (...): geometric
    levels [y_s 4^-(j+1), y_s 4^-j] with Gauss-Legendre (N_LEVEL nodes on [1/4, 1]),
    then a tail [0, d] with two Gauss rules on [0, 1]: weight u (N_TAIL) and weight
    -u ln u (N_TAIL).
Rules for non-classical weights are built from exact moments (Hankel/Cholesky,
Golub-Welsch) at 200 digits.  Usage: python3 tools/md_gauss_rules.py > rules.f90
"""
import mpmath as mp

mp.mp.dps = 200
N_INNER, N_LEVEL, N_TAIL = 14, 16, 12


def gauss_from_moments(mom, n):
    """Gauss rule (nodes, weights) for the weight with moments mom[0..2n]."""
    hank = mp.matrix(n + 1, n + 1)
    for i in range(n + 1):
        for j in range(n + 1):
            hank[i, j] = mom[i + j]
    up = mp.cholesky(hank).T
    alpha, beta = [], []
    for j in range(n):
        alpha.append(up[j, j + 1] / up[j, j] - (up[j - 1, j] / up[j - 1, j - 1] if j else 0))
        if j < n - 1:
            beta.append(up[j + 1, j + 1] / up[j, j])
    jac = mp.matrix(n, n)
    for i in range(n):
        jac[i, i] = alpha[i]
        if i < n - 1:
            jac[i, i + 1] = jac[i + 1, i] = beta[i]
    eig, vec = mp.eigsy(jac)
    order = sorted(range(n), key=lambda i: eig[i])
    return [eig[i] for i in order], [mom[0] * vec[0, i] ** 2 for i in order]


def rule(kind, n):
    """Gauss rule on [0, 1] for weight 1, u, -u ln u or -ln u."""
    moments = {"legendre": lambda k: mp.mpf(1) / (k + 1),
               "u": lambda k: mp.mpf(1) / (k + 2),
               "ulog": lambda k: mp.mpf(1) / (k + 2) ** 2,
               "log": lambda k: mp.mpf(1) / (k + 1) ** 2}[kind]
    return gauss_from_moments([moments(k) for k in range(2 * n + 2)], n)


def fortran_array(name, values, comment):
    lines = [f"   !> {comment}",
             f"   real(wp), parameter :: {name}({len(values)}) = [ &"]
    body = [f"      {mp.nstr(v, 21, min_fixed=-1, max_fixed=0, strip_zeros=False)}_wp"
            for v in values]
    body = [b.replace("e", "e") for b in body]
    for i, b in enumerate(body):
        lines.append(b + (", &" if i < len(body) - 1 else "]"))
    return "\n".join(lines)


def main():
    rs = mp.sqrt(mp.mpf(1) / 2)
    x, w = rule("legendre", N_INNER)
    r = [rs * xi for xi in x]
    print(fortran_array("inner_r2", [ri ** 2 for ri in r], "Inner nodes r^2, r in (0, 1/sqrt 2)"))
    print(fortran_array("inner_w", [rs * wi * mp.atanh(ri) * ri for wi, ri in zip(w, r)],
                        "Inner weights with artanh(r) r folded in"))
    x, w = rule("legendre", N_LEVEL)
    print(fortran_array("level_eta", [mp.mpf(1) / 4 + mp.mpf(3) / 4 * xi for xi in x],
                        "Level nodes on [1/4, 1] (times y_s 4^-j)"))
    print(fortran_array("level_w", [mp.mpf(3) / 4 * wi for wi in w], "Level weights on [1/4, 1]"))
    x, w = rule("u", N_TAIL)
    print(fortran_array("tail_u", x, "Tail nodes, weight u on [0, 1]"))
    print(fortran_array("tail_uw", w, "Tail weights, weight u on [0, 1]"))
    x, w = rule("ulog", N_TAIL)
    print(fortran_array("tail_l", x, "Tail nodes, weight -u ln u on [0, 1]"))
    print(fortran_array("tail_lw", w, "Tail weights, weight -u ln u on [0, 1]"))


if __name__ == "__main__":
    main()
