#!/usr/bin/env bash
# Installs wavyadhesion into a prefix (default: a new temporary directory) with
# tools/install.sh, then builds and runs the four host-code examples of
# doc/using-the-library.md against it: make/ (Makefile + pkg-config, Fortran),
# cmake/ (find_package(wavyadhesion CONFIG), Fortran), c/ (C + pkg-config) and fpm/
# (fpm path dependency; builds from the sources). Each checks a DW equilibrium against the
# mpmath reference and exits non-zero on a mismatch; every program built and the installed
# command line must have a non-executable stack (tools/check_stack.sh).
# Usage: bash test/consumers/run.sh [PREFIX]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../.." && pwd)
[ -x "$repo/.venv/bin/fpm" ] && export PATH="$repo/.venv/bin:$PATH"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=${1:-$work/prefix}

bash "$repo/tools/install.sh" "$prefix"
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}"
pkg-config --libs wavyadhesion

echo "== make"
cp -r "$here/make" "$work/make"
make -s -C "$work/make"
"$work/make/consumer"

echo "== cmake"
cmake -S "$here/cmake" -B "$work/cmake" -DCMAKE_PREFIX_PATH="$prefix" > "$work/cmake.log" \
   || { cat "$work/cmake.log"; exit 1; }
cmake --build "$work/cmake" > "$work/cmake-build.log" || { cat "$work/cmake-build.log"; exit 1; }
"$work/cmake/consumer"

echo "== c"
cp -r "$here/c" "$work/c"
make -s -C "$work/c"
"$work/c/consumer"

echo "== fpm"
(cd "$here/fpm" && fpm run --profile release > "$work/fpm.log" 2>&1) || { cat "$work/fpm.log"; exit 1; }
grep '^wavyadhesion ' "$work/fpm.log"
fpm_consumer=$(cd "$here/fpm" && fpm run --profile release --runner echo 2>/dev/null | tail -n 1)

echo "== non-executable stack (readelf)"
bash "$repo/tools/check_stack.sh" "$prefix/bin/wavyadhesion" "$work/make/consumer" \
   "$work/cmake/consumer" "$work/c/consumer" "$here/fpm/$fpm_consumer"

echo "consumers: make, cmake, c, fpm all ok"
