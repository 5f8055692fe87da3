"""Paper Figs. 7 and 8: as Fig. 6 (a* and c* against P*, with the load path) for
alpha = 0.6 (mu = 0.1, 1, 2.5, 3, 5) and alpha = 1 (mu = 1, 3, as the paper's text says;
its Fig. 8 caption contradicts the text, doc/theory.md).

    python python/examples/fig7_fig8_half_widths.py [--out DIR]   # default: the current directory

Needs the installed package (pip install ./python) and matplotlib.
"""

from _common import output_dir, save

from wavyadhesion import plotting

if __name__ == "__main__":
    out = output_dir(__doc__)
    save(plotting.figure6(alpha=0.6, mus=(0.1, 1.0, 2.5, 3.0, 5.0), paper_figure=7),
         out / "fig7_half_widths.png")
    save(plotting.figure6(alpha=1.0, mus=(1.0, 3.0), paper_figure=8),
         out / "fig8_half_widths.png")
