#!/usr/bin/env bash
# Installs the Debian 12 packages ModalTyre builds on, if any is missing. Idempotent; uses sudo
# when not run as root. Nothing is downloaded from anywhere but Debian's package archive.
set -euo pipefail
packages=(build-essential cmake ninja-build pkg-config
  libeigen3-dev libsundials-dev libsuitesparse-dev libgtest-dev libgmock-dev
  libyaml-cpp-dev nlohmann-json3-dev libcli11-dev libbenchmark-dev libzip-dev
  gnuplot-nox python3-numpy python3-scipy libopenmpi-dev openmpi-bin
  pybind11-dev python3-dev python3-pytest
  libxml2-utils
  clang-14 libclang-rt-14-dev libomp-14-dev llvm-14)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  exit 0
fi
echo "installing: ${missing[*]}" >&2
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
