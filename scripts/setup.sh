#!/usr/bin/env bash
# Installs every Debian 12 package Casteljau needs to build, test and benchmark.
# Idempotent: packages already present are skipped by apt; safe to rerun.
# Run as root (or with sudo available). Nothing is downloaded outside apt.
set -euo pipefail

packages=(
  cmake ninja-build g++ pkg-config git
  libopenimageio-dev openimageio-tools
  libpng-dev libtiff-dev libjpeg-dev libwebp-dev libopenexr-dev libdeflate-dev zlib1g-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libpugixml-dev libcli11-dev
  librsvg2-bin python3 doxygen
  libcairo2-dev
  clang libclang-rt-14-dev
  python3-dev pybind11-dev python3-pybind11 python3-numpy python3-pytest
  python3-dask python3-distributed python3-pil
  libfontconfig-dev libfreetype-dev libharfbuzz-dev libfribidi-dev
  fonts-dejavu-core fonts-noto-core fonts-noto-mono fonts-noto-cjk
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if ((${#missing[@]} == 0)); then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

SUDO=""
if [[ $(id -u) -ne 0 ]]; then SUDO="sudo"; fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
