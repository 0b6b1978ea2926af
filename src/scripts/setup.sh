#!/usr/bin/env bash
# Installs every build and test dependency from Debian 12 packages (clang-14
# and libFuzzer for src/scripts/fuzz.sh). Idempotent:
# packages already installed are skipped, and apt-get runs only when one is missing.
# Usage: setup.sh [--bench]   (--bench adds Intel Embree, used only by bench/)
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git clang-format
  libeigen3-dev libjsoncpp-dev libgtest-dev
  libpcl-dev libflann-dev
  libwebsocketpp-dev libboost-dev libboost-system-dev
  # The E57 reader's XML section (src/io/e57_xml.cpp).
  libpugixml-dev
  # Depth frames' PNG images (src/io/png_image.cpp).
  libpng-dev
  # The study's sharding recipes, run for real by tests/scripts/study_*_test.sh.
  slurm-wlm munge parallel
  # libFuzzer targets with ASan + UBSan (src/scripts/fuzz.sh).
  clang-14 libfuzzer-14-dev libclang-rt-14-dev
  # The Python module (src/python) and its tests.
  pybind11-dev python3-dev python3-numpy python3-pytest
  # The learned reference segmenter (python/occlusion_segmenter, docs/study.md).
  # libopenblas0-pthread: with Debian's reference BLAS torch is ~40x slower
  # (a 2000^3 matmul 8.4 s instead of 0.2 s; 127 s a training epoch).
  python3-torch libopenblas0-pthread
)
if [[ "${1:-}" == "--bench" ]]; then
  packages+=(libembree-dev)
fi
# The programs users open our outputs in, run by tests/io/third_party_readers_test.cpp
# (CloudCompare 2.11 headless under Xvfb, Open3D's tensor API, PCL's command-line
# tools). Optional: if they cannot be installed those tests skip, saying so.
readers=(cloudcompare xvfb xauth python3-open3d pcl-tools)

missing_from() {
  local package
  for package in "$@"; do
    if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
      echo "$package"
    fi
  done
}
mapfile -t missing < <(missing_from "${packages[@]}")
mapfile -t missing_readers < <(missing_from "${readers[@]}")

if ((${#missing[@]} == 0 && ${#missing_readers[@]} == 0)); then
  echo "setup: all ${#packages[@]} packages and ${#readers[@]} reader programs present"
  exit 0
fi

sudo=()
if [[ $(id -u) -ne 0 ]]; then
  if ! command -v sudo >/dev/null; then
    echo "setup: run as root to install: ${missing[*]} ${missing_readers[*]}" >&2
    # The reader programs are optional: only missing build packages fail.
    ((${#missing[@]} == 0)) && exit 0
    exit 1
  fi
  sudo=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
if ((${#missing[@]} > 0)); then
  echo "setup: installing ${missing[*]}"
  "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
if ((${#missing_readers[@]} > 0)); then
  echo "setup: installing reader programs ${missing_readers[*]}"
  "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing_readers[@]}" ||
    echo "setup: could not install ${missing_readers[*]}; the third-party reader tests will skip" >&2
fi
