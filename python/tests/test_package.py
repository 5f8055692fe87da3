"""Package surface: the public names, the docstring examples, and the C header's
constants against the Fortran ones."""

import doctest
import re

import pytest

import wavyadhesion as wa
import importlib

import wavyadhesion
from wavyadhesion import _errors, _wa_f2py as _f

MODULES = ["_args", "_branch", "_energy", "_equilibrium", "_errors", "_gap", "_gapcritical",
           "_lj", "_loadpath", "_map", "_model_error", "_parallel", "_params", "_profile", "_results", "plotting"]


def test_public_names():
    for name in ("westergaard_load", "jkr_load", "equilibrium", "roots", "Params",
                 "WavyAdhesionError", "InvalidArgumentError", "ConvergenceError",
                 "trace_branch", "load_path", "critical_forces", "Branch", "LoadPath",
                 "CriticalForces", "EVENTS", "MECHANISMS", "STAGES"):
        assert hasattr(wa, name)
    assert set(wa.__all__) <= set(dir(wa))
    assert wa.MODELS == {"westergaard": 0, "jkr": 1, "dw": 2, "md": 3}


def test_docstring_examples():
    for module in [wa] + [importlib.import_module(f"wavyadhesion.{m}") for m in MODULES]:
        result = doctest.testmod(module, optionflags=doctest.NORMALIZE_WHITESPACE)
        assert result.failed == 0


def test_every_public_function_documented():
    for name in ("westergaard_load", "jkr_load", "equilibrium", "roots", "trace_branch",
                 "load_path", "critical_forces"):
        doc = getattr(wa, name).__doc__
        assert "Parameters" in doc and "Returns" in doc and "Raises" in doc


def _fortran_constants(text):
    return {k.lower(): int(v) for k, v in
            re.findall(r"\b(\w+)\s*=\s*(\d+)\b", text)}


def test_header_constants_equal_fortran(repo):
    header = (repo / "include" / "wavyadhesion.h").read_text()
    c = {k.lower(): int(v) for k, v in re.findall(r"#define\s+(WA_\w+)\s+(\d+)", header)}
    status = _fortran_constants((repo / "src" / "wa_status.f90").read_text())
    state = _fortran_constants((repo / "src" / "wa_state.f90").read_text())
    for name in ("wa_ok", "wa_invalid_argument", "wa_no_solution", "wa_not_converged",
                 "wa_capacity_too_small", "wa_numerical_error"):
        assert c[name] == status[name], name
    for name in ("westergaard", "jkr", "dw", "md"):
        assert c["wa_model_" + name] == state["model_" + name] == wa.MODELS[name]
    cli = _fortran_constants((repo / "app" / "wa_cli_options.f90").read_text())
    assert c["wa_model_lj"] == cli["model_lj"]     # the code of the CLI's --model lj
    for c_name, f_name in (("wa_zone_inside", "zone_inside"),
                           ("wa_zone_whole_period", "zone_whole_period"),
                           ("wa_zone_full_contact", "zone_full_contact")):
        assert c[c_name] == state[f_name]


def test_header_event_and_mechanism_constants(repo):
    """WA_EVENT_*, WA_STAGE_*, WA_MECHANISM_* equal the Fortran constants and the
    Python tables."""
    header = (repo / "include" / "wavyadhesion.h").read_text()
    c = {k.lower(): int(v) for k, v in re.findall(r"#define\s+(WA_\w+)\s+(\d+)", header)}
    branch = _fortran_constants((repo / "src" / "wa_branch.f90").read_text())
    path = _fortran_constants((repo / "src" / "wa_loadpath.f90").read_text())
    events = {"none": "none", "fold": "fold", "switch": "switch",
              "jump_start": "jump_start", "jump_end": "jump_end",
              "full_contact_reached": "full_contact_reached",
              "full_contact_left": "full_contact_left", "pull_off": "pull_off",
              "branch_end": "branch_end"}
    for name in events:
        assert c["wa_event_" + name] == branch["event_" + name], name
        assert wa.EVENTS[c["wa_event_" + name]] == name
    for code, name in enumerate(wa.MECHANISMS):
        assert c["wa_mechanism_" + name] == path["mechanism_" + name] == code, name
    for code, name in wa.STAGES.items():
        assert c["wa_stage_" + name] == path["stage_" + name] == code, name


def test_matplotlib_not_imported():
    """The plotting helpers are optional: importing the package does not import
    matplotlib."""
    import subprocess
    import sys
    code = ("import sys, wavyadhesion, wavyadhesion.plotting; "
            "print('matplotlib' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True)
    assert out.stdout.strip() == "False"


def test_meson_installs_every_module(repo):
    meson = (repo / "python" / "meson.build").read_text()
    for f in sorted((repo / "python" / "wavyadhesion").glob("*.py")):
        assert f"'wavyadhesion/{f.name}'" in meson, f"{f.name} missing from meson.build"
    listed = set(re.findall(r"'wavyadhesion/([^']+)'", meson))
    on_disk = {f.name for f in (repo / "python" / "wavyadhesion").glob("*.py")}
    assert listed == on_disk | {"py.typed"}, listed ^ (on_disk | {"py.typed"})


def test_py_typed_installed():
    """PEP 561 marker: type checkers read the package's annotations."""
    from pathlib import Path
    assert (Path(wa.__file__).parent / "py.typed").is_file()


def test_meson_lists_every_source(repo):
    meson = (repo / "python" / "meson.build").read_text()
    for f in sorted((repo / "src").glob("*.f90")):
        assert f"'../src/{f.name}'" in meson, f"{f.name} missing from python/meson.build"


def test_status_texts_match_c_interface():
    """wa_status::status_message (through the facade) has the wording the C interface's
    static table has (test/capi/main.c checks the same strings on the C side)."""
    want = ["ok", "invalid argument", "no solution", "iteration did not converge",
            "output capacity too small", "numerical error"]
    for code, text in enumerate(want):
        assert _errors.message_text(_f.fa_status_text(code)) == text
    assert _errors.message_text(_f.fa_status_text(99)) == "unknown status"


def test_extension_has_no_executable_stack(repo):
    """glibc 2.41 and later refuse to dlopen a library whose GNU_STACK is RWE."""
    import shutil
    import subprocess
    from wavyadhesion import _wa_f2py
    if shutil.which("readelf") is None:
        pytest.skip("readelf (binutils) not installed")
    run = subprocess.run(["bash", str(repo / "tools" / "check_stack.sh"), _wa_f2py.__file__],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stdout + run.stderr
