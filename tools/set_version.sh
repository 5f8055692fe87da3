#!/usr/bin/env bash
# Sets the library's version: the file VERSION (the one source, read by fpm.toml and
# python/meson.build) and the copies that cannot read it: wa_version in src/wa_release.f90
# (Fortran, C, CLI) and `version:` in CITATION.cff. test/docs checks that they agree.
# Usage: bash tools/set_version.sh X.Y.Z      (run from the repository root)
set -euo pipefail
[ $# -eq 1 ] && [[ $1 =~ ^[0-9]+\.[0-9]+\.[0-9]+$ ]] \
   || { echo "usage: bash tools/set_version.sh X.Y.Z (semantic version)" >&2; exit 2; }
[ -f VERSION ] && [ -f src/wa_release.f90 ] \
   || { echo "tools/set_version.sh: run from the repository root" >&2; exit 1; }
new=$1
echo "$new" > VERSION
sed -i -E "s/(wa_version = \")[0-9]+\.[0-9]+\.[0-9]+(\")/\1$new\2/" src/wa_release.f90
sed -i -E "s/^version: .*/version: $new/" CITATION.cff
grep -q "wa_version = \"$new\"" src/wa_release.f90 && grep -q "^version: $new$" CITATION.cff \
   || { echo "tools/set_version.sh: could not set the version everywhere" >&2; exit 1; }
echo "version $new: VERSION, src/wa_release.f90, CITATION.cff (rebuild; CHANGELOG.md is by hand)"
