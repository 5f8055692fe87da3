#!/usr/bin/env python3
"""Boundary-element cross-check of the Maugis-Dugdale (MD) gap law with tamaas.

Issue 11, item 6 (doc/accuracy-performance.md, section 10). Not run in CI.

tamaas (FFT boundary elements, PyPI) solves the 1-D periodic contact of the rigid wave
h(x) = Delta cos(2 pi x / L) against an elastic half-plane (plane strain, E*) with the
mean gap imposed (PolonskyKeerRey, primal and constraint "gap") and the Dugdale law as the
MaugisAdhesionFunctional (potential -w (1 - g/rho) for 0 <= g < rho: cohesive stress
w/rho for g < rho, zero beyond).  The library's dimensionless parameters map onto it as
(doc/theory.md, "Parameters"):

    p*     = pi E* Delta / L                  (P* = mean traction / p*, compressive > 0)
    w      = alpha^2 pi^2 E* Delta^2 / (2 L)  (alpha = sqrt(2 w L / (pi^2 E* Delta^2)))
    sigma0 = Sigma0 p*,  Sigma0 = mu pi (alpha^2/32)^(1/3)
    rho    = w / sigma0 = h0 = 2 Delta Delta_cod
    gbar*  = mean(gap) / Delta

The mapping is checked first on the non-adhesive (Westergaard) case, whose closed form is
gbar* = 1 - P* + P* ln P* (`--westergaard`).  The MD sweep then lowers gbar* from beyond the
first interaction to `--gmin` (approach) and raises it back (retraction), each solve
warm-started from the previous state, as a displacement-controlled experiment would.  At
each gbar* it compares P*, a* (contact half-width / L) and c* (Dugdale-zone half-width / L)
with the library's approach and retraction states (`wavyadhesion.gap_law`, and the state on
`wavyadhesion.trace_branch` / `roots` with that gbar* and P*), and with the average of
approach and retraction, which cancels most of the grid's lattice trapping.

Usage (from the repository root, with tamaas, numpy and the library's Python package in
the interpreter's environment):

    python study/bem/tamaas_md.py --out study/results/bem_md.txt

writes the summary table to --out and the per-point rows to the same name with
`_points` before the extension.  Options: --cases 0.3:1,0.3:5,0.6:1  --N 1024,2048,...
--gstep 0.05  --gmin 0.05  --tol 1e-8  --max-iter 20000.
"""
import argparse
import math
import multiprocessing
import os
import sys
import time

import numpy as np

import tamaas as tm
import wavyadhesion as wa

L = 1.0        # period
DELTA = 0.01   # amplitude (linear elasticity: only gbar/Delta and P/p* matter)
E_STAR = 1.0   # model.E with nu = 0


def md_constants(alpha, mu):
    """Dimensional tamaas inputs of the library's (alpha, mu)."""
    p_star = math.pi * E_STAR * DELTA / L
    w = alpha**2 * math.pi**2 * E_STAR * DELTA**2 / (2.0 * L)
    sigma0_star = mu * math.pi * (alpha**2 / 32.0) ** (1.0 / 3.0)
    sigma0 = sigma0_star * p_star
    rho = w / sigma0
    return p_star, w, sigma0_star, rho


def make_solver(n, tol, max_iter, adhesion=None):
    """tamaas model, surface and gap-controlled Polonsky-Keer-Rey solver."""
    model = tm.ModelFactory.createModel(tm.model_type.basic_1d, [L], [n])
    model.E = E_STAR
    model.nu = 0.0
    x = np.arange(n) * L / n
    surface = DELTA * np.cos(2.0 * math.pi * x / L)
    solver = tm.PolonskyKeerRey(model, surface, tol, tm.PolonskyKeerRey.gap,
                                tm.PolonskyKeerRey.gap)
    solver.max_iter = max_iter
    keep = [surface]
    if adhesion is not None:
        functional = tm.MaugisAdhesionFunctional(surface)
        functional.parameters = adhesion
        solver.addFunctionalTerm(functional)
        keep.append(functional)
    return model, solver, keep


def zone_widths(gap, rho):
    """a*, c* of a BEM gap field (crest at node 0), averaged over both sides.

    a*: the contact is the run of nodes with gap == 0 around the crest; its edge lies
    between the last closed node x_k and the first open node x_{k+1}, located with the
    gap's (x - a)^(3/2) growth through the first two open nodes (clamped to [x_k, x_{k+1}]).
    c*: where the gap crosses rho, by linear interpolation between the two nodes.
    """
    n = gap.size
    dx = L / n
    half = n // 2
    out_a, out_c = [], []
    for side in (gap[: half + 1], np.concatenate(([gap[0]], gap[::-1][:half]))):
        closed = side <= 0.0
        if not closed[0]:
            a = 0.0
        elif closed.all():
            a = 0.5
        else:
            k = int(np.argmin(closed)) - 1          # last closed node of the run
            x1, x2 = (k + 1) * dx, (k + 2) * dx
            g1, g2 = side[k + 1], side[k + 2]
            a = (k + 0.5) * dx
            if g2 > g1 > 0.0:
                r = (g1 / g2) ** (2.0 / 3.0)
                a = min(max((x1 - r * x2) / (1.0 - r), k * dx), x1)
        inside = side < rho
        if not inside[0]:
            c = 0.0
        elif inside.all():
            c = 0.5
        else:
            j = int(np.argmin(inside))              # first node with gap >= rho
            g0, g1 = side[j - 1], side[j]
            c = ((j - 1) + (rho - g0) / (g1 - g0)) * dx
        out_a.append(a / L)
        out_c.append(c / L)
    return 0.5 * sum(out_a), 0.5 * sum(out_c)


def residual(model, surface, p_star, sigma0=0.0, rho=0.0):
    """Equilibrium residual of a BEM state, independent of tamaas's error measure.

    From the gap g only: u = g + h, elastic traction fluctuation K u (K = E*|k|/2 in
    Fourier space), plus the reported mean traction P.  On open nodes (g > 0) the
    traction must be the Dugdale law (-sigma0 where g < rho, 0 beyond); on closed nodes
    it must be >= -sigma0.  Returns the largest violation over p*.
    """
    gap = np.array(model["gap"]).ravel()
    n = gap.size
    k = 2.0 * math.pi * np.fft.fftfreq(n, d=L / n)
    ku = np.real(np.fft.ifft(0.5 * E_STAR * np.abs(k) * np.fft.fft(gap + surface)))
    p = np.array(model.traction).ravel().mean() + ku
    open_ = gap > 0.0
    law = np.where(gap < rho, -sigma0, 0.0)
    r_open = np.abs(p - law)[open_].max() if open_.any() else 0.0
    r_closed = np.maximum(0.0, -sigma0 - p)[~open_].max() if (~open_).any() else 0.0
    return float(max(r_open, r_closed) / p_star)


def solve_at(model, solver, surface, gbar_star, p_star, sigma0=0.0, rho=0.0,
             rtol=1e-8, chunk=200, max_iter=20000):
    """Solve at one mean gap, in chunks of `chunk`, 2 `chunk`, 4 `chunk`, ... iterations
    (each warm-started from the last), until the residual (function `residual`) is <= rtol or `max_iter` iterations.
    tamaas's own error is not used as the test: it is undefined (divides by ~0) for
    states without contact, where it would always run to max_iter."""
    t = time.process_time()
    done, res, first = 0, math.inf, True
    while done < max_iter:
        solver.max_iter = min(chunk, max_iter - done)
        err = solver.solve(gbar_star * DELTA)
        done += solver.max_iter
        res = residual(model, surface, p_star, sigma0, rho)
        if res <= rtol or (err < solver.tolerance and not first):
            break
        first = False
        chunk *= 2
    cpu = time.process_time() - t
    traction = np.array(model.traction).ravel()
    gap = np.array(model["gap"]).ravel()
    return float(traction.mean() / p_star), gap, res, cpu


# --------------------------------------------------------------------------------------
# library states at a given gbar* and P*


def library_state(branch, sigma0_star, gbar, p_lib):
    """(a*, c*) of the library state with mean gap `gbar` and load `p_lib`.

    The branch (trace_branch, with the no-contact states a* = 0 first) is searched for
    the segments whose gbar* brackets `gbar`; the one whose interpolated P* is nearest
    `p_lib` is refined: no-contact states have c* = -P*/(2 Sigma0) exactly; contact
    states by bisection in a* on gbar*(a*) of the `roots` state nearest the branch's c*.
    Returns (a*, c*, |P*(state) - p_lib|).
    """
    if p_lib == 0.0:
        return 0.0, 0.0, 0.0
    g = branch.gbar
    best = None
    for i in range(g.size - 1):
        g0, g1 = g[i], g[i + 1]
        if not (np.isfinite(g0) and np.isfinite(g1)):
            continue
        if (g0 - gbar) * (g1 - gbar) > 0.0 or g0 == g1:
            continue
        t = (gbar - g0) / (g1 - g0)
        p = branch.P_star[i] + t * (branch.P_star[i + 1] - branch.P_star[i])
        if best is None or abs(p - p_lib) < best[0]:
            best = (abs(p - p_lib), i, t)
    if best is None:
        return math.nan, math.nan, math.nan
    _, i, t = best
    if branch.zone_case[i] == 0 and branch.zone_case[i + 1] == 0:
        return 0.0, -p_lib / (2.0 * sigma0_star), 0.0
    a0, a1 = branch.a_star[i], branch.a_star[i + 1]
    c_ref = branch.c_star[i] + t * (branch.c_star[i + 1] - branch.c_star[i])

    def state(a):
        sts = wa.roots("md", branch.alpha, branch.mu, a)
        return min(sts, key=lambda s: abs(s.c_star - c_ref))

    lo, hi = (a0, a1) if a0 < a1 else (a1, a0)
    lo = max(lo, 1e-9)
    s_lo = state(lo)
    f_lo = s_lo.gbar - gbar
    s = s_lo
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        s = state(mid)
        f = s.gbar - gbar
        if (f > 0) == (f_lo > 0):
            lo, f_lo = mid, f
        else:
            hi = mid
        if hi - lo < 1e-13:
            break
    return s.a_star, s.c_star, abs(s.P_star - p_lib)


def library_events(alpha, mu, gmax, probe=1e-3):
    """Mean gaps of the library's gap-control events, per stage.

    Jumps of P*(gbar*) (at constant gbar*) are found on a probe (step `probe`, geometric
    below 0.01) where |dP*| exceeds 5 step max|dP*/dgbar*| of the two ends or 4 times
    both neighbouring differences (a jump from a fold, where the slope is infinite), and
    located by bisection to
    1e-10; the largest gbar* with P* != 0 (first interaction / interaction lost) is added.
    """
    # geometric near gbar* = 0 (where dP*/dgbar* -> -inf), uniform beyond
    g = np.concatenate((np.geomspace(1e-6, 1e-2, 1000, endpoint=False),
                        np.arange(1e-2, gmax + probe, probe)))
    law = wa.gap_law("md", alpha, mu, g)
    out = {}
    for stage, p, s in (("approach", law.P_approach, law.dPdg_approach),
                        ("retract", law.P_retract, law.dPdg_retract)):
        ev = []
        dp = np.abs(np.diff(p))
        for k in range(g.size - 1):
            slope = max(abs(s[k]), abs(s[k + 1]))
            by_slope = np.isfinite(slope) and dp[k] > 5 * (g[k + 1] - g[k]) * slope + 1e-9
            # a jump that starts at a fold, where the slope is infinite: compare with the
            # neighbouring differences instead
            nb = max(dp[k - 1] if k > 0 else 0.0, dp[k + 1] if k + 1 < dp.size else 0.0)
            by_neighbours = dp[k] > 1e-4 and dp[k] > 4 * nb
            if not (by_slope or by_neighbours):
                continue
            lo, hi = g[k], g[k + 1]
            p_lo = p[k]
            for _ in range(40):
                mid = 0.5 * (lo + hi)
                lm = wa.gap_law("md", alpha, mu, [mid])
                pm = (lm.P_approach if stage == "approach" else lm.P_retract)[0]
                if abs(pm - p_lo) < abs(pm - p[k + 1]):
                    lo, p_lo = mid, pm
                else:
                    hi = mid
                if hi - lo < 1e-10:
                    break
            ev.append(0.5 * (lo + hi))
        nz = np.nonzero(p)[0]
        if nz.size:
            last = g[nz.max()]
            if not any(abs(last - e) < 2 * probe for e in ev):
                ev.append(float(last))
        out[stage] = sorted(ev)
    return out


# --------------------------------------------------------------------------------------


def functional_check():
    """Print tamaas's MaugisAdhesionFunctional on uniform gaps (rho = 0.5, w = 2): the
    potential per node is -w (1 - g/rho) for g < rho, 0 beyond; its gradient w/rho = 4."""
    n = 4
    surface = np.zeros(n)
    f = tm.MaugisAdhesionFunctional(surface)
    f.parameters = {"rho": 0.5, "surface_energy": 2.0}
    print("# gap  F/node  -w(1-g/rho)  dF/dg")
    for g in (0.0, 0.1, 0.25, 0.49, 0.51, 1.0):
        gap = np.full(n, g)
        grad = np.zeros(n)
        f.computeGradF(gap, grad)
        print(f"{g:5.2f}  {f.computeF(gap, np.zeros(n)) / n: .4f}  "
              f"{(-2.0 * (1 - g / 0.5) if g < 0.5 else 0.0): .4f}  {grad[0]:.4f}")


def westergaard_check(ns, tol, max_iter, log):
    """Non-adhesive mapping check: P* against gbar* = 1 - P* + P* ln P*."""
    gbars = [0.9, 0.5, 0.2, 0.05]
    p_star = math.pi * E_STAR * DELTA / L
    log("# Westergaard (no adhesion): |gbar*_BEM - (1 - P* + P* ln P*)| at the BEM P*")
    log("# N  max_abs_gbar_err  (at gbar* = %s)" % ", ".join(str(g) for g in gbars))
    rows = []
    for n in ns:
        model, solver, keep = make_solver(n, tol, max_iter)
        errs = []
        for gb in gbars:
            p, _, _, _ = solve_at(model, solver, keep[0], gb, p_star, max_iter=max_iter)
            errs.append(abs(gb - (1.0 - p + p * math.log(p))))
        rows.append((n, max(errs)))
        log("%6d  %.3e" % (n, max(errs)))
    return rows


def md_case(alpha, mu, ns, gstep, gmin, tol, max_iter, log, points, exclude, rtol,
            substeps):
    p_star, w, sigma0_star, rho = md_constants(alpha, mu)
    path = wa.trace_branch("md", alpha, mu)
    # grid: from one step beyond the last interaction to gmin
    gtop = max(path.gbar[np.isfinite(path.gbar)])
    law_probe = wa.gap_law("md", alpha, mu, np.linspace(0.0, 3.0, 3001))
    inter = law_probe.gbar[(law_probe.P_retract != 0.0) | (law_probe.P_approach != 0.0)]
    gmax = math.ceil((max(gtop, inter.max()) + gstep) / gstep) * gstep
    count = int(round((gmax - gmin) / gstep)) + 1
    grid = np.round(gmax - gstep * np.arange(count), 10)
    law = wa.gap_law("md", alpha, mu, grid)
    lib = {}
    for stage, plib in (("approach", law.P_approach), ("retract", law.P_retract)):
        lib[stage] = [library_state(path, sigma0_star, g, p) for g, p in zip(grid, plib)]
    log(f"# case alpha = {alpha} mu = {mu}: Sigma0 = {sigma0_star:.6f}, rho/Delta = "
        f"{rho / DELTA:.6f}, W* = {law.W_star:.6e}; gbar* grid {gmax:g} .. {gmin:g} "
        f"step {gstep:g} ({count} points)")
    cons = max(x[2] for st in lib.values() for x in st if np.isfinite(x[2]))
    log(f"#   library state consistency max |P*(state) - P*(gap_law)| = {cons:.1e}")
    events = library_events(alpha, mu, gmax)
    near = {st: np.array([any(abs(gb - e) < exclude for e in events[st]) for gb in grid])
            for st in events}
    # the average of approach and retraction is compared where the library has one state
    # (outside its hysteresis loops) and away from events
    loop = np.abs(law.P_approach - law.P_retract) > 1e-12
    near["average"] = near["approach"] | near["retract"] | loop
    for st in ("approach", "retract"):
        log(f"#   library {st} events at gbar* = "
            + ", ".join(f"{e:.6f}" for e in events[st])
            + f"; grid points within {exclude:g} of them (compared apart): "
            + ", ".join(f"{gb:g}" for gb in grid[near[st]]))
    summary = []
    for n in ns:
        model, solver, keep = make_solver(n, tol, max_iter, {"rho": rho, "surface_energy": w})
        res = {}
        cpu_total = 0.0
        worst_err = 0.0
        for stage, seq in (("approach", range(count)), ("retract", range(count - 1, -1, -1))):
            res[stage] = [None] * count
            attached = False
            prev = None
            for k in seq:
                if not attached and grid[k] >= 1.0 + rho / DELTA:
                    # the rigid wave's smallest gap (gbar - Delta) is >= rho and nothing
                    # pulls: the solution is u = const, P* = 0 (tamaas's error measure is
                    # undefined there: it would iterate to max_iter)
                    res[stage][k] = (0.0, 0.0, 0.0, 0.0, 0.0)
                    prev = grid[k]
                    continue
                # sub-steps from the previous grid point: a large step lets the
                # non-convex solve land in the basin of another stable state
                cpu = 0.0
                start = grid[k] if prev is None else prev
                for j in range(1, substeps + 1):
                    gb = start + (grid[k] - start) * j / substeps
                    p, gap, err, c1 = solve_at(model, solver, keep[0], gb, p_star,
                                               sigma0_star * p_star, rho, rtol,
                                               200, max_iter)
                    cpu += c1
                    if prev is None:
                        break
                prev = grid[k]
                a, c = zone_widths(gap, rho)
                attached = gap.min() < rho
                res[stage][k] = (p, a, c, err, cpu)
                cpu_total += cpu
                if attached:
                    worst_err = max(worst_err, err)
        # differences
        d = {}
        for stage in ("approach", "retract"):
            pl = law.P_approach if stage == "approach" else law.P_retract
            dp = np.array([res[stage][k][0] - pl[k] for k in range(count)])
            da = np.array([res[stage][k][1] - lib[stage][k][0] for k in range(count)])
            dc = np.array([res[stage][k][2] - lib[stage][k][1] for k in range(count)])
            d[stage] = (dp, da, dc)
            for k in range(count):
                points.append(
                    f"{alpha:g} {mu:g} {n:6d} {stage:8s} {grid[k]:6.3f} "
                    f"{res[stage][k][0]: .8f} {pl[k]: .8f} {res[stage][k][1]:.6f} "
                    f"{lib[stage][k][0]:.6f} {res[stage][k][2]:.6f} {lib[stage][k][1]:.6f} "
                    f"{res[stage][k][3]:.1e} {int(near[stage][k])} {res[stage][k][4]:.2f}")
        d["average"] = tuple(0.5 * (d["approach"][j] + d["retract"][j]) for j in range(3))
        row = {"n": n, "cpu": cpu_total, "err": worst_err}
        for stage in ("approach", "retract", "average"):
            dp, da, dc = (np.where(near[stage], np.nan, v) for v in d[stage])
            kp = int(np.nanargmax(np.abs(dp)))
            dpn = np.abs(d[stage][0][near[stage]])
            row[stage] = (np.nanmax(np.abs(dp)), grid[kp], np.nanmax(np.abs(da)),
                          np.nanmax(np.abs(dc)), np.sqrt(np.nanmean(dp**2)),
                          dpn.max() if dpn.size else math.nan)
        summary.append(row)
        log(f"  N = {n:6d}: CPU {cpu_total:7.1f} s, worst residual {worst_err:.1e}; "
            + "; ".join(f"{s} max|dP*| {row[s][0]:.2e} (gbar* {row[s][1]:.2f}) "
                        f"max|da*| {row[s][2]:.1e} max|dc*| {row[s][3]:.1e} "
                        f"[near events max|dP*| {row[s][5]:.2e}]"
                        for s in ("approach", "retract", "average")))
    return summary


def run_case(task):
    """One (alpha, mu) case (a worker process when --jobs > 1): its log lines, point
    rows and summary."""
    alpha, mu, ns, args = task
    tm.set_log_level(tm.LogLevel.error)
    lines, points = [], []

    def log(line):
        print(line, flush=True)
        lines.append(line)

    t0 = time.process_time()
    summary = md_case(alpha, mu, ns, args.gstep, args.gmin, args.tol, args.max_iter, log,
                      points, args.exclude, args.rtol, args.substeps)
    log(f"#   case CPU {time.process_time() - t0:.1f} s")
    return lines, points, summary


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--cases", default="0.3:1,0.3:5,0.6:1:8192",
                    help="alpha:mu[:largest N] of each case")
    ap.add_argument("--jobs", type=int, default=1, help="cases run in parallel")
    ap.add_argument("--N", default="1024,2048,4096,8192,16384")
    ap.add_argument("--gstep", type=float, default=0.05)
    ap.add_argument("--gmin", type=float, default=0.05)
    ap.add_argument("--substeps", type=int, default=5,
                    help="solves per grid step (warm-started continuation)")
    ap.add_argument("--tol", type=float, default=1e-10,
                    help="tamaas PolonskyKeerRey tolerance")
    ap.add_argument("--rtol", type=float, default=1e-8,
                    help="equilibrium residual (units p*) at which a solve stops")
    ap.add_argument("--max-iter", type=int, default=20000)
    ap.add_argument("--exclude", type=float, default=0.05,
                    help="compare apart grid points this close to a library event")
    ap.add_argument("--out", default="study/results/bem_md.txt")
    ap.add_argument("--westergaard-only", action="store_true")
    ap.add_argument("--functional-check", action="store_true",
                    help="print the Maugis functional on uniform gaps and stop")
    args = ap.parse_args(argv)
    tm.set_log_level(tm.LogLevel.error)
    if args.functional_check:
        functional_check()
        return
    ns = [int(v) for v in args.N.split(",")]
    cases = []
    for c in args.cases.split(","):
        f = c.split(":")
        cases.append((float(f[0]), float(f[1]), int(f[2]) if len(f) > 2 else max(ns)))
    lines = []

    def log(s):
        print(s, flush=True)
        lines.append(s)

    t0 = time.process_time()
    log(f"# tamaas {tm.__version__}, wavyadhesion {getattr(wa, '__version__', '?')}, "
        f"numpy {np.__version__}, Python {sys.version.split()[0]}")
    log(f"# command: python study/bem/tamaas_md.py {' '.join(argv or sys.argv[1:])}")
    log(f"# PolonskyKeerRey(gap, gap) tolerance {args.tol:g}, chunks of 200, 400, 800, ... iterations "
        f"until the equilibrium residual <= {args.rtol:g} p* or {args.max_iter} iterations, "
        f"{args.substeps} solves per gbar* step; "
        f"OMP_NUM_THREADS={os.environ.get('OMP_NUM_THREADS', 'unset')}")
    westergaard_check(ns, args.tol, args.max_iter, log)
    points = ["# alpha mu N stage gbar P_bem P_lib a_bem a_lib c_bem c_lib residual near_event cpu_s"]
    summaries = {}
    if not args.westergaard_only:
        tasks = [(alpha, mu, [n for n in ns if n <= nmax], args) for alpha, mu, nmax in cases]
        if args.jobs > 1:
            with multiprocessing.get_context("fork").Pool(args.jobs) as pool:
                results = pool.map(run_case, tasks, chunksize=1)
        else:
            results = [run_case(t) for t in tasks]
        for (alpha, mu, _, _), (case_lines, case_points, summary) in zip(tasks, results):
            for line in case_lines:
                log(line)
            points.extend(case_points)
            summaries[(alpha, mu)] = summary
        log("")
        log("# summary: max over the gbar* grid of |BEM - library| (P*, a*, c*), per branch "
            "and for the average of approach and retraction; rate = log2(max|dP*|(N/2) / "
            "max|dP*|(N))")
        log("# alpha mu N | approach dP da dc | retract dP da dc | average dP da dc rmsP "
            "rate | near-event average dP | CPU_s")
        for (alpha, mu), rows in summaries.items():
            prev = None
            for row in rows:
                rate = (math.log2(prev / row["average"][0])
                        if prev and row["average"][0] > 0 else math.nan)
                prev = row["average"][0]
                ap_, re_, av_ = row["approach"], row["retract"], row["average"]
                log(f"{alpha:g} {mu:g} {row['n']:6d} | {ap_[0]:.2e} {ap_[2]:.1e} {ap_[3]:.1e}"
                    f" | {re_[0]:.2e} {re_[2]:.1e} {re_[3]:.1e} | {av_[0]:.2e} {av_[2]:.1e}"
                    f" {av_[3]:.1e} {av_[4]:.1e} {rate:5.2f} | {av_[5]:.2e} | {row['cpu']:6.1f}")
    log(f"# CPU of the main process {time.process_time() - t0:.1f} s (each case's own "
        f"CPU is in its header)")
    if args.out:
        with open(args.out, "w") as f:
            f.write("\n".join(lines) + "\n")
        base, ext = os.path.splitext(args.out)
        with open(base + "_points" + ext, "w") as f:
            f.write("\n".join(points) + "\n")


if __name__ == "__main__":
    main()
