#!/usr/bin/env bash
# Builds the benchmarks (Release, in build-bench) and runs them in turn:
# bench_moc, bench_poc, bench_discs, bench_plan, bench_rgoc, bench_server, bench_simulate,
# bench_stations. Run by hand, never in CI.
# OCCLUSION_BENCH=poc bench/run.sh --points 2000000 runs one of them (moc, poc,
# discs, plan, rgoc, server, simulate, stations) and passes the arguments on to it; with all (the default) the
# benches run with their defaults.
# OCCLUSION_NATIVE=ON bench/run.sh builds with -march=native.
set -euo pipefail

selected="${OCCLUSION_BENCH:-all}"
case "$selected" in
  moc | poc | discs | plan | rgoc | server | simulate | stations | all) ;;
  *)
    echo "run.sh: OCCLUSION_BENCH must be moc, poc, discs, plan, rgoc, server, simulate, stations or all, got '$selected'" >&2
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
cmake --build "$build" -j"$(nproc)" --target bench_moc bench_poc bench_discs bench_plan bench_rgoc bench_server bench_simulate bench_stations \
  embree_job generate_room occlusion
if [ "$selected" != all ]; then
  "$build/bench/bench_$selected" "$@"
  exit
fi
for bench in moc poc discs plan rgoc server simulate stations; do
  echo "== bench_$bench"
  "$build/bench/bench_$bench"
  echo
done
