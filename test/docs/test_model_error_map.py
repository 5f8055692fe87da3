"""The saved model-error map, doc/figures/model_error_map.csv (made by
tools/figures/plot_model_error.py, the command in doc/user-guide.md, "Model-error map"):
its grid and statuses are what the user guide says (no cell extrapolated: an unresolved or
failed cell has no value and a message), and a few cheap cells recomputed now equal the
saved ones. The numbers the guide quotes from it are checked in test_docs.py (CLAIMS);
nothing here recomputes the map.
"""
import csv
import math
import pathlib

import numpy as np
import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
TABLE = REPO / "doc" / "figures" / "model_error_map.csv"
QUANTITIES = ("P_fc", "P_pf", "W_star")
MODELS = ("dw", "md")
# The grid and cap of the saved run (doc/user-guide.md)
ALPHA = np.logspace(-2, 1, 16)
MU = np.logspace(-2, 2, 21)
N_MAX = 4096


def rows():
    with open(TABLE, newline="") as fh:
        return list(csv.DictReader(fh))


def test_grid_is_the_issue_range():
    cells = rows()
    assert len(cells) == ALPHA.size * MU.size
    np.testing.assert_allclose(sorted({float(c["alpha"]) for c in cells}), ALPHA, rtol=1e-12)
    np.testing.assert_allclose(sorted({float(c["mu"]) for c in cells}), MU, rtol=1e-12)


def test_no_cell_is_extrapolated():
    for c in rows():
        st = c["lj_status"]
        assert st in ("ok", "unresolved", "failed")
        values = [float(c[f"{m}_rel_{q}"]) for m in MODELS for q in QUANTITIES]
        if st == "ok":
            assert 0 < int(c["lj_N"]) <= N_MAX and not any(math.isnan(v) for v in values)
            continue
        assert all(math.isnan(v) for v in values) and math.isnan(float(c["lj_P_pf"]))
        if st == "unresolved":
            assert "needs N = " in c["message"] and f"cap of {N_MAX}" in c["message"]
        else:
            assert c["message"]


@pytest.mark.parametrize("alpha_index, mu_index", [(0, 0), (10, 4), (15, 0)])
def test_recomputed_cells_equal_the_table(alpha_index, mu_index):
    """Three cheap cells (N = 128: small alpha and mu, the middle, the large-alpha
    small-mu corner) recomputed by model_error_map equal the saved row."""
    import wavyadhesion as wa

    a, u = ALPHA[alpha_index], MU[mu_index]
    saved = next(c for c in rows() if np.isclose(float(c["alpha"]), a, rtol=1e-12)
                 and np.isclose(float(c["mu"]), u, rtol=1e-12))
    m = wa.model_error_map([float(saved["alpha"])], [float(saved["mu"])], n_max=N_MAX)
    assert m.lj_status[0, 0] == saved["lj_status"] == "ok"
    assert m.lj_N[0, 0] == int(saved["lj_N"])
    for q, col in (("P_fc", "lj_P_fc_peak"), ("P_pf", "lj_P_pf"), ("W_star", "lj_W_star")):
        assert m.lj[q][0, 0] == pytest.approx(float(saved[col]), rel=1e-9, abs=1e-14)
    for model in MODELS:
        for q in QUANTITIES:
            want = float(saved[f"{model}_rel_{q}"])
            got = m.rel_error[model, q][0, 0]
            assert got == want or got == pytest.approx(want, rel=1e-6), (model, q)
