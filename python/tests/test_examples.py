"""The example scripts: si_cycle.py (SI in, SI out) runs and its numbers equal a hand
conversion of the dimensionless results; every script writes where it is told, by
default the current directory (never the repository)."""

import math
import re
import subprocess
import sys

import pytest

import wavyadhesion as wa


def _run(script, cwd, *args):
    res = subprocess.run([sys.executable, str(script), *args], cwd=cwd, capture_output=True,
                         text=True, timeout=300)
    assert res.returncode == 0, res.stderr
    return res.stdout


def test_si_cycle_numbers_and_figure(repo, tmp_path):
    out = _run(repo / "python" / "examples" / "si_cycle.py", tmp_path)   # default: cwd
    f_pf = float(re.search(r"pull-off force: (\S+) N/m", out).group(1))
    w = float(re.search(r"energy lost per cycle: (\S+) J/m\^2", out).group(1))
    # by hand: p* = pi E* Delta / L, force per length p* L, energy per area p* Delta
    p_star = math.pi * 1e6 * 1e-5 / 1e-3
    alpha = math.sqrt(2 * 0.05 * 1e-3 / (math.pi ** 2 * 1e6 * 1e-10))
    assert f"alpha = {alpha:.4f}" in out
    params = wa.Params.from_dimensional(Estar=1e6, period=1e-3, amplitude=1e-5,
                                        work_of_adhesion=0.05, peak_stress=1e5)
    P_pf = float(wa.critical_forces("md", params.alpha, params.mu).P_pf)
    W_star = wa.gap_path("md", params.alpha, params.mu).W_star
    assert f_pf == pytest.approx(P_pf * p_star * 1e-3, abs=5e-5)
    assert w == pytest.approx(W_star * p_star * 1e-5, rel=1e-3)
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        assert "matplotlib is not installed: no plot" in out
        return
    assert (tmp_path / "si_cycle.png").stat().st_size > 10_000
    other = tmp_path / "elsewhere"
    _run(repo / "python" / "examples" / "si_cycle.py", tmp_path, "--out", str(other))
    assert (other / "si_cycle.png").is_file()


def test_figure_scripts_default_to_the_current_directory(repo, tmp_path):
    pytest.importorskip("matplotlib")
    code = ("import sys; sys.path.insert(0, sys.argv[1]); sys.argv = ['x']; "
            "import _common; print(_common.output_dir('d'))")
    res = subprocess.run([sys.executable, "-c", code, str(repo / "python" / "examples")],
                         cwd=tmp_path, capture_output=True, text=True, check=True)
    assert res.stdout.strip() == str(tmp_path)


def test_every_example_takes_an_output_directory(repo):
    for script in sorted((repo / "python" / "examples").glob("*.py")):
        if script.name.startswith("_"):
            continue
        text = script.read_text()
        assert "output_dir(" in text or '"--out"' in text, script.name
        assert "doc/figures" not in text.replace("--out doc/figures", ""), script.name
