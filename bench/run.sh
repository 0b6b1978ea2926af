#!/usr/bin/env bash
# Builds the benchmarks (Release, in build-bench) and runs bench_moc, then bench_poc.
# Run by hand, never in CI. Arguments are passed on to each bench run, e.g.
#   bench/run.sh --threads 1
# OCCLUSION_BENCH=poc bench/run.sh --points 2000000 runs one of them (moc, poc;
# default all: then give only flags both know: --triangles --threads --seed --cli).
# OCCLUSION_NATIVE=ON bench/run.sh builds with -march=native.
set -euo pipefail

selected="${OCCLUSION_BENCH:-all}"
case "$selected" in
  moc | poc | all) ;;
  *)
    echo "run.sh: OCCLUSION_BENCH must be moc, poc or all, got '$selected'" >&2
    exit 2
    ;;
esac

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
cmake --build "$build" -j"$(nproc)" --target bench_moc bench_poc generate_room occlusion
if [ "$selected" != poc ]; then "$build/bench/bench_moc" "$@"; fi
if [ "$selected" = all ]; then echo; fi
if [ "$selected" != moc ]; then "$build/bench/bench_poc" "$@"; fi
