"""Paper Fig. 4: equilibrium P*-a* curves (a* < c* < 1/2) of the double-Westergaard
(solid) and Maugis-Dugdale (dashed) models for several mu, with the Westergaard and JKR
curves, for alpha = 0.3 and 0.6.

    python python/examples/fig4_load_curves.py [--out DIR]   # default: the current directory

Needs the installed package (pip install ./python) and matplotlib.
"""

from _common import output_dir, save

from wavyadhesion import plotting

if __name__ == "__main__":
    out = output_dir(__doc__)
    save(plotting.figure4(alphas=(0.3, 0.6), mus=(0.3, 1.0, 3.0, 10.0)),
         out / "fig4_load_curves.png")
