"""The command-line driver (doc/user-guide.md, "Command line"): columns, formats, errors, exit codes.

The executable is $WAVYADHESION_CLI, or the one fpm builds in the release profile.
"""
import csv
import io
import json
import math
import os
import signal
import subprocess
import time
from pathlib import Path

import numpy as np
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
    assert list(table[0].keys()) == ["a_star", "c_star", "P_star", "zone_case", "gbar"]
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
    assert any(l.startswith("# columns: a_star c_star P_star zone_case gbar") for l in comments)
    data = [l for l in lines if not l.startswith("#")]
    assert len(data) == 2
    for l in data:
        values = [float(x) for x in l.split()]
        assert len(values) == 5


def test_default_is_dw_branch(cli):
    res = run(cli)
    assert "# model: dw" in res.stdout
    assert "# columns: a_star c_star P_star b_star zone_case stable event gbar\n" in res.stdout
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


def test_path_header_lists_every_jump_energy_in_full(cli):
    # the energy of each load-control jump, in full (a note once cut off its exponent):
    # alpha = 0.3, mu = 5 snaps into full contact releasing 9.18e-3; the jump-in and the
    # pull-off have no finite energy and say so
    out = run(cli, "path", "--model", "dw", "--alpha", "0.3", "--mu", "5").stdout
    lines = [line for line in out.splitlines() if line.startswith("#   jump starting at")]
    assert len(lines) == 3
    values = [line.rsplit(": ", 1)[1] for line in lines]
    assert values[0] == values[2] == "not defined"
    assert float(values[1]) == pytest.approx(9.1834906501750517e-3, rel=1e-9)


def test_output_file(cli, tmp_path):
    out = tmp_path / "t.csv"
    run(cli, "point", "--a-star", "0.2", "--format", "csv", "--output", str(out))
    assert rows(out.read_text())[0]["zone_case"] in ("1", "2")


def test_dimensional_input(cli):
    res = run(cli, "point", "--Estar", "1e9", "--period", "1e-5", "--amplitude", "1e-7",
              "--work-of-adhesion", "0.05", "--peak-stress", "1e7", "--a-star", "0.2",
              "--format", "csv")
    assert len(rows(res.stdout)) >= 1


# --- issue 9: robustness of the driver ---------------------------------------------------

def files_in(path):
    return sorted(p.name for p in path.iterdir())


@pytest.mark.parametrize("args", [
    ["point", "--a-star", "0.2"],
    ["branch"],
    ["critical", "--mu", "0.5,1"],
    ["--help"],
])
def test_write_error_on_stdout_exits_1(cli, args):
    with open("/dev/full", "w") as full:
        res = subprocess.run([cli, *args], stdout=full, stderr=subprocess.PIPE, text=True)
    assert res.returncode == 1
    assert "cannot write" in res.stderr and "standard output" in res.stderr


def test_write_error_on_output_file_exits_1(cli):
    res = run(cli, "point", "--a-star", "0.2", "--output", "/dev/full", check=False)
    assert res.returncode == 1
    assert "/dev/full" in res.stderr and "No space left" in res.stderr


@pytest.mark.parametrize("target", ["/proc/version", "/proc/no-such-file"])
def test_output_that_cannot_be_created_exits_1(cli, target):
    # issue 8: a write error, not a usage error (user guide: write errors exit 1)
    if not os.path.isdir("/proc/self"):
        pytest.skip("no /proc here")
    res = run(cli, "point", "--a-star", "0.2", "--output", target, check=False)
    assert res.returncode == 1, res.stderr
    assert target in res.stderr and "--output" in res.stderr
    assert "Try 'wavyadhesion --help'" not in res.stderr and res.stdout == ""


@pytest.mark.parametrize("args, needle", [
    (["critical", "--mu-range", "1:x:3"], "--mu-range HI: 'x' is not a number (expected LO:HI:N"),
    (["critical", "--mu-range", "1:2"], "is not LO:HI:N[:log] (expected LO:HI:N"),
    (["critical", "--mu-range", "2:1:3"], "need 0 <= LO <= HI (expected LO:HI:N"),
    (["map", "--alpha-range", "0:1:3:log"], "LO must be > 0 with :log (expected LO:HI:N"),
    (["gaplaw", "--gbar-range", "0:1:3:lin"], "is not 'log' (expected LO:HI:N"),
])
def test_range_messages_say_expected_once(cli, args, needle):
    # issue 8: "(expected expected LO:HI:N...)"
    res = run(cli, *args, check=False)
    assert res.returncode == 2 and needle in res.stderr, res.stderr
    assert "expected expected" not in res.stderr


@pytest.mark.parametrize("args, needle", [
    (["critical", "--Estar", "1e6", "--period", "1e-3", "--amplitude", "1e-5",
      "--work-of-adhesion", "-1", "--peak-stress", "1e5"], "--work-of-adhesion = "),
    (["critical", "--Estar", "1e6", "--period", "1e-3", "--amplitude", "1e-5",
      "--work-of-adhesion", "0.05", "--peak-stress", "-1"], "--peak-stress = "),
    (["critical", "--E1", "1e6", "--nu1", "0.3", "--E2", "1e6", "--nu2", "0.6", "--period",
      "1e-3", "--amplitude", "1e-5", "--work-of-adhesion", "0.05", "--peak-stress", "1e5"],
     "--nu2 = "),
    (["point", "--alpha", "1e13", "--a-star", "0.2"], "--alpha = "),
    (["critical", "--mu", "1e101"], "--mu = "),
])
def test_library_messages_name_the_option(cli, args, needle):
    # issue 8: the library's argument names spelled as the options (--c-star, not --c_star)
    res = run(cli, *args, check=False)
    assert res.returncode == 2 and needle in res.stderr, res.stderr
    assert "_" not in res.stderr.split("=")[0], res.stderr


def test_output_to_a_device_is_written_directly(cli):
    run(cli, "point", "--a-star", "0.2", "--output", "/dev/null")


def test_failed_run_keeps_existing_output(cli, tmp_path):
    # the a* range is checked after --output is opened: the run fails with the
    # temporary file already created
    out = tmp_path / "t.csv"
    out.write_text("precious\n")
    res = run(cli, "point", "--a-star", "0.7", "--output", str(out), check=False)
    assert res.returncode == 2
    assert out.read_text() == "precious\n"
    assert files_in(tmp_path) == ["t.csv"]


def test_failed_run_leaves_no_file(cli, tmp_path):
    out = tmp_path / "new.csv"
    res = run(cli, "point", "--a-star", "0.7", "--output", str(out), check=False)
    assert res.returncode == 2
    assert files_in(tmp_path) == []


def test_numerical_failure_keeps_existing_output(cli, tmp_path):
    # DW at mu = 0 failed in the tracer (issue 9 item 3); whichever way it ends, the
    # file holds either the old text or a complete table, and no temporary file remains
    out = tmp_path / "t.csv"
    out.write_text("precious\n")
    res = run(cli, "branch", "--model", "dw", "--mu", "0", "--format", "csv", "--output",
              str(out), check=False)
    assert files_in(tmp_path) == ["t.csv"]
    if res.returncode == 0:
        assert rows(out.read_text())[-1]["event"] == "8"
    else:
        assert res.returncode == 1 and "no table written" in res.stderr
        assert out.read_text() == "precious\n"


def test_output_replaces_file_keeps_mode_and_symlink(cli, tmp_path):
    target = tmp_path / "t.csv"
    target.write_text("old\n")
    target.chmod(0o640)
    link = tmp_path / "link.csv"
    link.symlink_to(target.name)
    run(cli, "point", "--a-star", "0.2", "--format", "csv", "--output", str(link))
    assert link.is_symlink()
    assert rows(target.read_text())[0]["a_star"].startswith("2.0")
    assert target.stat().st_mode & 0o777 == 0o640
    assert files_in(tmp_path) == ["link.csv", "t.csv"]


def test_output_in_missing_directory_is_a_usage_error(cli, tmp_path):
    res = run(cli, "point", "--a-star", "0.2", "--output", str(tmp_path / "no" / "t.csv"),
              check=False)
    assert res.returncode == 2
    assert "--output" in res.stderr


@pytest.mark.parametrize("option, value, subcommand", [
    ("--alpha", "1+1", "point"),
    ("--a-star", "0.1-1", "point"),
    ("--alpha", "1e", "point"),
    ("--alpha", "nan", "point"),
    ("--mu", "inf", "point"),
    ("--mu", "", "point"),
    ("--mu", " 1", "point"),
    ("--alpha", "0x10", "point"),
    ("--alpha", "1d0", "point"),
    ("--alpha", "1e400", "point"),
    ("--a-star", "0.1,,0.2", "point"),
    ("--a-star", "0.1,", "point"),
    ("--Estar", "1e9Pa", "point"),
    ("--alpha", "0.3,abc", "critical"),
])
def test_strict_number_parsing(cli, option, value, subcommand):
    args = [subcommand, option, value]
    if subcommand == "point" and option != "--a-star":
        args += ["--a-star", "0.2"]
    res = run(cli, *args, check=False)
    assert res.returncode == 2, res.stdout
    assert option in res.stderr
    assert res.stdout == ""


@pytest.mark.parametrize("option, range_text", [
    ("--alpha", "[1e-12, 1e12]"), ("--mu", "0 or [1e-100, 1e100]"), ("--a-star", "[0, 1/2]"),
    ("--nu1", "(-1, 1/2]"), ("--period", "(0, inf) m"),
])
def test_parse_error_names_the_valid_range(cli, option, range_text):
    res = run(cli, "point", option, "x", check=False)
    assert res.returncode == 2
    assert option in res.stderr and range_text in res.stderr


@pytest.mark.parametrize("value", ["0.3", "+0.3", ".3", "3e-1", "3.E-1", "0.30"])
def test_plain_numbers_are_accepted(cli, value):
    res = run(cli, "point", "--alpha", value, "--a-star", "0.2", "--format", "csv")
    assert len(rows(res.stdout)) >= 1


@pytest.mark.parametrize("args, needle", [
    (["point", "--alpha", "1", "--alpha", "2", "--a-star", "0.1"], "--alpha is given twice"),
    (["point", "--a-star", "0.1", "--a-star", "0.2"], "--a-star is given twice"),
    (["point", "--model", "dw", "--model", "md", "--a-star", "0.1"], "--model is given twice"),
    (["critical", "--mu", "1", "--mu-range", "1:2:3"], "--mu and --mu-range"),
    (["point", "--mu-range", "1:2:1", "--a-star", "0.1"], "--mu-range"),
    (["path", "--a-star", "0.1"], "--a-star"),
    (["critical", "--a-star", "0.1"], "--a-star"),
    (["point", "--Estar", "1e9", "--a-star", "0.1"], "incomplete"),
    (["point", "--Estar", "1e9", "--E1", "1e9", "--nu1", "0.3", "--E2", "1e9", "--nu2", "0.3",
      "--period", "1e-5", "--amplitude", "1e-7", "--work-of-adhesion", "0.05",
      "--peak-stress", "1e7", "--a-star", "0.1"], "--Estar cannot be combined"),
    (["point", "--E1", "1e9", "--nu1", "0.3", "--period", "1e-5", "--amplitude", "1e-7",
      "--work-of-adhesion", "0.05", "--peak-stress", "1e7", "--a-star", "0.1"], "--E2 --nu2"),
    (["point", "--alpha", "0.3", "--Estar", "1e9", "--period", "1e-5", "--amplitude", "1e-7",
      "--work-of-adhesion", "0.05", "--peak-stress", "1e7", "--a-star", "0.1"], "--alpha"),
    (["critical", "--mu-range", "0.1:1:10", "--Estar", "1e9", "--period", "1e-5",
      "--amplitude", "1e-7", "--work-of-adhesion", "0.05", "--peak-stress", "1e7"],
     "--mu-range"),
    (["critical", "--mu-range", "1:2:3.5"], "N"),
    (["critical", "--mu-range", "1:2:3:lin"], "log"),
    (["critical", "--mu-range", "0:2:3:log"], "LO must be > 0"),
    (["point", "--a-star", "0.1", "--output", ""], "--output"),
])
def test_contradictory_or_repeated_options_exit_2(cli, args, needle):
    res = run(cli, *args, check=False)
    assert res.returncode == 2
    assert needle in res.stderr
    assert res.stdout == ""


SI = ["--period", "1e-5", "--amplitude", "1e-7", "--work-of-adhesion", "0.05",
      "--peak-stress", "1e7"]


def test_si_moduli_and_estar_agree(cli):
    nu = 0.3
    estar = 1.0 / (2 * (1 - nu * nu) / 2e9)            # two equal bodies, E = 2 GPa
    a = run(cli, "point", "--E1", "2e9", "--nu1", "0.3", "--E2", "2e9", "--nu2", "0.3", *SI,
            "--a-star", "0.2").stdout
    b = run(cli, "point", "--Estar", repr(estar), *SI, "--a-star", "0.2").stdout
    header = [l for l in a.splitlines() if l.startswith("# alpha")]
    assert header == [l for l in b.splitlines() if l.startswith("# alpha")]


def test_critical_takes_si_input(cli):
    point = run(cli, "point", "--Estar", "1e9", *SI, "--a-star", "0.2").stdout
    alpha_mu = next(l for l in point.splitlines() if l.startswith("# alpha")).split()
    res = run(cli, "critical", "--Estar", "1e9", *SI, "--format", "csv")
    table = rows(res.stdout)
    assert len(table) == 1
    assert float(table[0]["alpha"]) == float(alpha_mu[3])
    assert float(table[0]["mu"]) == float(alpha_mu[6])


def test_messages_print_three_digit_exponents(cli):
    res = run(cli, "point", "--alpha", "-1.5e300", "--a-star", "0.2", check=False)
    assert res.returncode == 2 and "E+300" in res.stderr
    res = run(cli, "point", "--a-star", "1.7e308", check=False)
    assert res.returncode == 2 and "E+308" in res.stderr


def test_point_many_values_in_order(cli):
    # point keeps its rows in a doubling array (linear time; issue 9 measured
    # 10k/20k/40k values); 20000 a* give 20000 rows in the order given
    values = [".1", ".2", ".3", ".4"] * 5000
    res = run(cli, "point", "--model", "westergaard", "--a-star", ",".join(values),
              "--format", "csv")
    table = rows(res.stdout)
    assert len(table) == 20000
    assert [float(r["a_star"]) for r in table[:5]] == [0.1, 0.2, 0.3, 0.4, 0.1]


def test_critical_lists_every_row_across_mechanism_changes(cli):
    # issue 9 item 4: the mechanism bisection landed in failure windows and the whole
    # table was lost; now it is always written
    res = run(cli, "critical", "--model", "md", "--alpha", "1", "--mu-range", "0.1:5:20",
              check=False)
    data = [l.split() for l in res.stdout.splitlines() if not l.startswith("#")]
    assert len(data) == 20
    notes = [l for l in res.stdout.splitlines() if l.startswith("# alpha")]
    assert any("P_pf" in l for l in notes) and any("P_fc" in l for l in notes)
    assert res.returncode == (1 if any("nan" in r[2].lower() for r in data) else 0)


def test_critical_mechanism_bisection_from_mu_zero(cli):
    # a linear range from 0: the bisection starts arithmetic (it cannot be geometric)
    res = subprocess.run([cli, "critical", "--model", "md", "--mu-range", "0:1:3"],
                         capture_output=True, text=True, timeout=120)
    assert res.returncode == 0, res.stderr
    assert any("P_pf: gradual -> jump case 1" in l for l in res.stdout.splitlines())


@pytest.mark.parametrize("model, alpha, mus, bad", [
    # MD tracer failure window at a mechanism change (issue 9 item 4)
    ("md", "1", ["0.5", "0.79369860901363931", "2"], "7.9369860901363931E-001"),
    # DW at mu = 0 (issue 9 item 3)
    ("dw", "0.3", ["1", "0", "5"], "0.0000000000000000E+000"),
])
def test_critical_failing_row_is_written_with_nan(cli, model, alpha, mus, bad):
    # whether or not the row still fails, the table has every row: a failing one is NaN,
    # named on stderr with its reason, and the exit status is 1; the others are intact
    res = run(cli, "critical", "--model", model, "--alpha", alpha, "--mu", ",".join(mus),
              "--format", "csv", check=False)
    table = rows(res.stdout)
    assert [float(r["mu"]) for r in table] == [float(m) for m in mus]
    assert math.isfinite(float(table[0]["P_fc"])) and math.isfinite(float(table[2]["P_pf"]))
    failed = [r for r in table if math.isnan(float(r["P_fc"]))]
    if failed:
        assert res.returncode == 1
        assert f"mu = {bad}" in res.stderr and "row written with NaN forces" in res.stderr
        assert "1 of 3 rows failed" in res.stderr
        assert [r["mu"] for r in failed] == [table[1]["mu"]]
    else:
        assert res.returncode == 0 and res.stderr == ""


def test_critical_failure_note_in_table_header(cli):
    res = run(cli, "critical", "--model", "dw", "--mu", "0,1", check=False)
    data = [l for l in res.stdout.splitlines() if not l.startswith("#")]
    assert len(data) == 2
    if res.returncode == 1:
        assert "# 1 of 2 rows failed" in res.stdout


@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM])
def test_interrupted_run_removes_its_temporary_file(cli, tmp_path, sig):
    out = tmp_path / "t.txt"
    out.write_text("precious\n")
    proc = subprocess.Popen([cli, "critical", "--model", "md", "--mu-range",
                             "0.01:10:2000:log", "--output", str(out)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    try:
        for _ in range(200):                      # the temporary file is made at start
            if len(files_in(tmp_path)) == 2:
                break
            time.sleep(0.05)
        assert len(files_in(tmp_path)) == 2
        proc.send_signal(sig)
        proc.communicate(timeout=60)
    finally:
        proc.kill()
    assert proc.returncode == 128 + sig
    assert files_in(tmp_path) == ["t.txt"]
    assert out.read_text() == "precious\n"


# --------------------------------------------------------------------- map (issue 13)

def test_map_rows_and_header(cli):
    """`map` prints rows 'boundary alpha mu' with every code explained in the header; at
    alpha = 0.3 (DW) the boundaries are where mechanism_change (critical's header) puts
    them."""
    res = run(cli, "map", "--model", "dw", "--alpha", "0.3,0.31")
    header = [l for l in res.stdout.splitlines() if l.startswith("#")]
    data = [l.split() for l in res.stdout.splitlines() if l and not l.startswith("#")]
    codes = {int(r[0]) for r in data}
    assert {101, 212}.issubset(codes)
    for code in codes:
        assert any(l.startswith(f"# boundary {code} = ") for l in header), code
    assert "# columns: boundary alpha mu" in header
    crit = run(cli, "critical", "--model", "dw", "--alpha", "0.3", "--mu-range",
               "1:10:5:log").stdout
    fc = float([l for l in crit.splitlines() if "P_fc: gradual -> jump case 1" in l][0]
               .split()[4])
    mu_101 = [float(r[2]) for r in data if r[0] == "101" and float(r[1]) == 0.3][0]
    assert abs(mu_101 - fc) <= 1e-8 * fc


def test_map_special_points_in_header(cli):
    """Where boundaries meet is a header line: DW 101 meets 103 near alpha 0.567."""
    res = run(cli, "map", "--model", "dw", "--alpha-range", "0.3:1:40:log", "--mu-range",
              "0.1:10:30:log")
    special = [l for l in res.stdout.splitlines() if l.startswith("# special point")]
    meet = [l for l in special if "gradual -> jump case 1 meets full contact: gradual -> "
            "snap at P=0" in l]
    assert len(meet) == 1
    alpha = float(meet[0].split("alpha")[1].split()[0])
    assert abs(alpha - 0.567) < 0.01


def test_map_csv_and_usage_errors(cli):
    res = run(cli, "map", "--model", "dw", "--alpha", "0.3", "--format", "csv")
    lines = res.stdout.splitlines()
    assert lines[0] == "boundary,alpha,mu" and all(l.count(",") == 2 for l in lines[1:])
    for args in (["map", "--model", "jkr"], ["map", "--mu", "1"],
                 ["map", "--alpha", "0.3", "--alpha-range", "0.1:1:3:log"],
                 ["critical", "--alpha-range", "0.1:1:3:log"],
                 ["map", "--alpha-range", "1:0.1:3:log"], ["map", "--alpha", "0.3,0.1"]):
        bad = run(cli, *args, check=False)
        assert bad.returncode == 2 and bad.stdout == "", args
        assert "wavyadhesion:" in bad.stderr


def test_map_gap_control(cli):
    """`map --control gap` prints only gap-control boundaries (DW: 401, retraction gradual
    -> jump-out, at mu 2.34035 for alpha 0.3), each code explained; `both` adds the
    load-control ones; `--control both` is refused outside map."""
    res = run(cli, "map", "--model", "dw", "--alpha", "0.3,0.31", "--mu-range",
              "1e-2:1e2:20:log", "--control", "gap")
    header = [l for l in res.stdout.splitlines() if l.startswith("#")]
    data = [l.split() for l in res.stdout.splitlines() if l and not l.startswith("#")]
    assert {int(r[0]) for r in data} == {401}
    assert "# boundary 401 = gap retraction: gradual -> jump-out" in header
    mu_401 = [float(r[2]) for r in data if float(r[1]) == 0.3][0]
    assert abs(mu_401 - 2.3403548179) <= 1e-8 * mu_401
    both = run(cli, "map", "--model", "dw", "--alpha", "0.3,0.31", "--mu-range",
               "1e-2:1e2:20:log", "--control", "both").stdout
    codes = {int(l.split()[0]) for l in both.splitlines() if l and not l.startswith("#")}
    assert {101, 212, 401}.issubset(codes)
    bad = run(cli, "path", "--control", "both", check=False)
    assert bad.returncode == 2 and "--control both" in bad.stderr


# --- separation: profile subcommand, gbar columns ----------------------------------------

@pytest.mark.parametrize("model", ["dw", "md"])
def test_branch_has_gbar_last(cli, model):
    res = run(cli, "branch", "--model", model, "--format", "csv")
    table = rows(res.stdout)
    assert list(table[0].keys())[-2:] == ["event", "gbar"]
    g = [float(r["gbar"]) for r in table]
    assert all(math.isfinite(v) and v >= 0 for v in g) and g[-1] < 1e-6


def test_point_gbar_matches_python_closed_form(cli):
    res = run(cli, "point", "--model", "westergaard", "--a-star", "0.1,0.3", "--format", "csv")
    for r in rows(res.stdout):
        s2 = math.sin(math.pi * float(r["a_star"])) ** 2
        assert float(r["gbar"]) == pytest.approx(1 - s2 + s2 * math.log(s2), rel=1e-14)


def test_profile_md(cli):
    res = run(cli, "profile", "--model", "md", "--alpha", "0.3", "--mu", "1", "--a-star", "0.2")
    lines = res.stdout.splitlines()
    comments = "\n".join(l for l in lines if l.startswith("#"))
    assert "# columns: x_star traction gap" in comments
    for needle in ("# state: the principal state", "a_star = 2.0000000000000001E-001", "c_star = ",
                   "P_star = ", "zone_case = 1",
                   "gbar = "):
        assert needle in comments
    data = [[float(v) for v in l.split()] for l in lines if not l.startswith("#")]
    assert len(data) == 201 and data[0][0] == -0.5 and data[-1][0] == 0.5
    assert all(h >= 0 for _, _, h in data)
    assert all(h == 0 for x, _, h in data if abs(x) < 0.2)
    gbar = float(comments.split("gbar = ")[1].split()[0])
    mean = sum(h for _, _, h in data[:-1]) / 200             # one period, trapezoid = left sum
    assert mean == pytest.approx(gbar, abs=1e-4)


def test_profile_options(cli):
    res = run(cli, "profile", "--model", "md", "--a-star", "0", "--c-star", "0.05", "--n", "5",
              "--format", "csv")
    table = rows(res.stdout)
    assert list(table[0].keys()) == ["x_star", "traction", "gap"] and len(table) == 5
    assert float(table[2]["traction"]) < 0 and float(table[0]["traction"]) == 0
    point = rows(run(cli, "point", "--model", "dw", "--a-star", "0.2", "--format", "csv").stdout)
    c = point[0]["c_star"]
    a = run(cli, "profile", "--model", "dw", "--a-star", "0.2", "--c-star", c).stdout
    b = run(cli, "profile", "--model", "dw", "--a-star", "0.2").stdout
    va = [float(v) for l in a.splitlines() if not l.startswith("#") for v in l.split()]
    vb = [float(v) for l in b.splitlines() if not l.startswith("#") for v in l.split()]
    assert va == pytest.approx(vb, rel=1e-10, abs=1e-14)    # roots vs principal: ulps


@pytest.mark.parametrize("args, code, needle", [
    (["profile"], 2, "--a-star"),
    (["profile", "--a-star", "0.1,0.2"], 2, "one value"),
    (["profile", "--a-star", "0.7"], 2, "[0, 1/2]"),
    (["profile", "--a-star", "0.2", "--c-star", "0.9"], 2, "--c-star = "),
    (["profile", "--a-star", "0.2", "--n", "1"], 2, "--n"),
    (["profile", "--a-star", "0.2", "--n", "x"], 2, "--n"),
    (["point", "--a-star", "0.2", "--n", "5"], 2, "--n are only for the profile"),
    (["branch", "--c-star", "0.2"], 2, "--c-star"),
    (["profile", "--model", "md", "--a-star", "0"], 2, "--c-star: needed"),
    (["profile", "--a-star", "0.2", "--c-star", "0.45"], 1, "nearest"),
    (["profile", "--model", "jkr", "--a-star", "0.5"], 1, "jkr"),
])
def test_profile_errors(cli, args, code, needle):
    res = run(cli, *args, check=False)
    assert res.returncode == code, res.stderr
    assert needle in res.stderr and "--c_star" not in res.stderr, res.stderr


def test_path_control_gap_md_events_and_energy(cli):
    # issue 11: approach and retraction under mean-gap control, with W* in the header
    res = run(cli, "path", "--control", "gap", "--model", "md", "--alpha", "0.3", "--mu", "1",
              "--format", "csv")
    table = rows(res.stdout)
    assert list(table[0].keys()) == ["stage", "event", "a_star", "c_star", "P_star", "gbar"]
    events = [(int(r["stage"]), int(r["event"])) for r in table]
    assert events == [(1, 10), (1, 3), (1, 4), (1, 11), (1, 3), (1, 4), (1, 5),
                      (2, 6), (2, 3), (2, 4), (2, 12), (2, 3), (2, 4), (2, 13)]
    for start, end in zip(table, table[1:]):
        if start["event"] == "3":          # a jump keeps the mean gap
            assert end["event"] == "4"
            assert float(end["gbar"]) == pytest.approx(float(start["gbar"]), abs=1e-12)
    header = run(cli, "path", "--control", "gap", "--model", "md", "--alpha", "0.3",
                 "--mu", "1").stdout
    w_line = [line for line in header.splitlines() if line.startswith("# W* = ")]
    assert len(w_line) == 1
    w_star = float(w_line[0].split()[3])
    assert 0.0 < w_star < 0.01


def test_path_control_gap_westergaard_has_no_hysteresis(cli):
    res = run(cli, "path", "--control", "gap", "--model", "westergaard")
    assert "# W* = 0.0000000000000000E+000" in res.stdout


def test_path_control_load_is_the_default(cli):
    assert run(cli, "path", "--control", "load").stdout == run(cli, "path").stdout


@pytest.mark.parametrize("args, needle", [
    (["path", "--control", "force"], "--control"),
    (["branch", "--control", "gap"], "--control"),
])
def test_control_usage_errors(cli, args, needle):
    res = run(cli, *args, check=False)
    assert res.returncode == 2
    assert needle in res.stderr
    assert res.stdout == ""


def test_gaplaw_table(cli):
    res = run(cli, "gaplaw", "--model", "md", "--alpha", "0.3", "--mu", "1",
              "--gbar-range", "0:1.5:31", "--format", "csv")
    table = rows(res.stdout)
    assert len(table) == 31
    assert list(table[0].keys()) == ["gbar", "P_approach", "P_retract", "dPdg_approach",
                                     "dPdg_retract"]
    assert table[0]["dPdg_approach"] == "-Infinity"          # full contact
    last = table[-1]                                           # beyond the interaction
    assert float(last["P_approach"]) == 0.0 and float(last["P_retract"]) == 0.0
    # retraction is at least as tensile as approach (W* >= 0), and differs inside loops
    diffs = [float(r["P_approach"]) - float(r["P_retract"]) for r in table]
    assert min(diffs) >= -1e-12 and max(diffs) > 1e-3


def test_gaplaw_westergaard_approach_curve(cli):
    res = run(cli, "gaplaw", "--model", "westergaard", "--gbar-range", "0.05:0.95:10",
              "--format", "csv")
    for r in rows(res.stdout):
        g, p = float(r["gbar"]), float(r["P_approach"])
        assert 1 - p + p * math.log(p) == pytest.approx(g, abs=1e-13)
        assert r["P_approach"] == r["P_retract"]


@pytest.mark.parametrize("args, needle", [
    (["gaplaw", "--model", "dw"], "--gbar-range"),
    (["gaplaw", "--gbar-range", "1:0:3"], "--gbar-range"),
    (["gaplaw", "--gbar-range", "0:1:x"], "--gbar-range"),
    (["point", "--a-star", "0.1", "--gbar-range", "0:1:3"], "--gbar-range"),
])
def test_gaplaw_usage_errors(cli, args, needle):
    res = run(cli, *args, check=False)
    assert res.returncode == 2
    assert needle in res.stderr
    assert res.stdout == ""


def test_critical_control_gap_columns_and_identities(cli):
    # issue 11 item 3: critical values under mean-gap control
    res = run(cli, "critical", "--control", "gap", "--model", "md", "--alpha", "0.3",
              "--mu", "1,5", "--format", "csv")
    table = rows(res.stdout)
    assert list(table[0].keys()) == [
        "alpha", "mu", "g_touch", "P_jump_in", "a_jump_in", "g_contact", "P_min", "g_P_min",
        "a_P_min", "g_contact_lost", "P_contact_lost", "g_interaction_lost"]
    load = rows(run(cli, "critical", "--model", "md", "--alpha", "0.3", "--mu", "1,5",
                    "--format", "csv").stdout)
    for gap_row, load_row in zip(table, load):
        # the most tensile load on retraction is the load-control pull-off
        assert float(gap_row["P_min"]) == pytest.approx(float(load_row["P_pf"]), rel=1e-12)
    path = rows(run(cli, "path", "--control", "gap", "--model", "md", "--alpha", "0.3",
                    "--mu", "1", "--format", "csv").stdout)
    assert float(table[0]["g_touch"]) == float(path[0]["gbar"])
    assert float(table[0]["g_interaction_lost"]) == float(path[-1]["gbar"])
    header = run(cli, "critical", "--control", "gap").stdout
    for name in ("g_touch:", "P_min, g_P_min, a_P_min:", "g_interaction_lost:"):
        assert f"# {name}" in header


def test_critical_control_gap_westergaard_and_jkr(cli):
    west = rows(run(cli, "critical", "--control", "gap", "--model", "westergaard",
                    "--format", "csv").stdout)[0]
    assert float(west["g_touch"]) == 1.0 and float(west["P_jump_in"]) == 0.0
    assert float(west["g_contact_lost"]) == 1.0 and float(west["P_min"]) == 0.0
    jkr = rows(run(cli, "critical", "--control", "gap", "--model", "jkr",
                   "--format", "csv").stdout)[0]
    assert jkr["P_min"] == "-Infinity"


def test_critical_control_gap_bad_input(cli):
    res = run(cli, "critical", "--control", "gap", "--mu", "1,-2", check=False)
    assert res.returncode == 2 and "mu" in res.stderr and res.stdout == ""
    res = run(cli, "critical", "--control", "gap", "--alpha", "nan", check=False)
    assert res.returncode == 2 and "alpha" in res.stderr
    res = run(cli, "critical", "--control", "shear", check=False)
    assert res.returncode == 2 and "--control" in res.stderr


# --- portability: help per subcommand, json, table names line, SI units, progress -------

SUBCOMMANDS = ["branch", "point", "profile", "path", "gaplaw", "critical", "map"]


@pytest.mark.parametrize("sub", SUBCOMMANDS)
def test_subcommand_help(cli, sub):
    # `SUB --help` printed the global help; now it and `help SUB` print SUB's own
    a = run(cli, sub, "--help").stdout
    assert a == run(cli, "help", sub).stdout
    assert a.startswith(f"Usage: wavyadhesion {sub}")
    assert "Columns" in a and "Example" in a
    assert a != run(cli, "--help").stdout


def test_help_without_subcommand_is_global(cli):
    text = run(cli, "--help").stdout
    assert run(cli, "help").stdout == text
    assert "Subcommands:" in text and "help [SUBCOMMAND]" in text and "json" in text
    for args in (["help", "bogus"], ["help", "point", "branch"]):
        res = run(cli, *args, check=False)
        assert res.returncode == 2 and res.stdout == "" and "help" in res.stderr


def strict_json(text):
    """json.loads refusing NaN/Infinity literals (they are not JSON)."""
    def refuse(name):
        raise ValueError(f"non-standard JSON constant {name}")
    return json.loads(text, parse_constant=refuse)


def table_values(text):
    """The numeric rows of the table format (what list-directed READ sees)."""
    return [[float(v) for v in l.split()] for l in text.splitlines()
            if l.strip() and not l.startswith("#")]


@pytest.mark.parametrize("args", [
    ["point", "--model", "md", "--a-star", "0.1,0.2,0.3"],
    ["branch", "--model", "dw", "--alpha", "0.3", "--mu", "5"],
    ["profile", "--model", "md", "--a-star", "0.2", "--n", "11"],
    ["path", "--alpha", "0.3", "--mu", "5"],
    ["path", "--control", "gap", "--model", "md"],
    ["gaplaw", "--model", "md", "--gbar-range", "0:1.5:31"],
    ["critical", "--model", "jkr", "--alpha", "0.3,1", "--mu", "0,1"],
    ["critical", "--control", "gap", "--model", "md", "--mu", "1,5"],
    ["map", "--model", "dw", "--alpha", "0.3,0.31"],
])
def test_json_is_strict_and_holds_the_table(cli, args):
    doc = strict_json(run(cli, *args, "--format", "json").stdout)
    table = run(cli, *args).stdout
    assert doc["program"] == "wavyadhesion" and doc["subcommand"] == args[0]
    assert doc["version"] == run(cli, "--version").stdout.split()[1]
    assert f"# model: {doc['model']}" in table
    assert doc["columns"] == table.splitlines()[0][2:].split()
    assert doc["n_rows"] == len(table_values(table))
    # every value equals the table's (non-finite ones are the strings float() reads)
    for k, name in enumerate(doc["columns"]):
        got = [float(v) for v in doc["data"][name]]
        want = [row[k] for row in table_values(table)]
        assert len(got) == len(want)
        for g, w in zip(got, want):
            assert (math.isnan(g) and math.isnan(w)) or g == w
    # the header notes are in the document (mechanism changes included)
    notes = [l[2:] for l in table.splitlines()[1:] if l.startswith("# ") and
             not l.startswith(("# columns:", "# wavyadhesion", "# model:", "# alpha =",
                               "# Sigma0 ="))]
    assert [n.rstrip() for n in notes] == [n.rstrip() for n in doc["notes"]]
    if args[0] not in ("critical", "map"):
        p = doc["parameters"]
        assert f"# alpha = {p['alpha']:.16E}"[:12] in table.replace("E+0", "E+").replace("E-0", "E-") \
            or float(table.split("# alpha = ")[1].split()[0]) == p["alpha"]
        assert set(p) == {"alpha", "mu", "Sigma0", "Dcod"}


def test_json_metadata_values(cli):
    path = strict_json(run(cli, "path", "--alpha", "0.3", "--mu", "5", "--format", "json").stdout)
    v = path["values"]
    assert v["jump_rows"] == [1, 3, 6]
    assert v["jump_energies"][0] == "NaN" and v["jump_energies"][2] == "NaN"
    assert v["jump_energies"][1] == pytest.approx(9.1834906501750517e-3, rel=1e-9)
    assert v["P_fc"] == max(path["data"]["P_star"])
    gap = strict_json(run(cli, "path", "--control", "gap", "--model", "md", "--format",
                          "json").stdout)
    text = run(cli, "path", "--control", "gap", "--model", "md").stdout
    w = float([l for l in text.splitlines() if l.startswith("# W* = ")][0].split()[3])
    assert gap["values"]["W_star"] == w
    jkr = strict_json(run(cli, "critical", "--model", "jkr", "--format", "json").stdout)
    assert jkr["data"]["P_pf"] == ["-Infinity"] and jkr["values"]["rows_failed"] == 0
    assert "Infinity" in jkr["nonfinite"]
    assert float(jkr["data"]["P_pf"][0]) == -math.inf
    crit = strict_json(run(cli, "critical", "--model", "dw", "--alpha", "0.3", "--mu-range",
                           "1:10:5:log", "--format", "json").stdout)
    assert any("P_fc: gradual -> jump case 1" in n for n in crit["notes"])


def test_json_output_file_and_failure(cli, tmp_path):
    out = tmp_path / "t.json"
    run(cli, "point", "--a-star", "0.2", "--format", "json", "--output", str(out))
    assert strict_json(out.read_text())["data"]["a_star"] == [0.2]
    res = run(cli, "point", "--a-star", "0.7", "--format", "json", check=False)
    assert res.returncode == 2 and res.stdout == ""


@pytest.mark.parametrize("args", [
    ["point", "--model", "md", "--a-star", "0.1,0.2,0.3"],
    ["branch", "--model", "md"],
    ["critical", "--model", "jkr", "--mu", "0,1"],
    ["path", "--control", "gap"],
])
def test_table_first_line_names_the_columns_for_numpy(cli, tmp_path, args):
    np = pytest.importorskip("numpy")
    out = tmp_path / "t.txt"
    run(cli, *args, "--output", str(out))
    csv_table = rows(run(cli, *args, "--format", "csv").stdout)
    data = np.genfromtxt(out, names=True)           # the documented call, no other option
    data = np.atleast_1d(data)
    assert list(data.dtype.names) == list(csv_table[0].keys())
    for name in data.dtype.names:
        want = [float(r[name]) for r in csv_table]
        assert data[name].tolist() == pytest.approx(want, rel=0, abs=0, nan_ok=True)


def test_table_reads_with_pandas(cli, tmp_path):
    pd = pytest.importorskip("pandas")
    out = tmp_path / "t.txt"
    run(cli, "branch", "--model", "md", "--output", str(out))
    # the call documented in doc/user-guide.md
    names = open(out).readline().lstrip("#").split()
    frame = pd.read_csv(out, sep=r"\s+", comment="#", header=None, names=names)
    csv_table = rows(run(cli, "branch", "--model", "md", "--format", "csv").stdout)
    assert list(frame.columns) == list(csv_table[0].keys()) and len(frame) == len(csv_table)
    assert frame["P_star"].tolist() == [float(r["P_star"]) for r in csv_table]


def test_table_reads_with_fortran_list_directed_read(cli, tmp_path):
    # a legacy reader: skip lines starting with '#', read the rest with READ(line, *)
    import shutil
    fc = shutil.which("gfortran")
    if not fc:
        pytest.skip("no gfortran")
    src = tmp_path / "reader.f90"
    src.write_text("""program reader
   implicit none
   character(len=1000) :: line
   double precision :: v(8), total
   integer :: ios, n
   n = 0
   total = 0
   do
      read (*, '(a)', iostat=ios) line
      if (ios /= 0) exit
      if (line(1:1) == '#') cycle
      read (line, *) v
      n = n + 1
      total = total + v(3)
   end do
   print '(i0, 1x, es24.16)', n, total
end program reader
""")
    subprocess.run([fc, str(src), "-o", str(tmp_path / "reader")], check=True)
    table = run(cli, "branch", "--model", "dw").stdout
    res = subprocess.run([str(tmp_path / "reader")], input=table, capture_output=True,
                         text=True, check=True)
    n, total = res.stdout.split()
    data = table_values(table)
    assert int(n) == len(data)
    assert float(total) == pytest.approx(sum(r[2] for r in data), rel=1e-14)


SI_INPUT = ["--Estar", "1e9", "--period", "1e-5", "--amplitude", "1e-7",
            "--work-of-adhesion", "0.05", "--peak-stress", "1e7"]


def test_si_header_gives_the_scales(cli):
    # hand computation: p* = pi E* Delta / L = pi 1e9 1e-7 / 1e-5 = pi 1e7 Pa
    pstar = math.pi * 1e9 * 1e-7 / 1e-5
    head = run(cli, "branch", *SI_INPUT).stdout
    line = [l for l in head.splitlines() if l.startswith("# SI scales: E*")][0]
    assert float(line.split("p* = pi E* Delta/L = ")[1].split()[0]) == pytest.approx(pstar, rel=1e-15)
    assert float(line.split("p* L = ")[1].split()[0]) == pytest.approx(pstar * 1e-5, rel=1e-15)
    line = [l for l in head.splitlines() if l.startswith("# SI scales: L")][0]
    assert float(line.split("L = ")[1].split()[0]) == 1e-5
    assert float(line.split("Delta = ")[1].split()[0]) == 1e-7
    assert float(line.split("p* Delta = ")[1].split()[0]) == pytest.approx(pstar * 1e-7, rel=1e-15)
    doc = strict_json(run(cli, "branch", *SI_INPUT, "--format", "json").stdout)
    assert doc["scales"]["p_star_Pa"] == pytest.approx(pstar, rel=1e-15)
    assert "# SI scales" not in run(cli, "branch").stdout


def test_units_si_columns_match_a_hand_computation(cli):
    pstar, length, delta = math.pi * 1e7, 1e-5, 1e-7
    table = rows(run(cli, "point", *SI_INPUT, "--a-star", "0.1,0.2", "--units", "si",
                     "--format", "csv").stdout)
    assert list(table[0].keys()) == ["a_star", "c_star", "P_star", "zone_case", "gbar",
                                     "a_m", "c_m", "P_Pa", "gbar_m"]
    for r in table:
        assert float(r["a_m"]) == pytest.approx(float(r["a_star"]) * length, rel=1e-15)
        assert float(r["c_m"]) == pytest.approx(float(r["c_star"]) * length, rel=1e-15)
        assert float(r["P_Pa"]) == pytest.approx(float(r["P_star"]) * pstar, rel=1e-15)
        assert float(r["gbar_m"]) == pytest.approx(float(r["gbar"]) * delta, rel=1e-15)
    law = rows(run(cli, "gaplaw", *SI_INPUT, "--gbar-range", "0.5:1:3", "--units", "si",
                   "--format", "csv").stdout)
    for r in law:
        assert float(r["dPdg_approach_Pa_per_m"]) == pytest.approx(
            float(r["dPdg_approach"]) * pstar / delta, rel=1e-15)
    gap = run(cli, "path", "--control", "gap", "--model", "md", *SI_INPUT, "--units", "si").stdout
    w_star = float([l for l in gap.splitlines() if l.startswith("# W* = ")][0].split()[3])
    w_si = [l for l in gap.splitlines() if l.startswith("# SI: W_J_per_m2 = ")][0]
    assert float(w_si.split()[4]) == pytest.approx(w_star * pstar * delta, rel=1e-15)
    assert w_si.endswith(" J/m^2")
    doc = strict_json(run(cli, "profile", *SI_INPUT, "--a-star", "0.2", "--n", "5", "--units",
                          "si", "--format", "json").stdout)
    assert doc["units"] == {"x_m": "m", "traction_Pa": "Pa", "gap_m": "m"}
    assert doc["data"]["x_m"][0] == pytest.approx(-0.5 * length, rel=1e-15)


def test_units_si_needs_si_input(cli):
    res = run(cli, "point", "--a-star", "0.2", "--units", "si", check=False)
    assert res.returncode == 2 and "--units si needs SI input" in res.stderr
    res = run(cli, "point", "--a-star", "0.2", "--units", "metric", check=False)
    assert res.returncode == 2 and "--units" in res.stderr


def run_on_terminal(cli, *args):
    """Run with standard error on a pseudo-terminal; returns (stdout, stderr text)."""
    import pty
    import tempfile
    master, slave = pty.openpty()
    out_file = tempfile.TemporaryFile()           # not a pipe: the table may be large
    proc = subprocess.Popen([cli, *args], stdout=out_file, stderr=slave)
    os.close(slave)
    err = b""
    while True:
        try:
            chunk = os.read(master, 4096)
        except OSError:                       # EIO: the child closed the terminal
            break
        if not chunk:
            break
        err += chunk
    proc.wait(timeout=300)
    os.close(master)
    out_file.seek(0)
    out = out_file.read()
    out_file.close()
    assert proc.returncode == 0, err
    return out.decode(), err.decode()


def test_progress_on_a_terminal_by_point(cli):
    # MD critical over 2000 mu takes a few seconds: a single line rewritten with \r,
    # counting points, erased at the end; the table itself is unchanged
    args = ["critical", "--model", "md", "--mu-range", "0.001:1000:2000:log"]
    out, err = run_on_terminal(cli, *args)
    assert "critical: " in err and " of 2000 points" in err
    assert "\n" not in err.replace("\r\n", "")      # never a new line of its own
    assert err.rstrip(" ").endswith("\r")            # erased: blanks, back to column 0
    assert out == run(cli, *args).stdout


def test_no_progress_when_stderr_is_not_a_terminal(cli):
    res = run(cli, "critical", "--model", "md", "--mu-range", "0.001:1000:2000:log")
    assert res.stderr == ""


def test_map_says_it_is_computing_on_a_terminal(cli):
    out, err = run_on_terminal(cli, "map", "--model", "dw", "--alpha", "0.3,0.31")
    assert "map: computing the boundaries over 2 alpha" in err
    assert err.rstrip(" ").endswith("\r")
    assert out.splitlines()[0] == "# boundary alpha mu"


# --model lj (the smooth Lennard-Jones model): the reference values are those of the
# Fortran bem suite (test/unit) at alpha = 0.3, mu = 3 and the automatic grid N = 512; the
# CLI must reproduce them to their error estimates.
LJ_P_FC_REF = 0.99600001838
LJ_P_PF_REF = -0.40595099926
LJ_P_FC_PEAK_REF = 0.38642269871      # P_fc_peak (b* = 1/2) there


def test_lj_critical_matches_the_fortran_suite_with_error_columns(cli):
    res = run(cli, "critical", "--model", "lj", "--alpha", "0.3", "--mu", "3")
    lines = res.stdout.splitlines()
    assert "# columns: alpha mu P_fc P_pf P_fc_err P_pf_err P_fc_peak P_fc_peak_err" in lines
    assert any("16/(9 sqrt 3) sigma0" in l for l in lines)
    assert any("(4 alpha^4)^(1/3)/mu" in l for l in lines)
    assert any("N = 512" in l for l in lines)
    assert any("P_fc_peak: load at which b*" in l for l in lines)
    alpha, mu, p_fc, p_pf, fc_err, pf_err, peak, peak_err = map(float, lines[-1].split())
    assert (alpha, mu) == (0.3, 3.0)
    # 1e-11: the rounding of the quoted reference values
    assert abs(p_fc - LJ_P_FC_REF) <= fc_err + 1e-11
    assert abs(p_pf - LJ_P_PF_REF) <= pf_err + 1e-11
    assert 0 < fc_err < 1e-6 and 0 < pf_err < 1e-6
    # b* reaches 1/2 by the snap into full contact: near DW's own snap to full contact
    assert abs(peak - LJ_P_FC_PEAK_REF) <= peak_err + 1e-11 and 0 < peak_err < 1e-4
    dw_row = run(cli, "critical", "--model", "dw", "--alpha", "0.3", "--mu", "3").stdout
    assert abs(peak - float(dw_row.splitlines()[-1].split()[2])) < 2e-3


def test_lj_path_gap_prints_the_cycle_and_w_star(cli):
    res = run(cli, "path", "--model", "lj", "--control", "gap", "--alpha", "0.3", "--mu", "3",
              "--format", "json")
    doc = json.loads(res.stdout)
    assert doc["model"] == "lj"
    v = doc["values"]
    assert v["N"] == 512
    assert 0 < v["W_star_err"] < 1e-3 * v["W_star"]
    assert v["W_fraction"] == pytest.approx(v["W_star"] / (math.pi * 0.3**2 / 2), rel=1e-12)
    cols = doc["data"]
    stage, event = cols["stage"], cols["event"]
    assert set(stage) == {1, 2}
    assert stage == sorted(stage)                 # approach, then retraction
    # every jump keeps gbar*: each jump start is followed by its end at the same gbar*
    g = cols["gbar"]
    for i, e in enumerate(event):
        if e == 3:
            assert event[i + 1] == 4
            assert g[i + 1] == pytest.approx(g[i], rel=1e-9)
    # full contact is reached at P_fc of load control (the end of the trace is shared)
    assert 5 in event and 6 in event


def test_lj_path_load_events_and_header(cli):
    res = run(cli, "path", "--model", "lj", "--alpha", "0.3", "--mu", "3", "--n", "256",
              "--format", "csv")
    table = rows(res.stdout)
    assert list(table[0].keys()) == ["stage", "event", "a_star", "P_star", "gbar"]
    events = [int(r["event"]) for r in table]
    assert events[-1] == 7                         # pull-off ends the unloading
    assert float(table[-1]["P_star"]) == pytest.approx(LJ_P_PF_REF, abs=1e-8)


def test_lj_branch_columns_and_stability(cli):
    res = run(cli, "branch", "--model", "lj", "--alpha", "0.3", "--mu", "3", "--n", "256",
              "--format", "csv")
    table = rows(res.stdout)
    assert list(table[0].keys()) == ["a_star", "b_star", "P_star", "stable", "stable_gap",
                                     "event", "extremum", "gbar", "h_min", "h_max"]
    assert int(table[0]["event"]) == 8 and int(table[-1]["event"]) == 8
    assert float(table[-1]["a_star"]) == 0.5
    for r in table:
        assert float(r["a_star"]) <= float(r["b_star"]) <= 0.5
        assert float(r["h_min"]) <= float(r["gbar"]) <= float(r["h_max"])


def test_lj_profile_file_of_the_sinusoid_gives_the_default(cli, tmp_path):
    """Samples of 1 - cos(2 pi x) at x = j/M are the default profile (to rounding)."""
    f = tmp_path / "wave.txt"
    x = np.arange(64) / 64
    f.write_text("# one period, heights over Delta\n" +
                 "\n".join(repr(float(v)) for v in 1 - np.cos(2 * np.pi * x)) + "\n")
    base = ["critical", "--model", "lj", "--alpha", "0.3", "--mu", "3", "--n", "256",
            "--format", "csv"]
    a = rows(run(cli, *base).stdout)[0]
    b = rows(run(cli, *base, "--profile-file", str(f)).stdout)[0]
    for k in ("P_fc", "P_pf"):
        assert float(b[k]) == pytest.approx(float(a[k]), abs=1e-11)


def test_lj_profile_state(cli):
    res = run(cli, "profile", "--model", "lj", "--alpha", "0.3", "--mu", "1", "--a-star",
              "0.2", "--n", "64", "--format", "json")
    doc = json.loads(res.stdout)
    x = doc["data"]["x_star"]
    assert len(x) == 64 and x[0] == -0.5 and x == sorted(x)
    # the mean traction is the load (compressive positive)
    assert np.mean(doc["data"]["traction"]) == pytest.approx(doc["values"]["P_star"],
                                                                abs=1e-10)
    assert np.mean(doc["data"]["gap"]) == pytest.approx(doc["values"]["gbar"], abs=1e-10)


@pytest.mark.parametrize("args, needle", [
    (["point", "--model", "lj", "--a-star", "0.1"], "point --model lj is not available"),
    (["map", "--model", "lj"], "map --model lj is not available"),
    (["gaplaw", "--model", "lj", "--gbar-range", "0:1:3"], "gaplaw --model lj"),
    (["branch", "--model", "lj", "--n", "7"], "even and >= 8"),
    (["branch", "--model", "dw", "--n", "64"], "--n are only for the profile"),
    (["branch", "--model", "md", "--profile-file", "x"], "--profile-file is only for --model lj"),
    (["branch", "--model", "lj", "--profile-file", "/nonexistent/p.txt"], "cannot open"),
    (["critical", "--model", "lj", "--mu", "0"], "mu must be > 0"),
    (["profile", "--model", "lj", "--a-star", "0.1", "--c-star", "0.2"], "--c-star does not"),
])
def test_lj_what_does_not_apply_exits_2(cli, args, needle):
    res = run(cli, *args, check=False)
    assert res.returncode == 2
    assert needle in res.stderr
    assert res.stdout == ""


@pytest.mark.parametrize("args, alternative", [
    (["point", "--model", "lj", "--a-star", "0.1"], "'profile --model lj --a-star X'"),
    (["map", "--model", "lj"], "'critical --model lj"),
    (["gaplaw", "--model", "lj", "--gbar-range", "0:1:3"], "'branch --model lj'"),
])
def test_lj_refusal_names_the_alternative(cli, args, alternative):
    """point, map and gaplaw refuse --model lj and say which subcommand gives it."""
    res = run(cli, *args, check=False)
    assert res.returncode == 2 and alternative in res.stderr and res.stdout == ""


def test_lj_profile_a_star_ends_and_subnormal(cli):
    """--a-star 0 and 1/2 draw the ends of the load-stable curve (a* = 1/2: full contact,
    every gap within the law's range eps); the smallest subnormal is the state of 0."""
    base = ["profile", "--model", "lj", "--alpha", "0.3", "--mu", "1", "--n", "64",
            "--format", "json"]
    full = json.loads(run(cli, *base, "--a-star", "0.5").stdout)
    eps = (4 * 0.3**4) ** (1 / 3) / 1.0
    assert full["values"]["a_star"] == 0.5 and max(full["data"]["gap"]) <= eps
    zero = json.loads(run(cli, *base, "--a-star", "0").stdout)
    tiny = json.loads(run(cli, *base, "--a-star", "4.9e-324").stdout)
    assert zero["values"] == tiny["values"] and zero["data"] == tiny["data"]
    res = run(cli, *base, "--a-star", "1e300", check=False)
    assert res.returncode == 2 and "--a-star" in res.stderr and "[0, 1/2]" in res.stderr


@pytest.mark.parametrize("args, needle", [
    (["profile", "--model", "lj", "--a-star", "0.2", "--n", "100000"], "16384"),
    (["branch", "--model", "lj", "--n", "20000"], "16384"),
    (["critical", "--model", "lj", "--mu-range", "1:2:2", "--n", "20000"], "16384"),
    (["path", "--model", "lj", "--alpha", "1e-6"], "pass n explicitly"),
])
def test_lj_grid_cap_is_a_usage_error(cli, args, needle):
    """A grid cap exceeded (--n too large, or the automatic grid beyond its cap, which --n
    resolves) is the caller's argument: exit 2 (it was 'output capacity too small', exit 1),
    as the C face's WA_INVALID_ARGUMENT."""
    res = run(cli, *args, check=False)
    assert res.returncode == 2 and needle in res.stderr and res.stdout == ""


def test_lj_critical_row_beyond_the_caps_says_so(cli):
    """A critical row whose (alpha, mu) needs a grid beyond the automatic cap, or whose law's
    range exceeds 1e5 Delta, is a NaN row (exit 1; the other rows are computed) whose reason
    names the solver's caps, not an output array "too small"."""
    for args, needle in ((["--alpha", "0.3", "--mu", "100"], "needs N = "),
                         (["--alpha", "5.5e7", "--mu", "4.8e-5"], "range eps/Delta")):
        res = run(cli, "critical", "--model", "lj", *args, check=False)
        assert res.returncode == 1 and "beyond the solver's caps" in res.stderr
        assert needle in res.stderr and "capacity too small" not in res.stderr
        assert "NaN" in res.stdout.splitlines()[-1]


def test_lj_bad_profile_line_exits_2(cli, tmp_path):
    f = tmp_path / "bad.txt"
    f.write_text("0\n0.5\nabc\n1\n")
    res = run(cli, "branch", "--model", "lj", "--profile-file", str(f), check=False)
    assert res.returncode == 2
    assert "line 3" in res.stderr


def test_lj_branch_header_carries_the_critical_values_with_errors(cli):
    doc = json.loads(run(cli, "branch", "--model", "lj", "--alpha", "0.3", "--mu", "3", "--n",
                         "256", "--format", "json").stdout)
    v = doc["values"]
    assert v["N"] == 256
    assert abs(v["P_fc"] - LJ_P_FC_REF) <= v["P_fc_err"] + 1e-10
    assert abs(v["P_pf"] - LJ_P_PF_REF) <= v["P_pf_err"] + 1e-10
    # the cycle at N/2 = 4 cannot be computed: the estimates are NaN, the curve is written
    doc = json.loads(run(cli, "branch", "--model", "lj", "--alpha", "0.3", "--mu", "3", "--n",
                         "8", "--format", "json").stdout)
    assert doc["values"]["P_fc_err"] == "NaN" and doc["n_rows"] > 0
