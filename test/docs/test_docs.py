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
4. The FORD API reference builds without warnings, with a*, P* not turned into emphasis.
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
    ("doc/python.md", "It prints\n\n```\n{}\n```", lambda: "\n".join(
        example_output("python/examples/si_cycle.py").splitlines()[:3])),
    ("doc/python.md", 'repr(wa.trace_branch("dw", 0.3, 5.0))` is\n`{}`',
     lambda: python_value('repr(wa.trace_branch("dw", 0.3, 5.0))')),
    ("doc/user-guide.md", "closed forms ({} points", lambda: branch_points("westergaard")),
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


FORBIDDEN = [
    (re.compile(r"SPEC\b"), "the SPEC is not in the repository"),
    (re.compile(r"MODEL-NOTES|STYLE\.md|\.\./shared|seed-double"), "not in the repository"),
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
