#!/usr/bin/env bash
# Installs every Debian 12 package Plumbago needs to build, test, benchmark and plot.
# Run as root or with sudo available. Safe to run again.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git
  libopenmesh-dev libembree-dev libopenimageio-dev libcgal-dev libeigen3-dev libglm-dev
  libcli11-dev nlohmann-json3-dev libpugixml-dev libtbb-dev libgtest-dev libgmock-dev libbenchmark-dev
  libegl-dev libopengl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri libosmesa6-dev
  python3-matplotlib python3-numpy
  pybind11-dev python3-dev python3-pytest  # the Python module (python/) and its tests
  snakemake
  libglfw3-dev libimgui-dev xvfb xauth
  clang-14 libclang-rt-14-dev llvm-14  # scripts/sanitize.sh: ASan, UBSan, libFuzzer, llvm-symbolizer
  clang-format-14  # scripts/format.sh --check (CI)
)

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: run as root or install sudo" >&2; exit 1; }
  sudo_cmd=(sudo)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages are installed"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
