#!/bin/sh
# Measurements behind the MD module's numerical choices (src/wa_md.f90), run from the
# repository root: Psi_c quadrature error vs time (wavyadhesion-psi-quadrature), time per
# equilibrium (wavyadhesion-md-timing) and a brute-force check of the root bracketing
# (wavyadhesion-md-root-scan, about 30 minutes on one core). fpm builds them with the
# library (release profile, the study's own package: study/fpm.toml).
# Usage: sh study/md_study.sh [study|timing|scan]...   (default: study timing)
set -e
fpm=fpm
[ -x .venv/bin/fpm ] && fpm=$PWD/.venv/bin/fpm
[ $# -eq 0 ] && set -- study timing
for what in "$@"; do
   case $what in
      study)  prog=wavyadhesion-psi-quadrature ;;
      timing) prog=wavyadhesion-md-timing ;;
      scan)   prog=wavyadhesion-md-root-scan ;;
      *) echo "study/md_study.sh: unknown: $what (study, timing or scan)" >&2; exit 2 ;;
   esac
   (cd study && "$fpm" run --profile release "$prog")
done
