#!/usr/bin/env bash
# Installs what the project needs on Debian 12 when it is missing: gfortran, GSL and
# pkg-config (apt-get), fpm (pip). Idempotent: does nothing when all are present.
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
command -v fpm >/dev/null || python3 -m pip install --quiet fpm
