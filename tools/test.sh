#!/usr/bin/env bash
# Runs every test (after `bash tools/setup.sh`), with the project's virtual environment
# .venv first on PATH:
#   1. fpm test --profile release: the Fortran unit tests (unit) and the C-interface
#      test (capi); then the study's programs (study/fpm.toml) are built;
#   2. installs the Python package ./python into .venv;
#   3. pytest over the command line (test/cli), the Python package (python/tests), the
#      docs (test/docs: commands and numbers quoted in README.md and doc/*.md, the FORD
#      API reference, the version everywhere) and the installed library used from
#      Make, CMake, C and fpm (test/consumers).
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x .venv/bin/python ] || { echo "tools/test.sh: run 'bash tools/setup.sh' first" >&2; exit 1; }
export PATH="$PWD/.venv/bin:$PATH"
# No executable stack: every fpm build of the tests (and the pytest runs below) refuses
# code that needs a trampoline (an internal procedure passed as an argument).
export FPM_FFLAGS="${FPM_FFLAGS:+$FPM_FFLAGS }-Werror=trampolines"

fpm test --profile release
# The study, verification and benchmark programs (their own fpm package): they must build.
(cd study && fpm build --profile release)
python -m pip install --quiet --disable-pip-version-check ./python
# pytest exits 5 when it collected no tests; set -e makes that (like any failure) fatal.
python -m pytest -q test/cli python/tests test/docs test/consumers
