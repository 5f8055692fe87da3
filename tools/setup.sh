#!/usr/bin/env bash
# Installs what the project needs on Debian 12 when it is missing, and does nothing more
# when everything is present:
#   apt-get:  gfortran, libgsl-dev, libfftw3-dev, pkg-config; for the Python parts also python3-venv
#             (when `python3 -m venv` cannot work) and python3-dev (Python.h, for f2py);
#             for the API reference libjs-bootstrap5 (FORD's pages without a CDN);
#   pip:      into the project's virtual environment .venv (git-ignored), never into the
#             system Python (Debian's python3 is EXTERNALLY-MANAGED, PEP 668): fpm; for
#             the Python parts also numpy, meson, meson-python, ninja, pytest, ford, and
#             dask and distributed (python/tests/test_parallel.py runs critical_forces on
#             a dask LocalCluster).
# Usage: bash tools/setup.sh          everything (build, tests, API reference)
#        bash tools/setup.sh --run    only what building and running the library needs
# Afterwards the tools are in .venv/bin (tools/test.sh puts it first on PATH).
set -euo pipefail
cd "$(dirname "$0")/.."

mode=all
case "${1:-}" in
   "") ;;
   --run) mode=run ;;
   *) echo "usage: bash tools/setup.sh [--run]" >&2; exit 2 ;;
esac

python=python3
command -v "$python" >/dev/null || { echo "tools/setup.sh: python3 not found (apt-get install python3)" >&2; exit 1; }

need_apt=()
command -v gfortran >/dev/null || need_apt+=(gfortran)
[ -e /usr/include/gsl/gsl_sf_ellint.h ] || need_apt+=(libgsl-dev)
# FFTW3: the smooth-adhesion model's stiffness products (and its threads library)
[ -e /usr/include/fftw3.h ] || need_apt+=(libfftw3-dev)
command -v pkg-config >/dev/null || need_apt+=(pkg-config)
# A virtual environment needs venv and ensurepip (Debian: python3-venv).
"$python" -c "import venv, ensurepip" 2>/dev/null || need_apt+=(python3-venv)
if [ "$mode" = all ]; then
   # The f2py extension compiles against Python.h (Debian: python3-dev).
   inc=$("$python" -c "import sysconfig; print(sysconfig.get_paths()['include'])")
   [ -e "$inc/Python.h" ] || need_apt+=(python3-dev)
   # The API reference renders offline with a local Bootstrap (tools/ford_offline.py).
   [ -e /usr/share/javascript/bootstrap5/css/bootstrap.min.css ] || need_apt+=(libjs-bootstrap5)
fi
if [ ${#need_apt[@]} -gt 0 ]; then
   sudo_cmd=""
   [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
   $sudo_cmd apt-get update -qq
   DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq "${need_apt[@]}"
fi

# The project's virtual environment; made again when its Python is gone.
if ! .venv/bin/python -c "" 2>/dev/null; then
   rm -rf .venv
   "$python" -m venv .venv
fi

# Requirements (pip does nothing, and asks no index, for those already satisfied).
pip_reqs=("fpm>=0.12")
if [ "$mode" = all ]; then
   pip_reqs+=("numpy>=1.26" "meson>=1.1" "meson-python>=0.15" "ninja" "pytest" "ford>=7.0,<8"
             "dask>=2024.1" "distributed>=2024.1")
fi
if ! .venv/bin/python - "${pip_reqs[@]}" 2>/dev/null <<'EOF'
# exit 0 when every requirement is installed in .venv at a satisfying version
import sys
from importlib.metadata import version, PackageNotFoundError
import re
for req in sys.argv[1:]:
    name, spec = re.match(r"([A-Za-z0-9_.-]+)(.*)", req).groups()
    try:
        have = tuple(int(x) for x in re.findall(r"\d+", version(name))[:3])
    except PackageNotFoundError:
        sys.exit(1)
    for op, ver in re.findall(r"(>=|<)([\d.]+)", spec):
        want = tuple(int(x) for x in ver.split("."))
        if (op == ">=" and have < want) or (op == "<" and have >= want):
            sys.exit(1)
EOF
then
   .venv/bin/python -m pip install --quiet --disable-pip-version-check "${pip_reqs[@]}"
fi
