"""Paper Figs. 9 and 10: the load P_fc* at which full contact is reached and the
pull-off load P_pf* against mu (200 values, log-spaced from 0.01 to 10) for alpha = 0.3,
0.6, 1 (double-Westergaard; line style by mechanism: dash-dot gradual, solid jump from
c* < 1/2, dashed jump from c* = 1/2, dotted snap at P* = 0).

    python python/examples/fig9_10_critical_forces.py [--out DIR]   # default: the current directory

Needs the installed package (pip install ./python) and matplotlib.
"""

import time

import numpy as np
from _common import output_dir, save

from wavyadhesion import plotting

if __name__ == "__main__":
    out = output_dir(__doc__)
    t0 = time.perf_counter()
    fig9, fig10 = plotting.figures9_10(alphas=(0.3, 0.6, 1.0), mu=np.logspace(-2, 1, 200))
    print(f"critical forces for 3 alpha x 200 mu and drawing: "
          f"{time.perf_counter() - t0:.2f} s")
    save(fig9, out / "fig9_full_contact_force.png")
    save(fig10, out / "fig10_pull_off_force.png")
