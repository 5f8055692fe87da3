"""Paper Fig. 6: contact half-width a* (red) and interaction-zone half-width c* (black)
against the load P* for alpha = 0.3 and mu = 0.1, 1, 2.5, 3, 5 (double-Westergaard;
solid: c* < 1/2, dash-dot: c* = 1/2), with the load-controlled path (blue: jumps
dotted, P_fc and P_pf marked).

    python python/examples/fig6_half_widths.py [--out DIR]   # default: the current directory

Needs the installed package (pip install ./python) and matplotlib.
"""

from _common import output_dir, save

from wavyadhesion import plotting

if __name__ == "__main__":
    out = output_dir(__doc__)
    save(plotting.figure6(alpha=0.3, mus=(0.1, 1.0, 2.5, 3.0, 5.0)),
         out / "fig6_half_widths.png")
