#!/usr/bin/env bash
# Installs every build and test dependency from Debian 12 packages. Idempotent:
# packages already installed are skipped, and apt-get runs only when one is missing.
# Usage: setup.sh [--bench]   (--bench adds Intel Embree, used only by bench/)
set -euo pipefail

packages=(
  build-essential cmake pkg-config git clang-format
  libeigen3-dev libjsoncpp-dev libgtest-dev
  libpcl-dev libflann-dev
  libwebsocketpp-dev libboost-dev libboost-system-dev
  pybind11-dev python3-dev python3-numpy python3-pytest
)
if [[ "${1:-}" == "--bench" ]]; then
  packages+=(libembree-dev)
fi

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

if ((${#missing[@]} == 0)); then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

sudo=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "setup: run as root to install: ${missing[*]}" >&2; exit 1; }
  sudo=(sudo)
fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
