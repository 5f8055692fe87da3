"""The installed library from host codes: runs test/consumers/run.sh (tools/install.sh into
a temporary prefix, then the Make, CMake, C and fpm examples, each checking a number)."""
import os
import pathlib
import re
import subprocess

HERE = pathlib.Path(__file__).resolve().parent


def test_consumers_build_and_run_against_installed_prefix(tmp_path):
    run = subprocess.run(["bash", str(HERE / "run.sh"), str(tmp_path / "prefix")],
                         capture_output=True, text=True, timeout=900)
    assert run.returncode == 0, run.stdout + run.stderr
    assert run.stdout.count("c* =  0.3279513311789390") + run.stdout.count(
        "c* = 0.3279513311789390") == 8, run.stdout
    # Only the command line goes to bin/; the library's modules only (not the CLI's/study's).
    prefix = tmp_path / "prefix"
    assert sorted(p.name for p in (prefix / "bin").iterdir()) == ["wavyadhesion"]
    # Only the public module, in a directory of its compiler (include/wavyadhesion/GNU-x.y.z).
    assert not list((prefix / "include").glob("*.mod"))
    mods = sorted(p.relative_to(prefix / "include").as_posix()
                  for p in (prefix / "include").rglob("*.mod"))
    assert len(mods) == 1 and re.fullmatch(r"wavyadhesion/GNU-[0-9.]+/wavyadhesion\.mod",
                                           mods[0]), mods
    # Shared library with a versioned soname, and the static one.
    version = (HERE.parent.parent / "VERSION").read_text().strip()
    major_minor = ".".join(version.split(".")[:2])
    lib = prefix / "lib"
    assert (lib / "libwavyadhesion.a").is_file()
    assert (lib / f"libwavyadhesion.so.{version}").is_file()
    assert os.readlink(lib / "libwavyadhesion.so") == f"libwavyadhesion.so.{major_minor}"
    assert os.readlink(lib / f"libwavyadhesion.so.{major_minor}") == f"libwavyadhesion.so.{version}"
    dyn = subprocess.run(["readelf", "-d", str(lib / "libwavyadhesion.so")],
                         capture_output=True, text=True, check=True).stdout
    assert f"Library soname: [libwavyadhesion.so.{major_minor}]" in dyn
    # pkg-config: GSL only for static links; no compiler-internal directory anywhere.
    pc = (lib / "pkgconfig" / "wavyadhesion.pc").read_text()
    assert "Requires.private: gsl" in pc and "\nRequires:" not in pc
    cmake = (lib / "cmake" / "wavyadhesion" / "wavyadhesion-config.cmake").read_text()
    for text in (pc, cmake):
        assert "/usr/lib/gcc" not in text and "-L/usr" not in text
    assert (prefix / "lib" / "cmake" / "wavyadhesion" / "wavyadhesion-config-version.cmake").is_file()
