#!/usr/bin/env bash
# Installs the Debian packages cvms needs when they are missing (as root), or
# prints the exact install line (otherwise). Safe to run repeatedly.
set -euo pipefail
# The Python module (CVMS_BUILD_PYTHON, on in the dev preset) and its tests:
# pybind11, Debian's python3 with numpy and headers, pytest, dask.distributed.
packages=(cmake ninja-build g++ pkg-config libgmp-dev libgtest-dev libbenchmark-dev libcli11-dev
          pybind11-dev python3-dev python3-numpy python3-pytest python3-distributed)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep "install ok installed" >/dev/null || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
if [ "$(id -u)" -eq 0 ]; then
  echo "cvms: installing ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
else
  echo "cvms: missing packages; run: sudo apt-get install -y ${missing[*]}" >&2
  exit 1
fi
