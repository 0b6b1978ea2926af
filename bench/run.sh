#!/usr/bin/env bash
# Builds the benchmarks (Release, in build-bench) and runs bench_moc.
# Run by hand, never in CI. Arguments are passed on to bench_moc, e.g.
#   bench/run.sh --threads 1
# OCCLUSION_NATIVE=ON bench/run.sh builds with -march=native.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$repo/build-bench"

# Embree is the yardstick; only the benchmark needs it.
if ! dpkg-query -W -f='${Status}' libembree-dev 2>/dev/null | grep -q "install ok installed"; then
  if [ "$(id -u)" -ne 0 ]; then
    echo "run.sh: libembree-dev is missing; run as root to install it, or apt-get install it" >&2
    exit 1
  fi
  apt-get update
  DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends libembree-dev
fi

cmake -S "$repo" -B "$build" -DCMAKE_BUILD_TYPE=Release -DOCCLUSION_BUILD_BENCH=ON \
  -DOCCLUSION_NATIVE="${OCCLUSION_NATIVE:-OFF}"
cmake --build "$build" -j"$(nproc)" --target bench_moc generate_room occlusion
"$build/bench/bench_moc" "$@"
