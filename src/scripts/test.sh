#!/usr/bin/env bash
# Sets up, builds once and runs every test: C++ formatting, then all GoogleTest
# cases in parallel through ctest.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
bash "$root/src/scripts/setup.sh"
bash "$root/src/scripts/check_format.sh"
bash "$root/src/scripts/build.sh"
build="${OCCLUSION_BUILD_DIR:-$root/build}"
ctest --test-dir "$build" -j "$(nproc)" --output-on-failure
