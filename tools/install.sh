#!/usr/bin/env bash
# Installs the library for host codes into PREFIX (release build):
#   PREFIX/lib/libwavyadhesion.a                         static library
#   PREFIX/include/wavyadhesion.h                        C header
#   PREFIX/include/*.mod                                 the library's Fortran modules
#                                                        (wavyadhesion.mod and the wa_*.mod
#                                                        it uses; gfortran-specific)
#   PREFIX/lib/pkgconfig/wavyadhesion.pc                 pkg-config (Libs with GSL and the
#                                                        gfortran runtime, Cflags -I include)
#   PREFIX/lib/cmake/wavyadhesion/wavyadhesion-config.cmake (+ -config-version.cmake)
#                                                        CMake package, imported target
#                                                        wavyadhesion::wavyadhesion
#   PREFIX/bin/wavyadhesion                              the command line
# fpm (`fpm install`, with `[install] library = true` in fpm.toml) builds and collects the
# archive, the modules and the executable into a staging directory; this script keeps the
# library's own modules (not the command line's or the study's) and writes what fpm cannot
# (header, pkg-config file, CMake package).
# Usage: bash tools/install.sh PREFIX        (see doc/using-the-library.md)
set -euo pipefail
if [ $# -ne 1 ] || [ "${1:0:1}" = "-" ]; then
   echo "usage: bash tools/install.sh PREFIX" >&2
   exit 2
fi
repo=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$1"
prefix=$(cd "$1" && pwd)
cd "$repo"

fpm=fpm
[ -x .venv/bin/fpm ] && fpm=$PWD/.venv/bin/fpm
command -v "$fpm" >/dev/null || { echo "tools/install.sh: fpm not found (bash tools/setup.sh --run)" >&2; exit 1; }

version=$(tr -d ' \t\r\n' < VERSION)
stage=$(mktemp -d)
log=$(mktemp)
trap 'rm -rf "$stage" "$log"' EXIT
"$fpm" install --profile release --prefix "$stage" > "$log" 2>&1 || { cat "$log" >&2; exit 1; }

# The library's modules: those defined in src/ (fpm's include/ also holds the CLI's and
# the study's, which are not part of the library).
mapfile -t modules < <(sed -nE 's/^[[:space:]]*module[[:space:]]+([A-Za-z0-9_]+)[[:space:]]*(!.*)?$/\1/Ip' src/*.f90 \
   | tr 'A-Z' 'a-z' | grep -v '^procedure$' | sort -u)
[ ${#modules[@]} -gt 0 ] || { echo "tools/install.sh: no modules found in src/" >&2; exit 1; }

install -d "$prefix/lib/pkgconfig" "$prefix/lib/cmake/wavyadhesion" "$prefix/include" "$prefix/bin"
install -m 644 "$stage/lib/libwavyadhesion.a" "$prefix/lib/"
for m in "${modules[@]}"; do
   install -m 644 "$stage/include/$m.mod" "$prefix/include/"
done
install -m 644 include/wavyadhesion.h "$prefix/include/"
install -m 755 "$stage/bin/wavyadhesion" "$prefix/bin/"

# The gfortran runtime, for C and C++ hosts (a Fortran compiler links it by itself).
fc=${FC:-gfortran}
fortran_libdir=$(dirname "$("$fc" -print-file-name=libgfortran.so)")

cat > "$prefix/lib/pkgconfig/wavyadhesion.pc" <<EOF
# wavyadhesion $version, installed by tools/install.sh (static library).
prefix=$prefix
libdir=\${prefix}/lib
includedir=\${prefix}/include

Name: wavyadhesion
Description: Adhesive contact of a wavy elastic surface (Westergaard, JKR, double-Westergaard, Maugis-Dugdale)
Version: $version
Requires: gsl
Cflags: -I\${includedir}
Libs: -L\${libdir} -lwavyadhesion -L$fortran_libdir -lgfortran -lm
EOF

cat > "$prefix/lib/cmake/wavyadhesion/wavyadhesion-config.cmake" <<EOF
# CMake package of wavyadhesion $version, installed by tools/install.sh.
#   find_package(wavyadhesion CONFIG REQUIRED)
#   target_link_libraries(app PRIVATE wavyadhesion::wavyadhesion)
# The imported target carries the include directory (C header and Fortran modules), GSL
# (CMake's FindGSL: GSL::gsl) and, for projects without Fortran enabled, the gfortran
# runtime.
cmake_minimum_required(VERSION 3.14)
get_filename_component(_wavyadhesion_prefix "\${CMAKE_CURRENT_LIST_DIR}/../../.." ABSOLUTE)
include(CMakeFindDependencyMacro)
find_dependency(GSL)
if(NOT TARGET wavyadhesion::wavyadhesion)
   add_library(wavyadhesion::wavyadhesion STATIC IMPORTED)
   set(_wavyadhesion_libs GSL::gsl)
   get_property(_wavyadhesion_languages GLOBAL PROPERTY ENABLED_LANGUAGES)
   if(NOT "Fortran" IN_LIST _wavyadhesion_languages)
      find_library(WAVYADHESION_GFORTRAN_LIBRARY gfortran HINTS "$fortran_libdir")
      list(APPEND _wavyadhesion_libs "\${WAVYADHESION_GFORTRAN_LIBRARY}")
   endif()
   list(APPEND _wavyadhesion_libs m)
   set_target_properties(wavyadhesion::wavyadhesion PROPERTIES
      IMPORTED_LOCATION "\${_wavyadhesion_prefix}/lib/libwavyadhesion.a"
      IMPORTED_LINK_INTERFACE_LANGUAGES "Fortran"
      INTERFACE_INCLUDE_DIRECTORIES "\${_wavyadhesion_prefix}/include"
      INTERFACE_LINK_LIBRARIES "\${_wavyadhesion_libs}")
   unset(_wavyadhesion_libs)
   unset(_wavyadhesion_languages)
endif()
set(wavyadhesion_VERSION "$version")
unset(_wavyadhesion_prefix)
EOF

cat > "$prefix/lib/cmake/wavyadhesion/wavyadhesion-config-version.cmake" <<EOF
# Version of the installed wavyadhesion: compatible with a request of the same major
# version (for 0.x: the same minor version) that is not newer.
set(PACKAGE_VERSION "$version")
set(PACKAGE_VERSION_COMPATIBLE FALSE)
if(NOT PACKAGE_FIND_VERSION VERSION_GREATER PACKAGE_VERSION)
   string(REPLACE "." ";" _wa_have "\${PACKAGE_VERSION}")
   list(GET _wa_have 0 _wa_have_major)
   list(GET _wa_have 1 _wa_have_minor)
   if(PACKAGE_FIND_VERSION_MAJOR EQUAL _wa_have_major AND
      (NOT _wa_have_major EQUAL 0 OR PACKAGE_FIND_VERSION_MINOR EQUAL _wa_have_minor))
      set(PACKAGE_VERSION_COMPATIBLE TRUE)
   endif()
endif()
if(PACKAGE_FIND_VERSION STREQUAL PACKAGE_VERSION)
   set(PACKAGE_VERSION_EXACT TRUE)
endif()
EOF

echo "installed wavyadhesion $version into $prefix"
