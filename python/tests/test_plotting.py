"""The optional matplotlib helpers draw without error (skipped without matplotlib)."""

import numpy as np
import pytest

matplotlib = pytest.importorskip("matplotlib")
matplotlib.use("Agg")

from wavyadhesion import plotting  # noqa: E402


def test_mechanism_runs():
    assert plotting.mechanism_runs(np.array([0, 0, 1, 1, 1, 2])) == [
        (0, 3, 0), (2, 6, 1), (5, 6, 2)]
    assert plotting.mechanism_runs(np.array([3])) == [(0, 1, 3)]


def test_figures_draw():
    import matplotlib.pyplot as plt
    fig = plotting.figure4(alphas=(0.3,), mus=(1.0,))
    assert len(fig.axes) == 1 and len(fig.axes[0].lines) >= 4
    fig6 = plotting.figure6(alpha=0.3, mus=(1.0, 5.0))
    assert sum(ax.get_visible() for ax in fig6.axes) == 2
    fig9, fig10 = plotting.figures9_10(alphas=(0.3,), mu=np.logspace(-1, 1, 8))
    assert fig9.axes[0].get_xscale() == "log"
    for f in (fig, fig6, fig9, fig10):
        plt.close(f)
