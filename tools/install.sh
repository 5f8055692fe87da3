#!/usr/bin/env bash
# Installs the library for host codes into PREFIX (release build):
#   PREFIX/lib/libwavyadhesion.a                          static library
#   PREFIX/lib/libwavyadhesion.so.X.Y.Z                   shared library, soname
#   PREFIX/lib/libwavyadhesion.so.X.Y -> .so.X.Y.Z        libwavyadhesion.so.X.Y (the ABI of
#   PREFIX/lib/libwavyadhesion.so -> .so.X.Y              a 0.x release may change with Y)
#   PREFIX/include/wavyadhesion.h                         C header
#   PREFIX/include/wavyadhesion/<compiler-id>/wavyadhesion.mod
#                                                         the public Fortran module (gfortran's
#                                                         .mod of the umbrella is self-contained;
#                                                         compiler-id e.g. GNU-12.2.0, as stdlib
#                                                         and dftd4 do, so modules of several
#                                                         compilers can live side by side)
#   PREFIX/lib/pkgconfig/wavyadhesion.pc                  pkg-config (GSL in Requires.private)
#   PREFIX/lib/cmake/wavyadhesion/wavyadhesion-config.cmake (+ -config-version.cmake)
#                                                         CMake package, imported targets
#                                                         wavyadhesion::wavyadhesion (shared)
#                                                         and wavyadhesion::wavyadhesion_static
#   PREFIX/bin/wavyadhesion                               the command line
# fpm (`fpm install`, with `[install] library = true` in fpm.toml) builds and collects the
# archive and the executable into a staging directory (its objects are position
# independent, so the shared library is linked from the archive); this script writes what
# fpm cannot (shared library, header, module directory, pkg-config file, CMake package).
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

fc=${FC:-gfortran}
compiler_id="GNU-$("$fc" -dumpfullversion)"
moddir="include/wavyadhesion/$compiler_id"
major_minor=$(echo "$version" | cut -d. -f1,2)
soname="libwavyadhesion.so.$major_minor"

install -d "$prefix/lib/pkgconfig" "$prefix/lib/cmake/wavyadhesion" "$prefix/$moddir" \
   "$prefix/bin"
install -m 644 "$stage/lib/libwavyadhesion.a" "$prefix/lib/"
install -m 644 "$stage/include/wavyadhesion.mod" "$prefix/$moddir/"
install -m 644 include/wavyadhesion.h "$prefix/include/"
install -m 755 "$stage/bin/wavyadhesion" "$prefix/bin/"

# The shared library, from the archive's objects; --no-undefined: every symbol resolved
# by GSL, FFTW3 (with its threads library: fftw_make_planner_thread_safe) and the
# compiler's runtime, which it records as DT_NEEDED.
"$fc" -shared -o "$prefix/lib/libwavyadhesion.so.$version" -Wl,-soname,"$soname" \
   -Wl,--no-undefined -Wl,--whole-archive "$stage/lib/libwavyadhesion.a" \
   -Wl,--no-whole-archive $(pkg-config --libs gsl) -lfftw3_threads $(pkg-config --libs fftw3) -lm
ln -sf "libwavyadhesion.so.$version" "$prefix/lib/$soname"
ln -sf "$soname" "$prefix/lib/libwavyadhesion.so"

# A C host linking the static archive needs the gfortran runtime: named by its soname
# (-l:libgfortran.so.5), which the linker finds in the system's library path, so no
# compiler-internal directory is written into the .pc.
gfortran_soname=$(readelf -d "$("$fc" -print-file-name=libgfortran.so)" \
   | sed -n 's/.*Library soname: \[\(.*\)\].*/\1/p')
[ -n "$gfortran_soname" ] || { echo "tools/install.sh: no soname for libgfortran" >&2; exit 1; }

cat > "$prefix/lib/pkgconfig/wavyadhesion.pc" <<EOF
# wavyadhesion $version, installed by tools/install.sh.
#   shared: cc ex.c \$(pkg-config --cflags --libs wavyadhesion)
#   static: cc ex.c \$(pkg-config --cflags wavyadhesion) PREFIX/lib/libwavyadhesion.a \\
#           \$(pkg-config --static --libs-only-l wavyadhesion | sed 's/-lwavyadhesion//')
# Fortran hosts: fmoddir holds wavyadhesion.mod for $compiler_id.
prefix=$prefix
libdir=\${prefix}/lib
includedir=\${prefix}/include
fmoddir=\${includedir}/wavyadhesion/$compiler_id

Name: wavyadhesion
Description: Adhesive contact of a wavy elastic surface (Westergaard, JKR, double-Westergaard, Maugis-Dugdale)
Version: $version
Requires.private: gsl fftw3
Cflags: -I\${includedir} -I\${fmoddir}
Libs: -L\${libdir} -lwavyadhesion
Libs.private: -lfftw3_threads -l:$gfortran_soname -lm
EOF

cat > "$prefix/lib/cmake/wavyadhesion/wavyadhesion-config.cmake" <<EOF
# CMake package of wavyadhesion $version, installed by tools/install.sh.
#   find_package(wavyadhesion CONFIG REQUIRED)
#   target_link_libraries(app PRIVATE wavyadhesion::wavyadhesion)         # shared
#   target_link_libraries(app PRIVATE wavyadhesion::wavyadhesion_static)  # static
# Both targets carry the include directories (C header; Fortran module of $compiler_id).
# The static one also links GSL (CMake's FindGSL: GSL::gsl), FFTW3 (fftw3_threads, fftw3)
# and, for projects without
# Fortran enabled, the gfortran runtime; the shared library records them itself.
cmake_minimum_required(VERSION 3.14)
get_filename_component(_wavyadhesion_prefix "\${CMAKE_CURRENT_LIST_DIR}/../../.." ABSOLUTE)
set(_wavyadhesion_includes "\${_wavyadhesion_prefix}/include"
   "\${_wavyadhesion_prefix}/$moddir")
if(NOT TARGET wavyadhesion::wavyadhesion)
   add_library(wavyadhesion::wavyadhesion SHARED IMPORTED)
   set_target_properties(wavyadhesion::wavyadhesion PROPERTIES
      IMPORTED_LOCATION "\${_wavyadhesion_prefix}/lib/libwavyadhesion.so.$version"
      IMPORTED_SONAME "$soname"
      INTERFACE_INCLUDE_DIRECTORIES "\${_wavyadhesion_includes}")
endif()
if(NOT TARGET wavyadhesion::wavyadhesion_static)
   include(CMakeFindDependencyMacro)
   find_dependency(GSL)
   add_library(wavyadhesion::wavyadhesion_static STATIC IMPORTED)
   set(_wavyadhesion_libs GSL::gsl fftw3_threads fftw3)
   get_property(_wavyadhesion_languages GLOBAL PROPERTY ENABLED_LANGUAGES)
   if(NOT "Fortran" IN_LIST _wavyadhesion_languages)
      list(APPEND _wavyadhesion_libs "-l:$gfortran_soname")
   endif()
   list(APPEND _wavyadhesion_libs m)
   set_target_properties(wavyadhesion::wavyadhesion_static PROPERTIES
      IMPORTED_LOCATION "\${_wavyadhesion_prefix}/lib/libwavyadhesion.a"
      IMPORTED_LINK_INTERFACE_LANGUAGES "Fortran"
      INTERFACE_INCLUDE_DIRECTORIES "\${_wavyadhesion_includes}"
      INTERFACE_LINK_LIBRARIES "\${_wavyadhesion_libs}")
   unset(_wavyadhesion_libs)
   unset(_wavyadhesion_languages)
endif()
set(wavyadhesion_VERSION "$version")
unset(_wavyadhesion_includes)
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
