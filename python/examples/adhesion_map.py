"""The adhesion maps of DW and MD (issue 13): the boundaries between the mechanisms by
which full contact is reached and contact is lost, over alpha in [0.01, 10] and mu in
[1e-3, 1e3] (log axes), with the regions where Westergaard predicts both critical
forces within 1 %, the edge of where JKR's P_fc is within 1 %, contours of -P_pf, and
contours of W*/(pi alpha^2/2), the fraction of the work of adhesion lost per
gap-controlled cycle (energy_lost on a 16 x 21 grid, 5 points per decade, mu from 0.1:
below, the fraction stays under 0.01, checked and printed at mu = 0.1).

    python python/examples/adhesion_map.py [--out DIR]   # default: the current directory

Needs the installed package (pip install ./python) and matplotlib.
"""

import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np
from _common import output_dir, save

import wavyadhesion as wa
from wavyadhesion import plotting

#: The W* grid: 5 points per decade of alpha (0.01..10) and mu (0.1..1000).
ENERGY_ALPHA = np.geomspace(0.01, 10.0, 16)
ENERGY_MU = np.geomspace(0.1, 1e3, 21)

if __name__ == "__main__":
    out = output_dir(__doc__)
    for model in ("dw", "md"):
        t0 = time.perf_counter()
        with ThreadPoolExecutor(2) as pool, ThreadPoolExecutor(1) as side:
            # W* and the force grid share the two threads while the boundaries are
            # continued in a thread of their own (the longest part). DW: the
            # gap-control boundary (401, red) too; MD's gap boundaries cost 5-10x its
            # load-control map (see doc/user-guide.md): not drawn here
            energy = side.submit(wa.energy_lost, model, ENERGY_ALPHA[None, :],
                                 ENERGY_MU[:, None], errors="nan", executor=pool)
            amap = wa.adhesion_map(model, (0.01, 10.0, 60), (1e-3, 1e3, 60), forces=True,
                                   scan_every=8, executor=pool, alpha_tol=1e-5,
                                   control="both" if model == "dw" else "load")
            energy = energy.result()
        t1 = time.perf_counter()
        fig = plotting.adhesion_map(amap, energy=energy)
        save(fig, out / f"adhesion_map_{model}.png")
        print(f"{model}: map with forces and W* {t1 - t0:.1f} s ({amap.n_paths} load paths "
              f"for the boundaries, {len(amap.boundaries)} curves), drawing "
              f"{time.perf_counter() - t1:.1f} s")
        failed = np.argwhere(~energy.ok)
        print(f"{model}: W* at {energy.status.size} points, {len(failed)} failed (holes)"
              + "".join(f"\n    alpha = {energy.alpha[i, j]:.4g}, mu = {energy.mu[i, j]:.4g}: "
                        f"{energy.messages[(int(i), int(j))]}" for i, j in failed))
        frac = energy.W_fraction
        i, j = np.unravel_index(np.nanargmax(frac), frac.shape)
        over = frac > 1.0
        print(f"{model}: W*/(pi alpha^2/2) at mu = {ENERGY_MU[-1]:g}: {frac[-1, 0]:.4f} "
              f"(alpha = {ENERGY_ALPHA[0]:g}) to {frac[-1, -1]:.4f} (alpha = "
              f"{ENERGY_ALPHA[-1]:g}); largest at mu = {ENERGY_MU[0]:g}: "
              f"{np.nanmax(frac[0]):.4f}; largest {frac[i, j]:.4f} at alpha = "
              f"{ENERGY_ALPHA[j]:.3g}, mu = {ENERGY_MU[i]:.3g}"
              + (f"; above 1 for alpha {energy.alpha[over].min():.3g}..."
                 f"{energy.alpha[over].max():.3g}, mu {energy.mu[over].min():.3g}..."
                 f"{energy.mu[over].max():.3g}" if over.any() else ""))
