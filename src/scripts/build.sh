#!/usr/bin/env bash
# Configures and builds into build/ (Release, warnings as errors, tests included).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${OCCLUSION_BUILD_DIR:-$root/build}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DOCCLUSION_WERROR=ON \
  -DOCCLUSION_BUILD_TESTS=ON >/dev/null
cmake --build "$build" -j "$(nproc)"
