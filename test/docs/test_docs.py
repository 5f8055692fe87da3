"""Docs that stay true: README.md and doc/*.md.

1. Numbers quoted in the docs: CLAIMS below lists, for each quoted number, the file, the
   text as quoted with {} where the number goes, and how to compute it (from the command
   line `wavyadhesion`, the fpm release build). The test computes the number, fills in
   the text and asserts that the file contains it. When a number changes, the failure
   shows the text the doc must now contain. Only what a doc quotes is checked (other
   columns of the CLI output may change freely). doc/accuracy-performance.md quotes one
   recorded study run (study/results/) and is not recomputed here.
2. Commands quoted in the docs: a code block directly after the line
   `<!-- docs-test: run -->` is run line by line (from the repository root, with the
   release `wavyadhesion` first on PATH and .venv/bin next); each must exit 0.
3. The docs cite no file outside the repository and no build/gfortran_* directory, and
   `fpm test` names a suite only after `--`.
4. The FORD API reference builds without warnings, with a*, P* not turned into emphasis;
   the umbrella's page lists every public name; internal modules are hidden and the
   procedure list holds the public API only; every argument of a public routine is
   documented; nothing in the tree cites a file outside the repository.
5. One version everywhere: VERSION, `wavyadhesion --version`, Python __version__,
   CITATION.cff, CHANGELOG.md (the C `wa_version()` is checked by `fpm test capi`).
"""
import functools
import os
import pathlib
import re
import shlex
import subprocess

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
DOCS = [REPO / "README.md", *sorted((REPO / "doc").glob("*.md"))]
VERSION = (REPO / "VERSION").read_text().strip()


@functools.lru_cache(maxsize=None)
def cli_path():
    exe = os.environ.get("WAVYADHESION_CLI")
    if not exe:
        out = subprocess.run(["fpm", "run", "--profile", "release", "--runner", "echo",
                              "wavyadhesion"], cwd=REPO, check=True, capture_output=True,
                             text=True).stdout
        exe = out.strip().splitlines()[-1].strip()
    return exe


@functools.lru_cache(maxsize=None)
def cli(*args):
    res = subprocess.run([cli_path(), *args], capture_output=True, text=True, timeout=120)
    assert res.returncode == 0, f"wavyadhesion {' '.join(args)}: {res.stderr}"
    return res.stdout


def branch_points(model, alpha="0.3", mu="1"):
    """Number of points of `wavyadhesion branch` (non-comment rows)."""
    out = cli("branch", "--model", model, "--alpha", alpha, "--mu", mu)
    return sum(1 for line in out.splitlines() if line.strip() and not line.startswith("#"))


def critical(model, alpha, mu):
    """(P_fc, P_pf) from `wavyadhesion critical` (the last two columns of the last row)."""
    out = cli("critical", "--model", model, "--alpha", alpha, "--mu", mu)
    row = [line for line in out.splitlines() if line.strip() and not line.startswith("#")][-1]
    fields = row.split()
    return float(fields[-2]), float(fields[-1])


def python_value(expression):
    """str() of a Python expression over the installed package (``wa``), as a docs
    quote of the Python interface (the package is imported only when a claim needs it)."""
    import wavyadhesion as wa
    return str(eval(expression, {"wa": wa}))


def python_error(expression):
    """The exception a Python expression over the installed package (``wa``) raises, as
    "ClassName: message" (a docs quote of an error of the Python interface)."""
    import wavyadhesion as wa
    try:
        eval(expression, {"wa": wa})
    except wa.WavyAdhesionError as exc:
        return f"{type(exc).__name__}: {exc}"
    raise AssertionError(f"{expression} raised nothing")


@functools.lru_cache(maxsize=None)
def example_output(script):
    """What a python/examples script prints (run with the .venv's Python, its figure
    written to a temporary directory)."""
    import sys
    import tempfile
    with tempfile.TemporaryDirectory() as out:
        res = subprocess.run([sys.executable, str(REPO / script), "--out", out],
                             capture_output=True, text=True, timeout=300)
    assert res.returncode == 0, res.stderr
    return res.stdout


def fmt12(x):
    return f"{x:.12f}"


def gap_critical_value(model, alpha, mu, column):
    """One value of `wavyadhesion critical --control gap` (column as in its header)."""
    out = cli("critical", "--control", "gap", "--model", model, "--alpha", alpha, "--mu", mu)
    names = [line for line in out.splitlines() if line.startswith("# columns:")][0].split()[2:]
    row = [line for line in out.splitlines() if line.strip() and not line.startswith("#")][-1]
    return float(row.split()[names.index(column)])


def lj_value(column, *args):
    """A column of `wavyadhesion critical --model lj` (load control; `--control gap` with
    args "--control", "gap") at alpha = 0.3, mu = 3, by its name in the header."""
    out = cli("critical", "--model", "lj", "--alpha", "0.3", "--mu", "3", *args)
    names = [line for line in out.splitlines() if line.startswith("# columns:")][0].split()[2:]
    row = [line for line in out.splitlines() if line.strip() and not line.startswith("#")][-1]
    return float(row.split()[names.index(column)])


def gap_w_star(model, alpha, mu):
    """W* of `wavyadhesion path --control gap`."""
    out = cli("path", "--control", "gap", "--model", model, "--alpha", alpha, "--mu", mu)
    return float(re.search(r"# W\* = (\S+)", out).group(1))


def sci(x, digits):
    """x as quoted in prose: 1.685963e-6, −4.99163e-7 (a typographic minus on the mantissa)."""
    mantissa, exponent = f"{x:.{digits}e}".split("e")
    return mantissa.replace("-", "−") + f"e{int(exponent)}"


# the reproducers of the gap-control fixes (doc/theory.md, "Gap control")
GAP_PF_DW = ("dw", "3.2953421004685887e-05", "843.70633645969394")
GAP_FLOOR_MD = ("md", "0.0060257438729055621", "1.406552182111195")


@functools.lru_cache(maxsize=None)
def map_table():
    """The saved model-error map, doc/figures/model_error_map.csv (one dict per cell; made by
    tools/figures/plot_model_error.py, checked by test_model_error_map.py): the numbers
    doc/user-guide.md quotes from it, without recomputing the map."""
    import csv
    with open(REPO / "doc" / "figures" / "model_error_map.csv", newline="") as fh:
        return tuple(csv.DictReader(fh))


def map_cells(status="ok", alpha=(0, float("inf")), mu=(0, float("inf"))):
    """The cells of that LJ status with alpha and mu in the closed ranges given."""
    return [c for c in map_table() if c["lj_status"] == status
            and alpha[0] <= float(c["alpha"]) <= alpha[1] and mu[0] <= float(c["mu"]) <= mu[1]]


def map_within(model, q, level, **ranges):
    """How many "ok" cells (in the ranges) have |model - LJ|/|LJ| <= level."""
    return sum(1 for c in map_cells(**ranges) if float(c[f"{model}_rel_{q}"]) <= level)


def map_seconds(n, how=None):
    """Median (or how(...)) of LJ's CPU seconds over the ok cells at grid N = n."""
    import statistics
    return (how or statistics.median)(float(c["lj_seconds"]) for c in map_cells()
                                      if int(c["lj_N"]) == n)


def map_row(model):
    """A row of the guide's agreement table: per quantity the ok cells within 1/5/20 %."""
    return " | ".join(" / ".join(str(map_within(model, q, lv)) for lv in (0.01, 0.05, 0.2))
                      for q in ("P_fc", "P_pf", "W_star"))


def map_mechanism(model, *mechanisms):
    """The ok cells where the model reaches full contact by one of these mechanisms."""
    return [c for c in map_cells() if c[f"{model}_fc_mechanism"] in mechanisms]


def map_extreme(model, q, how, **ranges):
    """how (min or max) of the relative error over the ok cells in the ranges."""
    return how(float(c[f"{model}_rel_{q}"]) for c in map_cells(**ranges))


def map_w_ratio(model):
    """The smallest model W* / LJ W* over the ok cells where LJ's W* is not zero."""
    return min(float(c[f"{model}_W_star"]) / float(c["lj_W_star"]) for c in map_cells()
               if float(c[f"{model}_rel_W_star"]) != float("inf"))


# the corners of the paper's statements (bounds a little wider than the grid points)
SMALL_ALPHA_LARGE_MU = dict(alpha=(0.0099, 0.101), mu=(2.5, 101.0))
LARGE_ALPHA_SMALL_MU = dict(alpha=(0.99, 10.1), mu=(0.0099, 0.101))


# (file, quoted text with {} for the number, function giving the number as it is quoted)
CLAIMS = [
    ("doc/c-api.md", "α = 0.3, μ = 5 ({} points)", lambda: branch_points("dw", "0.3", "5")),
    ("doc/c-api.md", "4.2 ms for MD ({} points)", lambda: branch_points("md", "0.3", "5")),
    ("doc/c-api.md", "the branch has {} points (the", lambda: branch_points("dw", "0.3", "5")),
    ("doc/c-api.md", "status 0, {} points", lambda: branch_points("dw", "0.3", "5")),
    ("doc/c-api.md", "DW:  P_fc = {}", lambda: fmt12(critical("dw", "0.3", "5")[0])),
    ("doc/c-api.md", "P_pf = {}\nJKR", lambda: fmt12(critical("dw", "0.3", "5")[1])),
    ("doc/c-api.md", "the closed form at {} points", lambda: branch_points("westergaard")),
    ("doc/python.md", "{} ['branch_end', 'fold', 'fold', 'switch', 'branch_end']",
     lambda: branch_points("dw", "0.3", "5")),
    ("doc/python.md", "closed form at {} points", lambda: branch_points("westergaard")),
    ("doc/python.md", 'load_path("lj", 0.3, 10.0)`\nraises `{}`',
     lambda: python_error('wa.load_path("lj", 0.3, 10.0)')),
    ("doc/python.md", "and `n=16388` (beyond the even grid's 16384) `{}`",
     lambda: python_error('wa.load_path("lj", 0.3, 3.0, n=16388)')),
    ("doc/python.md", "It prints\n\n```\n{}\n```", lambda: "\n".join(
        example_output("python/examples/si_cycle.py").splitlines()[:3])),
    ("doc/python.md", 'repr(wa.trace_branch("dw", 0.3, 5.0))` is\n`{}`',
     lambda: python_value('repr(wa.trace_branch("dw", 0.3, 5.0))')),
    ("doc/user-guide.md", "closed forms ({} points", lambda: branch_points("westergaard")),
    ("doc/user-guide.md", "with P_fc = {} (error", lambda: f"{lj_value('P_fc'):.10f}"),
    ("doc/user-guide.md", "estimate {}) and P_pf", lambda: f"{lj_value('P_fc_err'):.1e}"),
    ("doc/user-guide.md", "and P_fc_peak = {}, the load", lambda: f"{lj_value('P_fc_peak'):.10f}"),
    ("doc/c-api.md", "P_fc_peak = {}, the snap load", lambda: f"{lj_value('P_fc_peak'):.10f}"),
    ("doc/user-guide.md", "and MD's P_fc, their b* = 1/2, are\n{}",
     lambda: " and ".join(f"{critical(m, '0.3', '3')[0]:.4f}" for m in ("dw", "md"))),
    ("doc/theory.md", "P_fc,peak* is its snap load\n{}", lambda: f"{lj_value('P_fc_peak'):.5f}"),
    ("doc/theory.md", "LJ's P_fc* is {} while", lambda: f"{lj_value('P_fc'):.3f}"),
    ("doc/theory.md", "against DW's and MD's {} (their snap",
     lambda: " and ".join(f"{critical(m, '0.3', '3')[0]:.4f}" for m in ("dw", "md"))),
    ("doc/user-guide.md", "and P_pf = {} (", lambda: f"{lj_value('P_pf'):.10f}"),
    ("doc/user-guide.md", "({}) at N = 512", lambda: f"{lj_value('P_pf_err'):.1e}"),
    ("doc/user-guide.md", "and W* = {} (error", lambda: sci(gap_w_star("lj", "0.3", "3"), 4)),
    ("doc/user-guide.md", "(error estimate {}) in units of p*Δ",
     lambda: f"{lj_value('W_star_err', '--control', 'gap'):.1e}".replace("e-07", "e-7")),
    # the model-error map: from its saved table (map_table), not recomputed
    ("doc/user-guide.md", "they lose more, from {} (DW) or", lambda: f"{map_w_ratio('dw'):.1f}"),
    ("doc/user-guide.md", "(DW) or {} (MD) times as much", lambda: f"{map_w_ratio('md'):.1f}"),
    ("doc/user-guide.md", '**Cells and cost.** Of the {} cells, ',
     lambda: str(len(map_table()))),
    ("doc/user-guide.md", ' cells, {} are ok, ',
     lambda: str(len(map_cells("ok")))),
    ("doc/user-guide.md", ' are ok, {} unresolved and',
     lambda: str(len(map_cells("unresolved")))),
    ("doc/user-guide.md", ' unresolved and {} failed. Unreso',
     lambda: str(len(map_cells("failed")))),
    ("doc/user-guide.md", ' needs a grid beyond the cap, N = 8192 ({} cells), 16384 ',
     lambda: str(sum("needs N = 8192 " in c["message"] for c in map_table()))),
    ("doc/user-guide.md", ' cells), 16384 ({} cells) or',
     lambda: str(sum("needs N = 16384 " in c["message"] for c in map_table()))),
    ("doc/user-guide.md", 'more ({} cells, beyond ',
     lambda: str(len(map_cells("unresolved")) - sum(any(f"needs N = {n} " in c["message"] for n in (8192, 16384)) for c in map_table()))),
    ("doc/user-guide.md", "cell (the median over the map's cells), {} at N = 128, ",
     lambda: str(f"{map_seconds(128):.2g}")),
    ("doc/user-guide.md", ' at N = 128, {} at N = 512, ',
     lambda: str(f"{map_seconds(512):.2g}")),
    ("doc/user-guide.md", ' at N = 512, {} at N = 1024,',
     lambda: str(f"{map_seconds(1024):.2g}")),
    ("doc/user-guide.md", '{} at N = 2048 an',
     lambda: str(f"{map_seconds(2048):.2g}")),
    ("doc/user-guide.md", ' at N = 2048 and {} at N = 4096 (t',
     lambda: str(f"{map_seconds(4096):.2g}")),
    ("doc/user-guide.md", ' at N = 4096 (the slowest {}); one cell at ',
     lambda: str(f"{map_seconds(4096, max):.2g}")),
    ("doc/user-guide.md", " unresolved and {} failed. Unresolved",
     lambda: str(len(map_cells("failed")))),
    ("doc/user-guide.md", 'suggests (at N = 4096 the slowest takes {}',
     lambda: str(f"{map_seconds(4096, max) / map_seconds(4096):.1f}")),
    ("doc/user-guide.md", 'eement, per quantity**: how many of the {} ok cells are w',
     lambda: str(len(map_cells("ok")))),
    ("doc/user-guide.md", '| DW | {} |',
     lambda: str(map_row("dw"))),
    ("doc/user-guide.md", '| MD | {} |',
     lambda: str(map_row("md"))),
    ("doc/user-guide.md", "a jump from c* < 1/2 ({} ok cells), LJ'",
     lambda: str(len(map_mechanism("dw", "jump_case1", "jump_case2")))),
    ("doc/user-guide.md", " LJ's P_fc_peak is its own snap load in {} of them (MD:",
     lambda: str(sum(c["lj_P_fc_peak"] == c["lj_P_snap"] for c in map_mechanism("dw", "jump_case1", "jump_case2")))),
    ("doc/user-guide.md", '{} of ',
     lambda: str(sum(c["lj_P_fc_peak"] == c["lj_P_snap"] for c in map_mechanism("md", "jump_case1", "jump_case2")))),
    ("doc/user-guide.md", ' of {}); where DW sna',
     lambda: str(len(map_mechanism("md", "jump_case1", "jump_case2")))),
    ("doc/user-guide.md", "e DW snaps into full contact at P* = 0 ({} ok cells), LJ'",
     lambda: str(len(map_mechanism("dw", "snap")))),
    ("doc/user-guide.md", 'in {} of them (its f',
     lambda: str(sum(abs(float(c["lj_P_fc_peak"])) < 1e-12 for c in map_mechanism("dw", "snap")))),
    ("doc/user-guide.md", 'e relative error is infinite there (DW: {} cells, MD: ',
     lambda: str(sum(float(c["dw_rel_P_fc"]) == float("inf") for c in map_cells()))),
    ("doc/user-guide.md", ' cells, MD: {} cells, marked ',
     lambda: str(sum(float(c["md_rel_P_fc"]) == float("inf") for c in map_cells()))),
    ("doc/user-guide.md", 'exactly) DW and MD still lose energy (inf, {} cells',
     lambda: str(sum(float(c["dw_rel_W_star"]) == float("inf") for c in map_cells()))),
    ("doc/user-guide.md", 'e reachable part, α ≤ 0.1 with μ ≥ 2.5 ({} ok cells; at α',
     lambda: str(len(map_cells(**SMALL_ALPHA_LARGE_MU)))),
    ("doc/user-guide.md", ' is beyond the cap), P_fc agrees within {} (DW)',
     lambda: str(f"{map_extreme('dw', 'P_fc', max, **SMALL_ALPHA_LARGE_MU):.2%}")),
    ("doc/user-guide.md", 'and {} (MD), P_pf wit',
     lambda: str(f"{map_extreme('md', 'P_fc', max, **SMALL_ALPHA_LARGE_MU):.2%}")),
    ("doc/user-guide.md", ' (MD), P_pf within {} (DW) and ',
     lambda: str(f"{map_extreme('dw', 'P_pf', max, **SMALL_ALPHA_LARGE_MU):.1%}")),
    ("doc/user-guide.md", ' (DW) and {} (MD), the erro',
     lambda: str(f"{map_extreme('md', 'P_pf', max, **SMALL_ALPHA_LARGE_MU):.1%}")),
    ("doc/user-guide.md", "It does not hold for W*: DW's is off by {} to ",
     lambda: str(f"{map_extreme('dw', 'W_star', min, **SMALL_ALPHA_LARGE_MU):.0%}")),
    ("doc/user-guide.md", " to {} there, MD's by",
     lambda: str(f"{map_extreme('dw', 'W_star', max, **SMALL_ALPHA_LARGE_MU):.0%}")),
    ("doc/user-guide.md", '{} to ',
     lambda: str(f"{map_extreme('md', 'W_star', min, **SMALL_ALPHA_LARGE_MU):.0%}")),
    ("doc/user-guide.md", ' to {}. The corner th',
     lambda: str(f"{map_extreme('md', 'W_star', max, **SMALL_ALPHA_LARGE_MU):.0%}")),
    ("doc/user-guide.md", "appreciably.* For α ≥ 1, μ ≤ 0.1 ({} ok cells) DW's",
     lambda: str(len(map_cells(**LARGE_ALPHA_SMALL_MU)))),
    ("doc/user-guide.md", " ok cells) DW's P_pf is off by {} to ",
     lambda: str(f"{map_extreme('dw', 'P_pf', min, **LARGE_ALPHA_SMALL_MU):.1%}")),
    ("doc/user-guide.md", ' to {} (about',
     lambda: str(f"{map_extreme('dw', 'P_pf', max, **LARGE_ALPHA_SMALL_MU):.1%}")),
    ("doc/user-guide.md", " kind for both models (inf in every cell{}: LJ's b* is 1/",
     lambda: str("" if all(float(c[f"{m}_rel_{q}"]) == float("inf") for c in map_cells(**LARGE_ALPHA_SMALL_MU) for m in ("dw", "md") for q in ("P_fc", "W_star")) else " (no longer true)")),
    ("doc/user-guide.md", "e has no jump); but MD's P_pf is within {} to ",
     lambda: str(f"{map_extreme('md', 'P_pf', min, **LARGE_ALPHA_SMALL_MU):.1%}")),
    ("doc/user-guide.md", " to {} of LJ's",
     lambda: str(f"{map_extreme('md', 'P_pf', max, **LARGE_ALPHA_SMALL_MU):.1%}")),
    ("doc/theory.md", "against P_pf = {}", lambda: sci(critical(*GAP_PF_DW)[1], 5)),
    ("doc/theory.md", "P_min is now {})", lambda: sci(gap_critical_value(*GAP_PF_DW, "P_min"), 5)),
    ("doc/theory.md", "1.68596e-6, now {}).", lambda: sci(gap_w_star(*GAP_FLOOR_MD), 6)),
]


@pytest.mark.parametrize("path, text, value", CLAIMS,
                         ids=[f"{p}:{t[:30]}" for p, t, _ in CLAIMS])
def test_quoted_number(path, text, value):
    want = text.format(value())
    doc = (REPO / path).read_text()
    assert want in doc, f"{path} should quote: {want!r}"


def marked_commands():
    """(doc, command) for every line of a code block after `<!-- docs-test: run -->`."""
    found = []
    for doc in DOCS:
        lines = doc.read_text().splitlines()
        for i, line in enumerate(lines):
            if line.strip() != "<!-- docs-test: run -->":
                continue
            j = i + 1
            while j < len(lines) and not lines[j].strip():
                j += 1
            if j < len(lines) and lines[j].startswith("```"):
                j += 1
                while j < len(lines) and not lines[j].startswith("```"):
                    found.append((doc.name, lines[j]))
                    j += 1
            else:  # indented block
                while j < len(lines) and lines[j].startswith("    "):
                    found.append((doc.name, lines[j][4:]))
                    j += 1
    return [(d, c.split(" #")[0].strip()) for d, c in found if c.strip()]


COMMANDS = marked_commands()


def test_some_commands_are_marked():
    assert len(COMMANDS) >= 3, COMMANDS


@pytest.mark.parametrize("doc, command", COMMANDS, ids=[c for _, c in COMMANDS])
def test_quoted_command_runs(doc, command, tmp_path):
    env = dict(os.environ)
    env["PATH"] = os.pathsep.join([str(pathlib.Path(cli_path()).parent),
                                   str(REPO / ".venv" / "bin"), env["PATH"]])
    res = subprocess.run(command, shell=True, cwd=REPO, env=env, capture_output=True,
                         text=True, timeout=300)
    assert res.returncode == 0, f"{doc}: `{command}` exited {res.returncode}: {res.stderr[-2000:]}"


# Files outside the repository that nothing in it may cite (their content belongs in
# doc/theory.md, doc/user-guide.md, doc/accuracy-performance.md). Spelled in pieces so
# that this file does not cite them itself.
OUTSIDE = re.compile(r"\bSP" r"EC\b|MODEL" r"-NOTES|STYLE" r"\.md|\.\./sha" r"red|seed" r"-double")
FORBIDDEN = [
    (OUTSIDE, "not in the repository"),
    (re.compile(r"build/gfortran_"), "use tools/install.sh (doc/using-the-library.md)"),
    (re.compile(r"fpm test(?: --profile \w+)? (?:unit|capi) (?!--)\w"),
     "fpm needs -- before a suite name: fpm test --profile release unit -- dw"),
    (re.compile(r"fpm test(?: --profile \w+)? (?!--|unit|capi)[a-z]\w*"),
     "fpm needs -- before a suite name"),
]


@pytest.mark.parametrize("doc", DOCS, ids=[d.name for d in DOCS])
def test_docs_cite_only_the_repository(doc):
    text = doc.read_text()
    bad = [(m.group(0), why) for rx, why in FORBIDDEN for m in rx.finditer(text)]
    assert not bad, f"{doc.name}: {bad}"


@pytest.mark.parametrize("doc", DOCS, ids=[d.name for d in DOCS])
def test_relative_links_exist(doc):
    for target in re.findall(r"\]\(([^)#:\s]+)(?:#[^)]*)?\)", doc.read_text()):
        assert (doc.parent / target).exists(), f"{doc.name} links to missing {target}"


def test_si_example_quoted_verbatim():
    """doc/python.md's SI example is the body of python/examples/si_cycle.py."""
    script = (REPO / "python" / "examples" / "si_cycle.py").read_text()
    body = script[script.index("    # --- the problem in SI units"):
                  script.index("    try:\n        import matplotlib")]
    body = "\n".join(line[4:] for line in body.rstrip().splitlines())
    assert body in (REPO / "doc" / "python.md").read_text()


def test_consumer_files_quoted_verbatim():
    page = (REPO / "doc" / "using-the-library.md").read_text()
    for rel in ["make/Makefile", "make/main.f90", "cmake/CMakeLists.txt", "c/Makefile",
                "c/main.c", "fpm/fpm.toml", "fpm_installed/fpm.toml"]:
        text = (REPO / "test" / "consumers" / rel).read_text()
        assert text.strip() in page, f"doc/using-the-library.md must quote test/consumers/{rel}"


def test_ford_builds_without_warnings():
    res = subprocess.run(["bash", str(REPO / "tools" / "ford.sh")], cwd=REPO,
                         capture_output=True, text=True, timeout=300)
    assert res.returncode == 0, res.stdout + res.stderr
    pages = list((REPO / "doc" / "api").rglob("*.html"))
    assert len(pages) > 20
    # a*, c*, P* stay names: no emphasis except FORD's own "<em>None</em>".
    ems = set()
    for page in (REPO / "doc" / "api" / "module").glob("*.html"):
        ems.update(m for m in re.findall(r"<em>(.*?)</em>", page.read_text(), re.S)
                   if m.strip() != "None")
    assert not ems, sorted(ems)[:10]
    text = (REPO / "doc" / "api" / "module" / "wa_state.html").read_text()
    assert "a* &lt; c* &lt; 1/2" in text
    # Renders offline: every stylesheet and script of every page is local.
    for page in pages:
        head = page.read_text().split("</head>", 1)[0]
        remote = re.findall(r'(?:href|src)="(https?://[^"]+)"', head)
        assert not remote, f"{page}: {remote}"
    assert (REPO / "doc" / "api" / "vendor" / "bootstrap.min.css").stat().st_size > 100_000
    # The procedure and type lists hold the public API only (tools/ford_public.py), and
    # every exported procedure is there; index.html's short lists likewise.
    api = REPO / "doc" / "api"
    names, renames, public_modules = umbrella()
    exported = {renames.get(n, n) for n in names}
    listed = re.findall(r"<td><a href='\.\./(proc|interface|type)/(\w+)\.html'>\w+</a></td>\s*"
                        r"<td><a href='\.\./module/(\w+)\.html'>",
                        (api / "lists" / "procedures.html").read_text()
                        + (api / "lists" / "types.html").read_text())
    assert {m for _, _, m in listed} <= public_modules, sorted({m for _, _, m in listed})
    procs = {n for kind, n, _ in listed if kind != "type"}
    assert procs == set(public_procedures()), sorted(procs ^ set(public_procedures()))
    assert {n for kind, n, _ in listed if kind == "type"} <= exported
    index = (api / "index.html").read_text()
    shown = re.findall(r"<li><a href='(proc|type|module)/(\w+)\.html'>", index)
    assert shown[0] == ("module", "wavyadhesion"), shown[:3]
    assert all(n in exported or (k == "module" and n in public_modules | {"wavyadhesion"})
               for k, n in shown), shown
    # The umbrella's page links every name it lists.
    page = (api / "module" / "wavyadhesion.html").read_text()
    linked = set(re.findall(r'<a href="[^"]+">(\w+)</a>', page))
    assert exported <= linked, sorted(exported - linked)


def test_one_version_everywhere():
    assert re.fullmatch(r"\d+\.\d+\.\d+", VERSION)
    assert cli("--version").split() == ["wavyadhesion", VERSION]
    assert re.search(rf"^version: {re.escape(VERSION)}$", (REPO / "CITATION.cff").read_text(), re.M)
    assert f"— {VERSION}" in (REPO / "CHANGELOG.md").read_text() or \
        f"[{VERSION}]" in (REPO / "CHANGELOG.md").read_text()
    assert 'version = "VERSION"' in (REPO / "fpm.toml").read_text()
    assert "version: files('../VERSION')" in (REPO / "python" / "meson.build").read_text()
    assert f'wa_version = "{VERSION}"' in (REPO / "src" / "wa_release.f90").read_text()
    wa = pytest.importorskip("wavyadhesion")
    assert wa.__version__ == VERSION


def test_readme_gives_two_commands():
    readme = (REPO / "README.md").read_text()
    assert "    bash tools/setup.sh --run && .venv/bin/fpm run --profile release wavyadhesion\n" in readme
    assert "    bash tools/setup.sh && bash tools/test.sh\n" in readme
    assert shlex.split("bash tools/setup.sh && bash tools/test.sh")  # quoted by .ci/run


# ---------------------------------------------------------------- the Fortran API reference
SRC = REPO / "src"


def fortran_statements(path):
    """The source of a Fortran file, lower case, comments dropped, continuations joined."""
    text = re.sub(r"!.*", "", path.read_text().lower())
    return re.sub(r"&\s*\n\s*&?", " ", text)


def umbrella():
    """(exported names, {local name: name in its module}, modules re-exported from) of
    src/wavyadhesion.f90."""
    text = fortran_statements(SRC / "wavyadhesion.f90")
    names = [n.strip() for stmt in re.findall(r"^\s*public\s*::(.*)$", text, re.M)
             for n in stmt.split(",") if n.strip()]
    renames, modules = {}, set()
    for module, only in re.findall(r"^\s*use\s+(\w+)\s*,\s*only\s*:(.*)$", text, re.M):
        modules.add(module)
        for item in only.split(","):
            local, _, original = item.partition("=>")
            renames[local.strip()] = (original or local).strip()
    assert len(names) == len(set(names)), "a name is made public twice"
    return set(names), renames, modules


def umbrella_api_section():
    """The `## The public API` part of the umbrella's module doc comment."""
    lines = (SRC / "wavyadhesion.f90").read_text().split("\nmodule wavyadhesion", 1)[0]
    doc = "\n".join(line[2:] for line in lines.splitlines() if line.startswith("!>"))
    assert "## The public API" in doc
    return doc.split("## The public API", 1)[1]


def test_umbrella_page_lists_every_public_name():
    """The umbrella's doc comment (FORD's page of module wavyadhesion) links every name the
    module exports, once, and nothing else; FORD resolves the links (tools/ford.sh fails on
    an unresolved one)."""
    names, renames, _ = umbrella()
    section = umbrella_api_section()
    linked = re.findall(r"\[\[(?:\w+:)?(\w+)\]\]", section)
    assert len(linked) == len(set(linked)), sorted(n for n in linked if linked.count(n) > 1)
    listed = set(linked)
    exported = {renames.get(n, n) for n in names}
    assert listed == exported, (f"exported but not listed: {sorted(exported - listed)}; "
                                f"listed but not exported: {sorted(listed - exported)}")
    # each group of the page is one of the library's layers
    groups = re.findall(r"^\s*### (.+)$", section, re.M)
    assert [g.split(" (")[0] for g in groups] == [
        "Parameters", "Kernels", "Models", "Separation", "Branch", "Load control",
        "Gap control", "Adhesion map", "Smooth adhesion", "Status and version"], groups


def module_doc(path):
    """(module name, its doc comment lines) of a src/*.f90 file."""
    lines = path.read_text().splitlines()
    for i, line in enumerate(lines):
        m = re.match(r"\s*module\s+(\w+)\s*$", line, re.I)
        if m:
            j = i
            while j > 0 and lines[j - 1].lstrip().startswith("!>"):
                j -= 1
            return m.group(1).lower(), [s.strip()[2:].strip() for s in lines[j:i]]
    return None, []




def test_internal_modules_are_hidden():
    """A module the umbrella re-exports nothing from is internal: its doc comment starts
    with FORD's `display: none` (the module page stays, its procedures and types are not
    documented); a module it re-exports from must not carry it."""
    _, _, public = umbrella()
    wrong = []
    for path in sorted(SRC.glob("*.f90")):
        name, doc = module_doc(path)
        if name is None or name == "wavyadhesion":
            continue
        hidden = doc[:2] == ["display: none", ""]
        if (name in public) == hidden:
            wrong.append(f"{name}: {'hidden but re-exported' if hidden else 'internal, not hidden'}")
    assert not wrong, wrong


PROC_HEAD = re.compile(r"^\s*(?:(?:pure|elemental|impure|recursive|module)\s+|"
                       r"(?:real|integer|logical|complex|character|type)\s*(?:\([^)]*\))?\s+)*"
                       r"(?:function|subroutine)\s+(\w+)\s*(?:\(([^)]*)\))?", re.I)


def joined(lines, i):
    """Line i with its continuation lines (comments dropped), and the index of its last line."""
    text = lines[i].split("!")[0].rstrip()
    while text.endswith("&"):
        i += 1
        text = text[:-1] + " " + lines[i].split("!")[0].strip().lstrip("&")
    return text, i


def procedure_arguments(path):
    """{procedure: [(argument, its doc lines)]} for every procedure of a Fortran file: the
    `!>` lines right above the declaration of each dummy argument (or a `!!` after it)."""
    lines = path.read_text().splitlines()
    found, i = {}, 0
    while i < len(lines):
        head, last = joined(lines, i)
        m = None if re.match(r"\s*end\b", head, re.I) else PROC_HEAD.match(head)
        if not m:
            i += 1
            continue
        args = [a.strip().lower() for a in (m.group(2) or "").split(",") if a.strip()]
        docs = {}
        k = last + 1
        while k < len(lines) and not re.match(r"\s*(end\s*(function|subroutine)|contains)\b",
                                              lines[k], re.I):
            decl, end = joined(lines, k)
            dm = re.match(r"[^!]*?::(.*)$", decl)
            if dm:
                above, p = [], k - 1
                while p >= 0 and lines[p].lstrip().startswith("!>"):
                    above.insert(0, lines[p].strip()[2:].strip())
                    p -= 1
                if "!!" in lines[end]:
                    above.append(lines[end].split("!!", 1)[1].strip())
                for entity in re.split(r",(?![^()]*\))", dm.group(1)):
                    n = re.match(r"\s*(\w+)", entity)
                    if n and n.group(1).lower() in args:
                        docs.setdefault(n.group(1).lower(), [s for s in above if s])
            k = end + 1
        found[m.group(1).lower()] = [(a, docs.get(a, [])) for a in args]
        i = last + 1
    return found


def public_procedures():
    """{procedure the umbrella exports: (file name, [(argument, doc lines)])}."""
    names, renames, _ = umbrella()
    exported = {renames.get(n, n) for n in names}
    procs = {}
    for path in sorted(SRC.glob("*.f90")):
        for name, args in procedure_arguments(path).items():
            if name in exported:
                procs[name] = (path.name, args)
    return procs


def test_public_arguments_documented():
    """Every dummy argument of every routine `use wavyadhesion` exports has a `!>` doc
    comment (FORD shows it on the routine's page)."""
    procs = public_procedures()
    assert len(procs) >= 50, sorted(procs)
    missing = [f"{file}: {proc}({arg})" for proc, (file, args) in sorted(procs.items())
               for arg, doc in args if not doc]
    assert not missing, missing
    n_args = sum(len(args) for _, args in procs.values())
    assert n_args > 250, n_args


def test_procedure_parser_sees_missing_docs(tmp_path):
    src = tmp_path / "m.f90"
    src.write_text("module m\ncontains\n   !> f\n   pure subroutine f(a, b, &\n         c)\n"
                   "      !> the a\n      real, intent(in) :: a\n      real, intent(in) :: b\n"
                   "      real, intent(out) :: c !! the c\n   end subroutine f\nend module m\n")
    assert procedure_arguments(src) == {"f": [("a", ["the a"]), ("b", []), ("c", ["the c"])]}


# Trees where nothing may cite a file outside the repository.
CITING_TREES = ["src", "app", "python", "include", "doc", "README.md", "test", "study", "tools",
                "benchmark"]


def test_no_citation_of_files_outside_the_repository():
    files = subprocess.run(["git", "ls-files", "--cached", "--others", "--exclude-standard",
                            "--", *CITING_TREES], cwd=REPO, check=True, capture_output=True,
                           text=True).stdout.split()
    assert len(files) > 100
    bad = []
    for rel in files:
        path = REPO / rel
        if rel.startswith(("doc/api/", "build/")) or not path.is_file():
            continue
        text = path.read_bytes().decode("utf-8", errors="replace")
        bad += [f"{rel}:{text.count(chr(10), 0, m.start()) + 1}: {m.group(0)}"
                for m in OUTSIDE.finditer(text)]
    assert not bad, bad


def test_cli_build_builds_only_what_it_needs():
    """`fpm run wavyadhesion` builds the library, the command line and the tests only: the
    study, verification and benchmark programs are a package of their own (study/fpm.toml)."""
    root = (REPO / "fpm.toml").read_text()
    assert "[[example]]" not in root
    study = (REPO / "study" / "fpm.toml").read_text()
    assert 'wavyadhesion = { path = ".." }' in study
    for name in ["wavyadhesion-study", "wavyadhesion-benchmark", "wavyadhesion-lj-benchmark",
                 "wavyadhesion-mapcheck", "wavyadhesion-gapcheck"]:
        assert f'name = "{name}"' in study, name
