#!/bin/sh
# Wall time of `wavyadhesion point` on 10000, 20000 and 40000 values of a* (DW, the
# defaults alpha 0.3, mu 1): linear when the rows are kept in a doubling array (issue 9
# measured 1.2 / 5.3 / 28 s with the quadratic `rows = [rows, ...]`). The values are
# .1,.2,.3,.4 repeated, 3 bytes each: Linux limits one argument to 128 KiB.
# Usage: sh benchmark/cli_point_scaling.sh [path/to/wavyadhesion]
set -e
exe=${1:-$(fpm run --profile release --runner echo wavyadhesion 2>/dev/null | tail -n 1)}
for n in 10000 20000 40000; do
   values=$(python3 -c "print(','.join(['.1', '.2', '.3', '.4'] * ($n // 4)))")
   start=$(date +%s.%N)
   "$exe" point --a-star "$values" > /dev/null
   end=$(date +%s.%N)
   python3 -c "print(f'point, $n values of a*: {$end - $start:.2f} s')"
done
