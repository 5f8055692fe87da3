#!/usr/bin/env python3
"""Independent check of the smooth-adhesion (Lennard-Jones) W* (doc/accuracy-performance.md,
section 12). Not run in CI; asserts nothing.

The library computes W* = -oint P* dgbar* of the gap-controlled cycle as the sum over its
jumps of Pi(start) - Pi(end), Pi = (1/2) mean(u K u) + mean phi(h) the energy per period at
fixed mean gap (src/wa_bem_path.f90, gap_energy in src/wa_bem_solver.f90). This script
recomputes Pi of every jump's two states from their gap fields on the whole period with
numpy alone: the elastic energy from the DFT of u = h - f (mode k stiffness |k|, the
Nyquist mode N/2: doc/theory.md), the interaction energy from phi integrated by mpmath
(not the closed form), and the equilibrium residual K u + sigma(h) + P* of each state.

Run from the repository root (fpm on PATH, e.g. .venv/bin after tools/setup.sh):

    .venv/bin/python study/bem/check_wstar.py 0.3 3 512 1024

It builds and runs the study program wavyadhesion-lj-wstar (cd study) once per N.
"""
import os
import subprocess
import sys
import tempfile

import mpmath
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def run(alpha, mu, n, out):
    text = subprocess.run(["fpm", "run", "--profile", "release", "wavyadhesion-lj-wstar", "--",
                           alpha, mu, str(n), "1", out], cwd=os.path.join(ROOT, "study"),
                          check=True, capture_output=True, text=True).stdout
    line = [l for l in text.splitlines() if l.startswith("N ")][-1].split()
    return float(line[line.index("W_star") + 1])


def read(path):
    with open(path) as f:
        head = f.readline().split()
        dgamma, eps, n = float(head[1]), float(head[2]), int(head[3])
        jumps = []
        while True:
            line = f.readline()
            if not line:
                break
            _, gbar, p0, p1 = line.split()
            fields = np.array([[float(v) for v in f.readline().split()] for _ in range(n)])
            jumps.append((float(gbar), float(p0), float(p1), fields[:, 0], fields[:, 1]))
    return dgamma, eps, n, jumps


def main():
    alpha, mu = sys.argv[1], sys.argv[2]
    for n_arg in sys.argv[3:]:
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "states.txt")
            w_lib = run(alpha, mu, int(n_arg), out)
            dgamma, eps, n, jumps = read(out)
        x = np.arange(n)/n
        f = 1.0 - np.cos(2*np.pi*x)
        k = np.abs(np.fft.fftfreq(n, 1.0/n))        # |k|, the Nyquist mode N/2
        mpmath.mp.dps = 30
        c = 8*mpmath.mpf(dgamma)/(3*eps)

        def phi(h):                                  # -int_h^inf sigma, by quadrature
            return -float(mpmath.quad(lambda t: c*((eps/t)**3 - (eps/t)**9), [h, mpmath.inf]))

        def energy(h, p):
            u = h - f
            uh = np.fft.fft(u)
            elastic = 0.5*np.sum(k*np.abs(uh)**2)/n**2
            ku = np.real(np.fft.ifft(k*uh))
            sigma = 8*dgamma/(3*eps)*((eps/h)**3 - (eps/h)**9)
            resid = np.max(np.abs(ku + sigma + p))
            return elastic + np.mean([phi(v) for v in h]), resid

        w = 0.0
        for gbar, p0, p1, h0, h1 in jumps:
            e0, r0 = energy(h0, p0)
            e1, r1 = energy(h1, p1)
            w += e0 - e1
            print(f"  jump at gbar* {gbar:.10f}: Pi {e0:.15e} -> {e1:.15e}, mean gaps "
                  f"{np.mean(h0):.12f} {np.mean(h1):.12f}, residuals {r0:.1e} {r1:.1e}")
        print(f"alpha {alpha} mu {mu} N {n}: jumps {len(jumps)}  W* library {w_lib:.13e}  "
              f"numpy {w:.13e}  difference {w_lib - w:.1e}")


if __name__ == "__main__":
    main()
