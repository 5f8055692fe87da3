#!/bin/sh
# Measurements behind the MD module's numerical choices (src/wa_md.f90), run from the
# repository root: Psi_c quadrature error vs time (md_quadrature_study), time per
# equilibrium (md_timing) and a brute-force check of the root bracketing
# (md_root_scan_check, about 30 minutes on one core). Builds in a scratch directory,
# not in build/.
# Usage: tools/md_study.sh [study|timing|scan]...   (default: study timing)
set -e
root=$(pwd)
work=${TMPDIR:-/tmp}/wa_md_study.$$
mkdir -p "$work"
trap 'rm -rf "$work"' EXIT
cd "$work"
for m in wa_kinds wa_status wa_validate wa_params wa_state wa_math wa_roots wa_gsl wa_separation wa_md; do
   gfortran -O2 -c "$root/src/$m.f90"
done
gfortran -O2 -c "$root/study/wa_psi_methods.f90"      # the Psi_c alternatives, shared with study/
objs="wa_kinds.o wa_status.o wa_validate.o wa_params.o wa_state.o wa_math.o wa_roots.o wa_gsl.o wa_separation.o wa_md.o wa_psi_methods.o"
[ $# -eq 0 ] && set -- study timing
for what in "$@"; do
   case $what in
      study)  prog=md_quadrature_study ;;
      timing) prog=md_timing ;;
      scan)   prog=md_root_scan_check ;;
      *) echo "unknown: $what" >&2; exit 2 ;;
   esac
   gfortran -O2 -I. "$root/tools/$prog.f90" $objs -lgsl -lgslcblas -lm -o $prog
   (cd "$root" && "$work/$prog")
done
