#!/usr/bin/env bash
# Configures and builds into build/ (Release, warnings as errors, tests included).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${OCCLUSION_BUILD_DIR:-$root/build}"
# Ninja for a new build directory (setup.sh installs it): it keeps both cores
# busy across targets and logs each file's time (.ninja_log, docs/ci.md). An
# existing build directory keeps the generator it was made with.
export CMAKE_GENERATOR="${CMAKE_GENERATOR:-Ninja}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DOCCLUSION_WERROR=ON \
  -DOCCLUSION_BUILD_TESTS=ON >/dev/null
cmake --build "$build" -j "$(nproc)"
