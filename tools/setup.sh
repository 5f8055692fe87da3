#!/usr/bin/env bash
# Installs what the project needs on Debian 12 when it is missing: gfortran, GSL and
# pkg-config (apt-get); fpm, numpy, pytest, meson, meson-python, ninja (pip).
# Idempotent: does nothing when everything is present.
set -euo pipefail
need_apt=()
command -v gfortran >/dev/null || need_apt+=(gfortran)
[ -e /usr/include/gsl/gsl_sf_ellint.h ] || need_apt+=(libgsl-dev)
command -v pkg-config >/dev/null || need_apt+=(pkg-config)
if [ ${#need_apt[@]} -gt 0 ]; then
   sudo_cmd=""
   [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
   $sudo_cmd apt-get update -qq
   DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq "${need_apt[@]}"
fi
need_pip=()
command -v fpm >/dev/null || need_pip+=(fpm)
for mod in numpy pytest mesonpy; do
   python3 -c "import $mod" 2>/dev/null || need_pip+=("${mod/mesonpy/meson-python}")
done
command -v meson >/dev/null || need_pip+=(meson)
command -v ninja >/dev/null || need_pip+=(ninja)
if [ ${#need_pip[@]} -gt 0 ]; then
   python3 -m pip install --quiet "${need_pip[@]}"
fi
