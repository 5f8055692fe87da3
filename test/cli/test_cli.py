"""The command-line driver (SPEC section 7): columns, formats, errors, exit codes.

The executable is $WAVYADHESION_CLI, or the one fpm builds in the release profile.
"""
import csv
import io
import math
import os
import subprocess
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def cli():
    exe = os.environ.get("WAVYADHESION_CLI")
    if not exe:
        out = subprocess.run(["fpm", "run", "--profile", "release", "--runner", "echo",
                              "wavyadhesion"], cwd=REPO, check=True, capture_output=True,
                             text=True).stdout
        exe = out.strip().splitlines()[-1].strip()
    return exe


def run(cli, *args, check=True):
    res = subprocess.run([cli, *args], capture_output=True, text=True)
    if check:
        assert res.returncode == 0, res.stderr
    return res


def rows(text):
    return list(csv.DictReader(io.StringIO(text)))


@pytest.mark.parametrize("model", ["dw", "md", "jkr", "westergaard"])
def test_point_csv_columns(cli, model):
    res = run(cli, "point", "--model", model, "--alpha", "0.3", "--mu", "1",
              "--a-star", "0.1,0.2", "--format", "csv")
    table = rows(res.stdout)
    assert list(table[0].keys()) == ["a_star", "c_star", "P_star", "zone_case"]
    assert {float(r["a_star"]) for r in table} == {0.1, 0.2}
    for r in table:
        assert math.isfinite(float(r["P_star"]))
        assert float(r["a_star"]) <= float(r["c_star"]) <= 0.5


def test_table_format_is_numeric_after_comments(cli):
    res = run(cli, "point", "--alpha", "0.3", "--mu", "1", "--a-star", "0.1,0.2")
    lines = res.stdout.splitlines()
    comments = [l for l in lines if l.startswith("#")]
    assert any("alpha" in l and "mu" in l for l in comments)
    assert any("Sigma0" in l and "Dcod" in l for l in comments)
    assert any(l.startswith("# columns: a_star c_star P_star zone_case") for l in comments)
    data = [l for l in lines if not l.startswith("#")]
    assert len(data) == 2
    for l in data:
        values = [float(x) for x in l.split()]
        assert len(values) == 4


def test_default_is_dw_branch(cli):
    res = run(cli)
    assert "# model: dw" in res.stdout
    assert "a_star c_star P_star b_star zone_case stable event" in res.stdout
    data = [l.split() for l in res.stdout.splitlines() if not l.startswith("#")]
    events = {int(r[6]) for r in data}
    assert {1, 2, 8} <= events


@pytest.mark.parametrize("args, needle", [
    (["point", "--alpha", "-1", "--a-star", "0.1"], "alpha"),
    (["point", "--alpha", "0.3", "--mu", "-2", "--a-star", "0.1"], "mu"),
    (["point", "--a-star", "0.7"], "a-star"),
    (["point", "--a-star", "abc"], "a-star"),
    (["point", "--model", "xyz", "--a-star", "0.1"], "model"),
    (["point", "--format", "xml", "--a-star", "0.1"], "format"),
    (["frobnicate"], "subcommand"),
    (["point", "--bogus", "1"], "--bogus"),
    (["critical", "--mu-range", "1:0.1:10"], "mu-range"),
])
def test_usage_errors_exit_2(cli, args, needle):
    res = run(cli, *args, check=False)
    assert res.returncode == 2
    assert needle in res.stderr
    assert res.stdout == ""


def test_help_and_version(cli):
    assert "Usage: wavyadhesion" in run(cli, "--help").stdout
    assert run(cli, "--version").stdout.startswith("wavyadhesion ")


def test_critical_600_rows(cli):
    res = run(cli, "critical", "--model", "dw", "--alpha", "0.3,0.6,1",
              "--mu-range", "0.01:10:200:log", "--format", "csv")
    table = rows(res.stdout)
    assert len(table) == 600
    assert list(table[0].keys()) == ["alpha", "mu", "P_fc", "P_pf"]
    assert all(float(r["P_pf"]) <= 0.0 for r in table)


def test_jkr_pull_off_is_minus_infinity(cli):
    res = run(cli, "critical", "--model", "jkr", "--alpha", "0.3", "--mu", "1", "--format", "csv")
    assert float(rows(res.stdout)[0]["P_pf"]) == -math.inf
    assert "-Infinity" in res.stdout


def test_path_lists_the_papers_jumps(cli):
    # alpha = 0.3, mu = 5: snapping into full contact and snapping detachment (section 4.1)
    res = run(cli, "path", "--alpha", "0.3", "--mu", "5", "--format", "csv")
    events = [(int(r["stage"]), int(r["event"])) for r in rows(res.stdout)]
    assert events == [(1, 3), (1, 4), (1, 3), (1, 5), (2, 6), (2, 3), (2, 7)]


def test_output_file(cli, tmp_path):
    out = tmp_path / "t.csv"
    run(cli, "point", "--a-star", "0.2", "--format", "csv", "--output", str(out))
    assert rows(out.read_text())[0]["zone_case"] in ("1", "2")


def test_dimensional_input(cli):
    res = run(cli, "point", "--Estar", "1e9", "--period", "1e-5", "--amplitude", "1e-7",
              "--work-of-adhesion", "0.05", "--peak-stress", "1e7", "--a-star", "0.2",
              "--format", "csv")
    assert len(rows(res.stdout)) >= 1
