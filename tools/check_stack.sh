#!/usr/bin/env bash
# Fails (exit 1) when a binary or shared library needs an executable stack: its GNU_STACK
# program header is RWE, or it has none (the linker then assumes an executable stack).
# gfortran builds an executable stack where an internal procedure is passed as an argument
# (a trampoline); glibc 2.41 and later refuse to dlopen such a library.
# Usage: bash tools/check_stack.sh FILE...
set -euo pipefail
[ $# -gt 0 ] || { echo "usage: bash tools/check_stack.sh FILE..." >&2; exit 2; }
command -v readelf >/dev/null || { echo "tools/check_stack.sh: readelf not found (binutils)" >&2; exit 1; }
bad=0
for f in "$@"; do
   flags=$(readelf -lW "$f" | awk '$1 == "GNU_STACK" {print $(NF-1)}')
   if [ "$flags" = "RW" ]; then
      echo "stack ok (GNU_STACK RW): $f"
   else
      echo "executable stack (GNU_STACK ${flags:-missing}): $f" >&2
      bad=1
   fi
done
exit $bad
