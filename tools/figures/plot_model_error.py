#!/usr/bin/env python3
"""Draw the model-error map: the relative error of DW's and MD's P_fc, P_pf and W* against
the smooth Lennard-Jones model (LJ), |model - LJ|/|LJ|, on the adhesion map's axes.

    .venv/bin/python tools/figures/plot_model_error.py --outdir doc/figures \\
        --alpha 0.01:10:16 --mu 0.01:100:21 --n-max 4096 --workers 2

Writes model_error_map.png and model_error_map.csv (into --outdir, default the current
directory). The figure: a 2 x 3 grid of panels (rows DW, MD; columns P_fc, P_pf, W*),
each log10 of the relative error per cell over log alpha (x) and log mu (y), with the
1 %, 5 % and 20 % contours; LJ's P_fc is its P_fc_peak (b* = 1/2), the one comparable with
the cohesive models'. Cells are marked: grey with a cross where LJ is unresolved (its zone
needs a grid beyond --n-max: no value, never extrapolated), a red cross where a
computation failed, a small circle where LJ's error estimate is not small against the
model error (``ModelErrorMap.resolved`` false), and "inf" where LJ's value is zero and the
model's is not (W* of an LJ cycle without a jump; P_fc where LJ's b* is 1/2 from the first
contact). The table: one row per cell (the columns are listed in TABLE_COLUMNS' comment).
Values from `wavyadhesion.model_error_map` (`--workers K` runs it on a dask LocalCluster's
executor when dask.distributed is installed, else on a thread pool), with a progress bar.
Prints the grid, the wall time, the cells per status and the CPU time per LJ grid.
`--from-table CSV` draws the figure again from a saved table, computing nothing.
Uses the installed Python package (`pip install ./python`); matplotlib is imported here only.
"""
import argparse
import csv
import time
from pathlib import Path

import numpy as np

import wavyadhesion as wa

LEVELS = (0.01, 0.05, 0.2)
LABELS = {"P_fc": r"$P^*_{fc}$", "P_pf": r"$P^*_{pf}$", "W_star": r"$W^*$"}


def log_axis(text):
    """lo:hi:n -> n log-spaced values."""
    lo, hi, n = text.split(":")
    return np.logspace(np.log10(float(lo)), np.log10(float(hi)), int(n))


def compute(alpha, mu, workers, n_max):
    if workers <= 1:
        return wa.model_error_map(alpha, mu, n_max=n_max, progress=True)
    try:
        from dask.distributed import Client, LocalCluster
    except ImportError:
        from concurrent.futures import ThreadPoolExecutor
        with ThreadPoolExecutor(workers) as ex:
            return wa.model_error_map(alpha, mu, n_max=n_max, executor=ex, progress=True)
    with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True) as cluster, \
            Client(cluster) as client:
        return wa.model_error_map(alpha, mu, n_max=n_max, executor=client.get_executor(),
                                  progress=True)


# One row per cell: alpha, mu; LJ's status, grid N, CPU seconds, P_fc_peak (compared as
# P_fc), P_fc (a* = 1/2), P_snap, P_pf, W_star and the estimates of the compared three;
# per model its P_fc, P_pf, W_star, fc_mechanism, status and the relative errors rel_*
# (nan: not "ok"; inf: LJ zero, model not) with their resolved_* flags (1/0); the message
# of a cell that is not "ok".
def table_rows(m):
    head = ["alpha", "mu", "lj_status", "lj_N", "lj_seconds", "lj_P_fc_peak",
            "lj_P_fc_peak_err", "lj_P_fc", "lj_P_snap", "lj_P_pf", "lj_P_pf_err",
            "lj_W_star", "lj_W_star_err"]
    for mo in m.models:
        head += [f"{mo}_{q}" for q in wa.QUANTITIES] + [f"{mo}_fc_mechanism", f"{mo}_status"]
        head += [f"{mo}_rel_{q}" for q in wa.QUANTITIES]
        head += [f"{mo}_resolved_{q}" for q in wa.QUANTITIES]
    head.append("message")
    rows = [head]
    for i, a in enumerate(m.alpha):
        for j, u in enumerate(m.mu):
            row = [a, u, m.lj_status[i, j], m.lj_N[i, j], round(m.lj_seconds[i, j], 3),
                   m.lj["P_fc"][i, j], m.lj_err["P_fc"][i, j], m.lj["P_fc_contact"][i, j],
                   m.lj["P_snap"][i, j], m.lj["P_pf"][i, j], m.lj_err["P_pf"][i, j],
                   m.lj["W_star"][i, j], m.lj_err["W_star"][i, j]]
            for mo in m.models:
                row += [m.values[mo, q][i, j] for q in wa.QUANTITIES]
                row += [m.fc_mechanism[mo][i, j], m.status[mo][i, j]]
                row += [m.rel_error[mo, q][i, j] for q in wa.QUANTITIES]
                row += [int(m.resolved[mo, q][i, j]) for q in wa.QUANTITIES]
            texts = [t for (src, ii, jj), t in m.messages.items() if (ii, jj) == (i, j)]
            row.append(" | ".join(texts))
            rows.append([repr(float(v)) if isinstance(v, (float, np.floating)) else v
                         for v in row])
    return rows


def from_table(path):
    """A ModelErrorMap rebuilt from a saved table (table_rows' columns): draws the figure
    again without recomputing the map."""
    with open(path, newline="") as fh:
        rows = list(csv.DictReader(fh))
    alpha = np.array(sorted({float(r["alpha"]) for r in rows}))
    mu = np.array(sorted({float(r["mu"]) for r in rows}))
    models = tuple(mo for mo in ("dw", "md") if f"{mo}_status" in rows[0])
    cell = {(float(r["alpha"]), float(r["mu"])): r for r in rows}

    def grid(col, kind=float):
        return np.array([[kind(cell[a, u][col]) for u in mu] for a in alpha])

    lj = {"P_fc": grid("lj_P_fc_peak"), "P_pf": grid("lj_P_pf"), "W_star": grid("lj_W_star"),
          "P_fc_contact": grid("lj_P_fc"), "P_snap": grid("lj_P_snap")}
    lj_err = {"P_fc": grid("lj_P_fc_peak_err"), "P_pf": grid("lj_P_pf_err"),
              "W_star": grid("lj_W_star_err")}
    key = lambda col: {(mo, q): grid(f"{mo}_{col}{q}") for mo in models for q in wa.QUANTITIES}
    resolved = {k: v.astype(bool) for k, v in key("resolved_").items()}
    return wa.ModelErrorMap(alpha, mu, models, lj, lj_err, grid("lj_N", int),
                            grid("lj_status", str), grid("lj_seconds"), key(""), key("rel_"),
                            resolved, {mo: grid(f"{mo}_status", str) for mo in models},
                            {mo: grid(f"{mo}_fc_mechanism", str) for mo in models})


def edges(x):
    """Cell edges of log-spaced centres."""
    lx = np.log10(x)
    d = np.diff(lx).mean() if x.size > 1 else 1.0
    return 10 ** np.concatenate([[lx[0] - d / 2], (lx[:-1] + lx[1:]) / 2, [lx[-1] + d / 2]])


def draw(m, path, n_max):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import Normalize

    norm = Normalize(-3, 0)                   # log10 of 0.1 % .. 100 %
    fig, axes = plt.subplots(len(m.models), 3, figsize=(13, 4 * len(m.models)),
                             squeeze=False, constrained_layout=True)
    A, M = np.meshgrid(m.alpha, m.mu, indexing="ij")
    ea, em = edges(m.alpha), edges(m.mu)
    for r, model in enumerate(m.models):
        for c, q in enumerate(wa.QUANTITIES):
            ax = axes[r, c]
            rel = m.rel_error[model, q]
            shown = np.where(np.isinf(rel), 1.0, rel)
            with np.errstate(divide="ignore"):
                logr = np.log10(np.clip(shown, 1e-3, 1.0))
            mesh = ax.pcolormesh(ea, em, np.ma.masked_invalid(logr).T, cmap="viridis",
                                 norm=norm, shading="flat")
            fin = np.isfinite(rel)
            if fin.sum() >= 4 and min(rel.shape) >= 2:
                cs = ax.contour(A.T, M.T, np.where(fin, np.log10(np.fmax(shown, 1e-12)),
                                                   np.nan).T,
                                levels=np.log10(LEVELS), colors=("white", "orange", "red"),
                                linewidths=1.5)
                ax.clabel(cs, fmt={np.log10(v): f"{v:.0%}" for v in LEVELS}, fontsize=8)
            st = m.status[model]
            for i, j in zip(*np.nonzero(st == "unresolved")):
                ax.fill_between([ea[i], ea[i + 1]], em[j], em[j + 1], color="0.8", lw=0)
                ax.plot(m.alpha[i], m.mu[j], "x", color="0.4", ms=6)
            for i, j in zip(*np.nonzero(st == "failed")):
                ax.plot(m.alpha[i], m.mu[j], "x", color="red", ms=7)
            for i, j in zip(*np.nonzero((st == "ok") & ~m.resolved[model, q])):
                ax.plot(m.alpha[i], m.mu[j], "o", mfc="none", mec="white", ms=7)
            for i, j in zip(*np.nonzero(np.isinf(rel))):
                ax.text(m.alpha[i], m.mu[j], "inf", ha="center", va="center", fontsize=7,
                        color="black")
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_xlim(ea[0], ea[-1])
            ax.set_ylim(em[0], em[-1])
            ax.set_xlabel(r"$\alpha$")
            ax.set_ylabel(r"$\mu$")
            ax.set_title(f"{model.upper()} vs LJ: {LABELS[q]}", fontsize=10)
    cb = fig.colorbar(mesh, ax=axes, shrink=0.8)
    cb.set_label(r"$\log_{10}$ |model − LJ| / |LJ|  (clipped to [0.1 %, 100 %])")
    fig.suptitle("Model error against LJ (LJ's P_fc: b* = 1/2); contours 1 %, 5 %, 20 %; "
                 f"grey x: LJ's zone needs N > {n_max}; o: LJ estimate not small against the "
                 "error; "
                 "inf: LJ zero, model not", fontsize=9)
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--outdir", default=".", help="directory of the PNG (default: cwd)")
    ap.add_argument("--alpha", default="0.1:3:5", help="lo:hi:n log-spaced (default 0.1:3:5)")
    ap.add_argument("--mu", default="0.3:30:5", help="lo:hi:n log-spaced (default 0.3:30:5)")
    ap.add_argument("--workers", type=int, default=1,
                    help="parallel workers (dask LocalCluster if installed; default 1)")
    ap.add_argument("--n-max", type=int, default=16384,
                    help="cap of LJ's automatic grid, 128..16384 (default 16384)")
    ap.add_argument("--from-table", metavar="CSV",
                    help="draw the figure from a saved table (no computation; --alpha, --mu, "
                         "--workers ignored; --n-max only labels the figure)")
    args = ap.parse_args()
    try:        # fail before a long computation, not after it
        import matplotlib  # noqa: F401
    except ImportError:
        ap.error("matplotlib is needed to draw the figure: pip install matplotlib")
    if args.from_table:
        m = from_table(args.from_table)
        path = Path(args.outdir) / "model_error_map.png"
        draw(m, path, args.n_max)
        print(repr(m))
        print(f"wrote {path}")
        return
    alpha, mu = log_axis(args.alpha), log_axis(args.mu)
    t0 = time.perf_counter()
    m = compute(alpha, mu, args.workers, args.n_max)
    seconds = time.perf_counter() - t0
    path = Path(args.outdir) / "model_error_map.png"
    # the table first: a figure that cannot be drawn never loses a computed map
    table = Path(args.outdir) / "model_error_map.csv"
    with open(table, "w", newline="") as fh:
        csv.writer(fh, lineterminator="\n").writerows(table_rows(m))
    draw(m, path, args.n_max)
    print(f"grid: alpha {args.alpha} x mu {args.mu} ({alpha.size * mu.size} cells), "
          f"n_max {args.n_max}, {args.workers} workers: {seconds:.1f} s wall")
    print(repr(m))
    for n in sorted(set(m.lj_N[m.lj_status == "ok"].tolist())):
        sec = m.lj_seconds[(m.lj_N == n) & (m.lj_status == "ok")]
        print(f"N = {n:5d}: {sec.size:3d} cells, CPU s per cell median {np.median(sec):.2f}, "
              f"max {sec.max():.2f}, total {sec.sum():.0f}")
    print("alpha     mu        N     " + "  ".join(f"{mo}:{q:<7}" for mo in m.models
                                                  for q in wa.QUANTITIES))
    for i, a in enumerate(alpha):
        for j, u in enumerate(mu):
            cells = []
            for mo in m.models:
                for q in wa.QUANTITIES:
                    if m.status[mo][i, j] != "ok":
                        cells.append(f"{m.status[mo][i, j][:10]:>10}")
                    else:
                        flag = "" if m.resolved[mo, q][i, j] else "?"
                        cells.append(f"{m.rel_error[mo, q][i, j]:9.3g}{flag or ' '}")
            print(f"{a:<9.4g} {u:<9.4g} {m.lj_N[i, j]:<5d} " + " ".join(cells))
    print(f"wrote {path} and {table}")


if __name__ == "__main__":
    main()
