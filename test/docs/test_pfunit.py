"""The pFUnit front end (test/pfunit, doc/testing.md) stays current without pFUnit.

Its pf_<suite>.pf wrappers are generated from the one table of unit suites,
test/unit/suites.f90. `python3 test/pfunit/generate.py --check` rereads the table and
every suite's test list and exits 1 when a generated file would change (or 2 when a
test/unit/test_*.f90 is not in the table); CI has no pFUnit, so this check is what keeps
the wrappers from going stale. The other tests run the check on a copy of test/ with a
test added, a suite added and a file left out of the table, so the check itself is
shown to fail when it must.
"""
import pathlib
import re
import shutil
import subprocess
import sys

REPO = pathlib.Path(__file__).resolve().parents[2]
GENERATE = pathlib.Path("test/pfunit/generate.py")


def run_generate(root, *args):
    return subprocess.run([sys.executable, str(root / GENERATE), *args], cwd=root,
                          capture_output=True, text=True, timeout=60)


def copy_tests(tmp_path):
    """test/unit and test/pfunit copied under tmp_path (what generate.py reads)."""
    for sub in ("unit", "pfunit"):
        shutil.copytree(REPO / "test" / sub, tmp_path / "test" / sub)
    return tmp_path


def test_generated_pfunit_files_are_current():
    res = run_generate(REPO, "--check")
    assert res.returncode == 0, res.stdout + res.stderr


def test_every_suite_of_the_table_is_wrapped():
    table = (REPO / "test/unit/suites.f90").read_text()
    suites = re.findall(r'new_testsuite\("(\w+)"', table)
    assert "mechanism" in suites and "gapcritical" in suites
    for suite in suites:
        assert (REPO / f"test/pfunit/pf_{suite}.pf").is_file(), suite
    for path in (REPO / "test/unit").glob("test_*.f90"):
        assert path.stem.removeprefix("test_") in suites, path.name


def test_check_sees_a_new_test(tmp_path):
    root = copy_tests(tmp_path)
    path = root / "test/unit/test_text.f90"
    text = path.read_text()
    row = 'new_unittest("int_text", test_int)'
    assert row in text
    path.write_text(text.replace(row, row + ', &\n         new_unittest("int_text_again", test_int)'))
    res = run_generate(root, "--check")
    assert res.returncode == 1 and "pf_text.pf: out of date" in res.stderr, res.stderr
    assert run_generate(root).returncode == 0
    assert "int_text_again" in (root / "test/pfunit/pf_text.pf").read_text()
    assert run_generate(root, "--check").returncode == 0


def test_check_sees_a_new_suite_and_a_removed_one(tmp_path):
    root = copy_tests(tmp_path)
    table = root / "test/unit/suites.f90"
    text = table.read_text()
    text = text.replace('new_testsuite("text", collect_text)',
                        'new_testsuite("text", collect_text), &\n'
                        '         new_testsuite("text2", collect_text)')
    text = text.replace('         new_testsuite("mechanism", collect_mechanism), &\n', "")
    text = text.replace("   use test_mechanism, only: collect_mechanism\n", "")
    table.write_text(text)
    (root / "test/unit/test_mechanism.f90").unlink()
    res = run_generate(root, "--check")
    assert res.returncode == 1, res.stderr
    assert "pf_text2.pf: out of date" in res.stderr
    assert "pf_mechanism.pf: its suite is no longer in the table" in res.stderr
    assert run_generate(root).returncode == 0
    assert not (root / "test/pfunit/pf_mechanism.pf").exists()
    assert (root / "test/pfunit/pf_reference_values.pf").exists()   # written by hand: kept
    assert run_generate(root, "--check").returncode == 0


def test_check_refuses_a_suite_not_in_the_table(tmp_path):
    root = copy_tests(tmp_path)
    shutil.copy(root / "test/unit/test_text.f90", root / "test/unit/test_orphan.f90")
    res = run_generate(root, "--check")
    assert res.returncode == 2 and "test_orphan.f90 is not in the table" in res.stderr
