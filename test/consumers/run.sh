#!/usr/bin/env bash
# Installs wavyadhesion into a prefix (default: a new temporary directory) with
# tools/install.sh, then builds and runs the host-code examples of
# doc/using-the-library.md against it: make/ (Makefile + pkg-config, Fortran, shared
# library), cmake/ (find_package(wavyadhesion CONFIG), Fortran, shared and static), c/
# (C + pkg-config, shared and static), ctypes (Python loading the shared library by
# path, as any FFI does), fpm_installed/ (fpm against the installed module and library)
# and fpm/ (fpm path dependency; builds from the sources). Each checks a DW equilibrium
# against the mpmath reference and exits non-zero on a mismatch; every program built, the
# shared library and the installed command line must have a non-executable stack
# (tools/check_stack.sh).
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
"$work/cmake/consumer_static"

echo "== c"
cp -r "$here/c" "$work/c"
make -s -C "$work/c"
"$work/c/consumer"
"$work/c/consumer_static"

echo "== ctypes (the shared library by path)"
python3 - "$prefix/lib/libwavyadhesion.so" <<'EOF'
import ctypes, sys
lib = ctypes.CDLL(sys.argv[1])
c, p, zone = ctypes.c_double(), ctypes.c_double(), ctypes.c_int()
lib.wa_equilibrium.argtypes = ([ctypes.c_int] + [ctypes.c_double] * 3 + [ctypes.c_void_p] * 5
                               + [ctypes.c_int])
st = lib.wa_equilibrium(2, 0.3, 1.0, 0.2, ctypes.byref(c), ctypes.byref(p), ctypes.byref(zone),
                        None, None, 0)
c_ref, p_ref = 0.32795133117893904447, 0.17439576801132992591
print(f"ctypes: c* = {c.value:.16f}  P* = {p.value:.16f}")
if st != 0 or abs(c.value - c_ref) > 1e-12 * c_ref or abs(p.value - p_ref) > 1e-12 * p_ref:
    sys.exit("ctypes: c* or P* differs from the reference")
EOF

echo "== fpm (installed prefix)"
cp -r "$here/fpm_installed" "$work/fpm_installed"
cp -r "$here/fpm/app" "$work/fpm_installed/app"     # the same program as fpm/
(cd "$work/fpm_installed" && fpm run --profile release \
   --flag "-I$(pkg-config --variable=fmoddir wavyadhesion)" \
   --link-flag "-L$prefix/lib -Wl,-rpath,$prefix/lib" > "$work/fpm_installed.log" 2>&1) \
   || { cat "$work/fpm_installed.log"; exit 1; }
grep '^wavyadhesion ' "$work/fpm_installed.log"
fpm_installed=$(cd "$work/fpm_installed" && fpm run --profile release \
   --flag "-I$(pkg-config --variable=fmoddir wavyadhesion)" \
   --link-flag "-L$prefix/lib -Wl,-rpath,$prefix/lib" --runner echo 2>/dev/null | tail -n 1)

echo "== fpm"
(cd "$here/fpm" && fpm run --profile release > "$work/fpm.log" 2>&1) || { cat "$work/fpm.log"; exit 1; }
grep '^wavyadhesion ' "$work/fpm.log"
fpm_consumer=$(cd "$here/fpm" && fpm run --profile release --runner echo 2>/dev/null | tail -n 1)

echo "== non-executable stack (readelf)"
bash "$repo/tools/check_stack.sh" "$prefix/bin/wavyadhesion" "$prefix/lib/libwavyadhesion.so" \
   "$work/make/consumer" "$work/cmake/consumer" "$work/cmake/consumer_static" \
   "$work/c/consumer" "$work/c/consumer_static" "$work/fpm_installed/$fpm_installed" \
   "$here/fpm/$fpm_consumer"

echo "consumers: make, cmake (shared, static), c (shared, static), ctypes, fpm (installed, path) all ok"
