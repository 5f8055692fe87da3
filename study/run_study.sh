#!/bin/sh
# Reproduce every number of doc/accuracy-performance.md. Run from the repository root:
#   sh study/run_study.sh            (about 15 min on the 2-core development machine when
#                                     the mpmath references have to be computed, 2 min if not)
# Steps 1 and 3 compute mpmath references (tools/reference/study_reference.py, mp.dps = 50) and are
# skipped when their output exists (delete study/data/*.txt to recompute them).
set -e
python3 -c "import scipy, matplotlib, mpmath" 2>/dev/null || python3 -m pip install scipy matplotlib mpmath
mkdir -p build/study
# 1. mpmath states on the extreme grid (7 alpha x 7 mu x 5 a*, DW and MD; ~8 min on one core)
[ -f study/data/extreme_md.txt ] || python3 tools/reference/study_reference.py grid --jobs 2
# 2. the library's traced branches, folds, case switches, critical-force points and curve
#    points, written with its values for the mpmath check
(cd study && fpm run --profile release wavyadhesion-study -- samples)
# 3. mpmath check of those (~6 min on one core), redone only when the library's points changed
h=$(sha256sum study/data/samples.txt | cut -d' ' -f1)
grep -q "input sha256 $h" study/data/samples_check.txt 2>/dev/null \
   || python3 tools/reference/study_reference.py check --jobs 2
# 4. the study itself (work-precision DW and MD, scipy peer, 400-point curves, extreme grid)
(cd study && fpm run --profile release wavyadhesion-study) 2>&1 | tee build/study/study.log
# 5. the figure, and the summary of the mpmath check of branches and critical forces
python3 study/plot_study.py build/study doc/figures
python3 study/summarize_check.py study/data/samples_check.txt | tee build/study/check_summary.txt
# 6. Psi_c alone (error vs time per Psi_c, 64 cases; the MD module's own study)
sh study/md_study.sh study | tee build/study/psi_c.txt
# 7. the performance-target benchmark, for the record
(cd study && fpm run --profile release wavyadhesion-benchmark) | tee build/study/benchmark.txt
# Not run here (needs tamaas, ~25 min CPU): the boundary-element cross-check of the MD gap
# law, doc/accuracy-performance.md section 10:
#   OMP_NUM_THREADS=1 python study/bem/tamaas_md.py --jobs 2 --out study/results/bem_md.txt
