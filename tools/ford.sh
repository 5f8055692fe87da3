#!/usr/bin/env bash
# Builds the Fortran API reference with FORD (PyPI `ford`, installed into .venv by
# tools/setup.sh) from the `!>` comments in src/, into doc/api/ (open doc/api/index.html).
# Project file: doc/ford.md. Fails when FORD prints any warning or error. The pages
# render offline (tools/ford_offline.py: a local Bootstrap, no CDN); the index lists the
# public API only (tools/ford_public.py; internal modules carry `display: none`).
# Usage: bash tools/ford.sh
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x .venv/bin/ford ] && export PATH="$PWD/.venv/bin:$PATH"
# tools/ford_markdown.py: asterisks in a*, P* are names, not emphasis.
export PYTHONPATH="$PWD/tools${PYTHONPATH:+:$PYTHONPATH}"
log=$(mktemp)
trap 'rm -f "$log"' EXIT
status=0
(cd doc && COLUMNS=1000 ford ford.md) > "$log" 2>&1 || status=$?
# FORD prints a warning for a [[link]] it cannot resolve and for a doc comment whose first
# line reads `word: ...` (taken as metadata and dropped), hence quiet: false in doc/ford.md.
if [ "$status" -ne 0 ] || grep -qiE "warning|error" "$log"; then
   cat "$log" >&2
   echo "tools/ford.sh: FORD failed or warned (exit status $status)" >&2
   exit 1
fi
# The index (procedure and type lists, index.html) lists only what `use wavyadhesion` exports.
python3 tools/ford_public.py doc/api src
# Offline: Bootstrap from Debian's libjs-bootstrap5 instead of FORD's CDN links.
python3 tools/ford_offline.py doc/api src
echo "FORD API reference: doc/api/index.html ($(find doc/api -name '*.html' | wc -l) pages)"
