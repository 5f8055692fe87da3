"""The installed library from host codes: runs test/consumers/run.sh (tools/install.sh into
a temporary prefix, then the Make, CMake, C and fpm examples, each checking a number)."""
import pathlib
import subprocess

HERE = pathlib.Path(__file__).resolve().parent


def test_consumers_build_and_run_against_installed_prefix(tmp_path):
    run = subprocess.run(["bash", str(HERE / "run.sh"), str(tmp_path / "prefix")],
                         capture_output=True, text=True, timeout=900)
    assert run.returncode == 0, run.stdout + run.stderr
    assert run.stdout.count("c* =  0.3279513311789390") + run.stdout.count(
        "c* = 0.3279513311789390") == 4, run.stdout
    # Only the command line goes to bin/; the library's modules only (not the CLI's/study's).
    prefix = tmp_path / "prefix"
    assert sorted(p.name for p in (prefix / "bin").iterdir()) == ["wavyadhesion"]
    mods = {p.name for p in (prefix / "include").glob("*.mod")}
    assert "wavyadhesion.mod" in mods
    assert not [m for m in mods if m.startswith(("wa_cli", "wa_study", "wa_psi"))], mods
    assert (prefix / "lib" / "cmake" / "wavyadhesion" / "wavyadhesion-config-version.cmake").is_file()
