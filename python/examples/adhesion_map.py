"""The adhesion maps of DW and MD (issue 13): the boundaries between the mechanisms by
which full contact is reached and contact is lost, over alpha in [0.01, 10] and mu in
[1e-3, 1e3] (log axes), with the regions where Westergaard predicts both critical
forces within 1 %, the edge of where JKR's P_fc is within 1 %, and contours of -P_pf.

    python python/examples/adhesion_map.py [--out doc/figures]

Needs the installed package (pip install ./python) and matplotlib.
"""

import time
from concurrent.futures import ThreadPoolExecutor

from _common import output_dir, save

import wavyadhesion as wa
from wavyadhesion import plotting

if __name__ == "__main__":
    out = output_dir(__doc__)
    for model in ("dw", "md"):
        t0 = time.perf_counter()
        with ThreadPoolExecutor(2) as pool:       # the force grid on two threads
            # DW: the gap-control boundary (401, red) too; MD's gap boundaries cost
            # 5-10x its load-control map (see doc/user-guide.md): not drawn here
            amap = wa.adhesion_map(model, (0.01, 10.0, 60), (1e-3, 1e3, 60), forces=True,
                                   scan_every=8, executor=pool, alpha_tol=1e-5,
                                   control="both" if model == "dw" else "load")
        t1 = time.perf_counter()
        fig = plotting.adhesion_map(amap)
        save(fig, out / f"adhesion_map_{model}.png")
        print(f"{model}: map with forces {t1 - t0:.1f} s ({amap.n_paths} load paths for the "
              f"boundaries, {len(amap.boundaries)} curves), drawing "
              f"{time.perf_counter() - t1:.1f} s")
