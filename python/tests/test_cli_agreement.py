"""trace_branch, load_path and critical_forces give what the command line prints
(`wavyadhesion branch|path|critical --format csv`, 17 significant digits). The
executable is $WAVYADHESION_CLI or the one fpm builds (release profile) in the
repository; skipped when neither is available."""

import csv
import io
import os
import shutil
import subprocess

import numpy as np
import pytest

import wavyadhesion as wa


@pytest.fixture(scope="module")
def cli(repo):
    exe = os.environ.get("WAVYADHESION_CLI")
    if exe:
        return exe
    if shutil.which("fpm") is None:
        pytest.skip("fpm not found and $WAVYADHESION_CLI not set")
    out = subprocess.run(["fpm", "run", "--profile", "release", "--runner", "echo",
                          "wavyadhesion"], cwd=repo, capture_output=True, text=True)
    if out.returncode != 0:
        pytest.skip("could not build the command line: " + out.stderr[-200:])
    return out.stdout.strip().splitlines()[-1].strip()


def table(cli, *args):
    res = subprocess.run([cli, *args, "--format", "csv"], capture_output=True, text=True,
                         check=True)
    rows = list(csv.DictReader(io.StringIO(res.stdout)))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


@pytest.mark.parametrize("model, alpha, mu", [
    ("dw", 0.3, 1.0), ("dw", 0.3, 5.0), ("dw", 0.6, 3.0), ("md", 0.3, 2.5),
    ("jkr", 0.3, 1.0), ("westergaard", 0.3, 1.0)])
def test_branch(cli, model, alpha, mu):
    t = table(cli, "branch", "--model", model, "--alpha", str(alpha), "--mu", str(mu))
    b = wa.trace_branch(model, alpha, mu)
    assert len(b) == t["a_star"].size
    for name in ("zone_case", "event"):
        np.testing.assert_array_equal(getattr(b, name), t[name])
    np.testing.assert_array_equal(b.stable, t["stable"] == 1)
    for name in ("a_star", "c_star", "P_star", "b_star"):
        np.testing.assert_allclose(getattr(b, name), t[name], rtol=1e-12, atol=1e-15)


@pytest.mark.parametrize("model, alpha, mu", [
    ("dw", 0.3, 5.0), ("dw", 1.0, 3.0), ("md", 0.3, 1.0), ("jkr", 0.6, 1.0)])
def test_path(cli, model, alpha, mu):
    t = table(cli, "path", "--model", model, "--alpha", str(alpha), "--mu", str(mu))
    p = wa.load_path(model, alpha, mu)
    np.testing.assert_array_equal(p.stage, t["stage"])
    np.testing.assert_array_equal(p.event, t["event"])
    for name in ("a_star", "c_star", "P_star"):
        np.testing.assert_allclose(getattr(p, name), t[name], rtol=1e-12, atol=1e-15)


@pytest.mark.parametrize("model", ["dw", "md", "jkr"])
def test_critical(cli, model):
    t = table(cli, "critical", "--model", model, "--alpha", "0.3,0.6,1",
              "--mu-range", "0.01:10:13:log")
    crit = wa.critical_forces(model, t["alpha"], t["mu"])
    np.testing.assert_allclose(crit.P_fc, t["P_fc"], rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(crit.P_pf, t["P_pf"], rtol=1e-12, atol=1e-15)


def test_lj_faces_agree(cli, tmp_path):
    """model="lj": the branch, both paths, the critical values with their error columns
    and a profile with --profile-file are those of the command line (one grid, n = 256)."""
    common = ["--model", "lj", "--alpha", "0.3", "--mu", "3", "--n", "256"]
    b = wa.trace_branch("lj", 0.3, 3.0, n=256)
    t = table(cli, "branch", *common)
    for k in ("a_star", "b_star", "P_star", "gbar", "h_min", "h_max"):
        np.testing.assert_array_equal(t[k], getattr(b, k))
    np.testing.assert_array_equal(t["stable_gap"], b.stable_gap)
    c = wa.critical_forces("lj", 0.3, 3.0, n=256)
    t = table(cli, "critical", *common)
    for k in ("P_fc", "P_pf", "P_fc_err", "P_pf_err"):
        assert t[k][0] == getattr(c, k)
    for control, path in (("load", wa.load_path("lj", 0.3, 3.0, n=256)),
                          ("gap", wa.gap_path("lj", 0.3, 3.0, n=256))):
        t = table(cli, "path", "--control", control, *common)
        for k in ("stage", "event", "a_star", "P_star", "gbar"):
            np.testing.assert_array_equal(t[k], getattr(path, k))
    samples = 1 - np.cos(2 * np.pi * (np.arange(48) / 48 + 0.01))
    f = tmp_path / "wave.txt"
    f.write_text("\n".join(repr(float(v)) for v in samples) + "\n")
    p = wa.profile("lj", 0.3, 3.0, 0.2, n=256, profile=samples)
    t = table(cli, "profile", "--a-star", "0.2", "--profile-file", str(f), *common)
    for k in ("x", "traction", "gap"):
        np.testing.assert_array_equal(t["x_star" if k == "x" else k], getattr(p, k))
