#!/usr/bin/env python3
"""Cross-check of the smooth-adhesion (Lennard-Jones) solver against ContactMechanics +
Adhesion (PyPI), and the side-by-side cost per converged stable state.

Issue 22, "Validation" and "Speed" (doc/accuracy-performance.md, section 13). Not run in
CI: the peer codes are installed for this study only.

Environment (a separate virtual environment; Python 3.11):

    python3 -m venv /tmp/cmvenv
    /tmp/cmvenv/bin/pip install -r study/bem/requirements-contactmechanics.txt

Run from the repository root (builds and runs the study program
wavyadhesion-lj-states with fpm, which must be on PATH, e.g. .venv/bin after
tools/setup.sh):

    OMP_NUM_THREADS=1 /tmp/cmvenv/bin/python study/bem/crosscheck_contactmechanics.py \
        --out study/results/crosscheck_contactmechanics.txt

Options: --runs 0.3:1:256,0.3:3:256,0.3:1:1024,0.3:3:1024,0.3:3:4096 (alpha:mu:N)
--states 10 (gap-stable states per run) --tol 1e-8 (CM's residual tolerance in p*).

Mapping of the library's model onto ContactMechanics/Adhesion (read from their sources)
---------------------------------------------------------------------------------------
Units: L = 1, Delta = 1, E* = 1/pi, so that p* = pi E* Delta / L = 1 and every length,
traction and energy of CM is directly the library's (x/L, h/Delta, P/p*, energy per area
over p* Delta).

* Substrate: PeriodicFFTElasticHalfSpace((N,), young=1/pi, physical_sizes=(1,)) is the
  plane-strain periodic half-plane: its surface stiffness of mode m is pi E* m / L (1D
  branch of _compute_greens_function: E*/2 |q| with q = 2 pi m / L), i.e. the library's
  u_m = p_m / m (doc/theory.md, "Smooth adhesion"); `young` is the contact modulus E*
  (poisson 0), no factor 2. Its nodes x = j L/N are the library's; the Nyquist mode has
  stiffness N/2 in both.
* Mean mode: CM's periodic half-space gives the mode m = 0 the stiffness stiffness_q0
  (default: that of m = 1), so at a fixed `offset` the mean displacement is P*/stiffness_q0
  and the mean gap is not fixed exactly. We set stiffness_q0 = S = N/2 (the largest
  stiffness of the other modes: the condition number is unchanged) and choose
      offset = P*/S + mean(f) - gbar*,
  for which the library's state (gbar*, P*) is an equilibrium of CM's system; a CM state at
  that offset has mean gap gbar* + (P*_CM - P*)/S (reported: `dg`). CM's system is then
  under the control of a stiff spring (compliance 2/N in Delta/p*), which is gap control
  for every state whose slope dP*/dgbar* along the curve is below N/2.
* Profile: CM's gap is disp - (heights + offset) (ContactMechanics.Systems.compute_gap);
  with heights = -f, f = 1 - cos 2 pi x (the library's rigid-equivalent profile, crest at
  x = 0), gap = disp + f - offset, and disp > 0 where the pressure is compressive, as the
  library's u (CM: force = -dE/d disp, K u = -sigma).
* Law: Adhesion's Lj82(w, z0) = VDW82(w z0^8/3, 16 pi w z0^2), the potential
  V(h) = w (-(4/3)(z0/h)^2 + (1/3)(z0/h)^8), minimum -w at h = z0, and
  dV/dh = (8 w/(3 z0)) ((z0/h)^3 - (z0/h)^9): the library's 3-9 law exactly (tension
  positive, zero at h = eps) with w = dgamma = pi alpha^2/2 (units p* Delta) and
  z0 = eps = (4 alpha^4)^(1/3)/mu (units Delta). CM's mean load P*_CM is -mean(dV/dh(gap))
  (compressive positive), the library's convention. The check on a far-apart state
  (traction = the law at the rigid gap) is printed first.
* Tolerance: CM (minimize_proxy, scipy L-BFGS-B on the N nodal displacements) stops when
  the largest gradient component is below gtol; a component is (K u + sigma)_j L/N, so
  gtol = tol/N makes `tol` a residual of the force balance in units of p*. With ftol = 0
  it also stops where the energy no longer decreases in floating point (its floor,
  reported as `r_CM`, the largest |K u + sigma + P| it reached). The library's Newton
  stops on a relative correction of 1e-12 (wa_bem_solver); `r_ours` is CM's own residual
  at the library's state, the same quantity.

What is compared, per gap-stable state picked along the library's trace
-----------------------------------------------------------------------
CM from two starts at the state's offset: `cold`, the undeformed wave just out of contact
(gap f - mean f + max(gbar*, 1 + eps): no knowledge of the state; zero displacement would
put negative gaps into the 8-2 potential, even in h, whose mirror well at h = -eps then
attracts it), and `warm`, the library's neighbouring state on the trace (the state a sweep
would come from). Where two stable states coexist at a mean gap the cold start lands on
one of them, not necessarily the state asked for, and L-BFGS-B may stall (the energy no
longer decreasing in floating point, which scipy reports as success): a CM run counts as
converged where its residual is within 1e3 tol (`ok`), and a cold start as reaching the
state where it converged with max |h_CM - h| < 0.01 eps (`cold: dh/eps`, inf where it did
not converge). The agreement table uses the warm start.
Agreement: |P*_CM - P*| (absolute, and over |P*|), max |h_CM - h|/eps over the nodes.

Speed: per converged stable state, at the same N, processor time of one core
(OMP_NUM_THREADS=1; a loaded machine inflates wall times).
Ours: (a) along the trace, the cycle (trace + both paths) over its number of states;
(b) one state alone at its mean gap from its neighbour on the trace (problem set-up, FFT
plans, factorisation and Newton included). CM: the same state from the cold start and from
the warm start (the mean over the runs that converged, and for the cold start reached the
library's state). `ours cold`: how many states the library's Newton reaches alone from
the rigid gap (it has no globalisation: a cold state costs the trace that reaches it).
"""
import argparse
import math
import os
import subprocess
import sys
import time

os.environ.setdefault("OMP_NUM_THREADS", "1")

import numpy as np  # noqa: E402

from Adhesion.Interactions import Lj82  # noqa: E402
from Adhesion.System import SmoothContactSystem  # noqa: E402
from ContactMechanics import PeriodicFFTElasticHalfSpace  # noqa: E402
from SurfaceTopography import UniformLineScan  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SAME_STATE = 1e-2   # max |h_CM - h|/eps below which a CM state is the library's
CONVERGED = 1e3     # a CM residual above CONVERGED tol: not converged (stalled)


def lj_states(alpha, mu, n, m, path):
    """Run the study program; return (header dict, list of state dicts)."""
    subprocess.run(["fpm", "run", "--profile", "release", "wavyadhesion-lj-states", "--",
                    repr(alpha), repr(mu), str(n), str(m), path],
                   cwd=os.path.join(ROOT, "study"), check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    lines = open(path).read().splitlines()
    h = lines[1].split()
    head = dict(alpha=float(h[0]), mu=float(h[1]), N=int(h[2]), points=int(h[3]),
                points_cycle=int(h[4]), trace_cpu=float(h[6]), cycle_cpu=float(h[8]),
                eps=float(h[9]))
    states = []
    for k in range(int(lines[3])):
        v = lines[4 + 3 * k].split()
        states.append(dict(index=int(v[0]), P=float(v[1]), gbar=float(v[2]),
                           a=float(v[3]), stable_load=v[5] == "T",
                           cold=[float(s) for s in v[7:11]],
                           warm=[float(s) for s in v[11:15]],
                           h=np.array(lines[5 + 3 * k].split(), float),
                           h_nb=np.array(lines[6 + 3 * k].split(), float)))
    return head, states


class Peer:
    """CM's system for (alpha, mu) at N points per period, in the library's units."""

    def __init__(self, alpha, mu, n):
        self.n = n
        self.dgamma = math.pi * alpha**2 / 2
        self.eps = (4 * alpha**4) ** (1 / 3) / mu
        self.f = 1 - np.cos(2 * np.pi * np.arange(n) / n)
        self.stiff0 = n / 2
        sub = PeriodicFFTElasticHalfSpace((n,), young=1 / math.pi, physical_sizes=(1.0,),
                                          stiffness_q0=self.stiff0)
        surf = UniformLineScan(-self.f, physical_sizes=1.0, periodic=True)
        self.system = SmoothContactSystem(sub, Lj82(self.dgamma, self.eps), surf)

    def law(self, h):
        s3 = (self.eps / h) ** 3
        return 8 * self.dgamma / (3 * self.eps) * (s3 - s3**3)

    def offset(self, p, gbar):
        return p / self.stiff0 + self.f.mean() - gbar

    def residual(self, gap, offset):
        """CM's largest force-balance residual at this gap field, in p*."""
        _, grad = self.system.objective(offset, gradient=True)(gap - self.f + offset)
        return float(np.abs(grad).max() * self.n)

    def solve(self, offset, gap0, tol):
        """CM from the gap field gap0: (gap, P*, residual, iterations, processor seconds,
        converged: the residual within CONVERGED tol; scipy's success flag is also true
        where L-BFGS-B stalls, the energy no longer decreasing, far from equilibrium)."""
        t = time.process_time()
        res = self.system.minimize_proxy(offset=offset,
                                         initial_displacements=gap0 - self.f + offset,
                                         options=dict(gtol=tol / self.n, ftol=0.0,
                                                      maxiter=200000, maxcor=10))
        t = time.process_time() - t
        gap = self.system.gap.copy()
        r = float(np.abs(res.jac).max() * self.n)
        return gap, float(-self.law(gap).mean()), r, int(res.nit), t, r <= CONVERGED * tol


def far_check(out):
    """The mapping on a trivial state: far apart, zero displacement, CM's traction and
    energy against the law at the rigid gap."""
    peer = Peer(0.3, 3.0, 256)
    gbar = 3.0
    offset = peer.f.mean() - gbar
    system = peer.system
    system.evaluate(np.zeros(peer.n), offset, forces=True)
    h = peer.f - peer.f.mean() + gbar
    trac = -system.interaction_force * peer.n          # force per node -> dV/dh
    phi = peer.dgamma * (-(4 / 3) * (peer.eps / h) ** 2 + (1 / 3) * (peer.eps / h) ** 8)
    out(f"far-apart check (alpha 0.3, mu 3, N 256, gbar* {gbar}, zero displacement): "
        f"max |CM traction - law(h)| = {np.abs(trac - peer.law(h)).max():.1e} "
        f"(law up to {np.abs(peer.law(h)).max():.2e}), "
        f"|CM energy - mean phi(h)| = {abs(system.energy - phi.mean()):.1e}, "
        f"CM mean gap - gbar* = {system.compute_mean_gap() - gbar:.1e}")


def run(alpha, mu, n, m, tol, tmp, out):
    head, states = lj_states(alpha, mu, n, m, tmp)
    peer = Peer(alpha, mu, n)
    eps = peer.eps
    out(f"\n## alpha {alpha}, mu {mu}, N {n}: eps/Delta {eps:.6g}, trace {head['points']} "
        f"states in {head['trace_cpu']:.3f} s, cycle {head['points_cycle']} states in "
        f"{head['cycle_cpu']:.3f} s")
    out(f"{'idx':>4} {'gbar*':>9} {'P*':>10} {'a*':>6} {'Ls':>2} {'r_ours':>8} "
        f"{'cold: dh/eps':>12} {'r_CM':>8} {'t[s]':>7} {'nit':>5} "
        f"{'warm: dP*':>10} {'dP/|P|':>8} {'dh/eps':>8} {'dg':>8} {'r_CM':>8} {'t[s]':>7} "
        f"{'nit':>5} {'ok':>2} {'ours warm[s]':>12}")
    rows = []
    for s in states:
        off = peer.offset(s["P"], s["gbar"])
        r_ours = peer.residual(s["h"], off)
        h0 = peer.f - peer.f.mean() + max(s["gbar"], 1.0 + eps)
        gc, pc, rc, nc, tc, okc = peer.solve(off, h0, tol)
        dh_cold = float(np.abs(gc - s["h"]).max() / eps)
        gw, pw, rw, nw, tw, okw = peer.solve(off, s["h_nb"], tol)
        dp = pw - s["P"]
        dh_cold = dh_cold if okc else math.inf
        row = dict(s, r_ours=r_ours, dh_cold=dh_cold, t_cold=tc, p_cold=pc, r_cold=rc,
                   dp=dp, dp_rel=abs(dp) / abs(s["P"]),
                   dh=float(np.abs(gw - s["h"]).max() / eps), dg=float(gw.mean() - s["gbar"]),
                   r_cm=rw, t_warm=tw, ok_warm=okw, ours_warm=s["warm"][2] if s["warm"][0] == 0 else math.nan)
        rows.append(row)
        out(f"{s['index']:4d} {s['gbar']:9.5f} {s['P']:+10.5f} {s['a']:6.4f} "
            f"{'y' if s['stable_load'] else 'n':>2} "
            f"{r_ours:8.1e} {dh_cold:12.2e} {rc:8.1e} {tc:7.3f} {nc:5d} {dp:+10.2e} {row['dp_rel']:8.1e} "
            f"{row['dh']:8.1e} {row['dg']:+8.1e} {rw:8.1e} {tw:7.3f} {nw:5d} {'ny'[okw]:>2} "
            f"{row['ours_warm']:12.5f}")
    return head, rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--runs", default="0.3:1:256,0.3:3:256,0.3:1:1024,0.3:3:1024,0.3:3:4096")
    ap.add_argument("--states", type=int, default=10)
    ap.add_argument("--tol", type=float, default=1e-8)
    ap.add_argument("--out", default="study/results/crosscheck_contactmechanics.txt")
    args = ap.parse_args()
    lines = []

    def out(text):
        print(text, flush=True)
        lines.append(text)

    import Adhesion
    import ContactMechanics
    import muGrid
    import scipy
    out("# LJ solver against ContactMechanics + Adhesion (study/bem/crosscheck_contactmechanics.py)")
    out(f"# ContactMechanics {ContactMechanics.__version__}, Adhesion {Adhesion.__version__}, "
        f"muGrid {muGrid.__version__}, numpy {np.__version__}, scipy {scipy.__version__}; "
        f"CM tolerance tol = {args.tol:g} p* (gtol = tol/N, ftol = 0); processor times, one core "
        f"(OMP_NUM_THREADS={os.environ['OMP_NUM_THREADS']})")
    out("# columns: Ls load-stable; r_ours CM's residual at our state [p*]; cold/warm: CM "
        "from the undeformed wave just out of contact / from our neighbouring state on the "
        "trace (cold dh/eps: inf where CM did not converge); dP* = P*_CM - P*; "
        "dh = max |h_CM - h|; dg = mean gap CM - gbar*; r_CM CM's final residual [p*]; ok: converged "
        "(r_CM <= 1e3 tol); "
        "ours warm: our solve of the state alone from the same neighbour [s]")
    far_check(out)
    tmp = os.path.join("/tmp", f"wa_lj_states_{os.getpid()}.txt")
    summary = []
    for spec in args.runs.split(","):
        a, mu, n = spec.split(":")
        head, rows = run(float(a), float(mu), int(n), args.states, args.tol, tmp, out)
        summary.append((head, rows))
    os.remove(tmp)

    out("\n## Agreement (warm start; the state asked for)")
    out(f"{'alpha':>5} {'mu':>4} {'N':>5} {'states':>6} {'max|dP*|':>9} {'max dP/|P|':>10} "
        f"{'max dh/eps':>10} {'max r_ours':>10} {'max r_CM':>9} {'CM ok':>6} {'cold same':>9}")
    for head, rows in summary:
        out(f"{head['alpha']:5.2f} {head['mu']:4.1f} {head['N']:5d} {len(rows):6d} "
            f"{max(abs(r['dp']) for r in rows):9.1e} {max(r['dp_rel'] for r in rows):10.1e} "
            f"{max(r['dh'] for r in rows):10.1e} {max(r['r_ours'] for r in rows):10.1e} "
            f"{max(r['r_cm'] for r in rows):9.1e} "
            f"{sum(r['ok_warm'] for r in rows):3d}/{len(rows):<2d} "
            f"{sum(r['dh_cold'] < SAME_STATE for r in rows):4d}/{len(rows):<4d}")

    out("\n## Speed per converged stable state [s, processor time of one core] (ratios CM/ours)")
    out(f"{'alpha':>5} {'mu':>4} {'N':>5} {'ours trace':>10} {'ours alone':>10} "
        f"{'CM cold':>9} {'CM warm':>9} {'cold/trace':>10} {'warm/trace':>10} "
        f"{'warm/alone':>10} {'ours cold':>9}")
    for head, rows in summary:
        ours_trace = head["cycle_cpu"] / head["points_cycle"]
        alone = np.nanmean([r["ours_warm"] for r in rows])
        cold = [r["t_cold"] for r in rows if r["dh_cold"] < SAME_STATE]
        cm_cold = float(np.mean(cold)) if cold else math.nan
        cm_warm = float(np.mean([r["t_warm"] for r in rows if r["ok_warm"]]))
        out(f"{head['alpha']:5.2f} {head['mu']:4.1f} {head['N']:5d} {ours_trace:10.2e} "
            f"{alone:10.2e} {cm_cold:9.2e} {cm_warm:9.2e} {cm_cold / ours_trace:10.1f} "
            f"{cm_warm / ours_trace:10.1f} {cm_warm / alone:10.1f} "
            f"{sum(r['cold'][0] == 0 and r['cold'][3] < SAME_STATE for r in rows):4d}/"
            f"{len(rows):<4d}")
    with open(args.out, "w") as fh:
        fh.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    sys.exit(main())
