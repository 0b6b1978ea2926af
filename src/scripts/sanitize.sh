#!/usr/bin/env bash
# Builds GoogleTest suites with AddressSanitizer and UndefinedBehaviorSanitizer
# (gcc, -O1, into build-asan/) and runs them through ctest; any sanitizer
# report fails its test. docs/fuzzing.md explains.
#
#   bash src/scripts/sanitize.sh            # every layer's suite
#   bash src/scripts/sanitize.sh core io    # some layers (what test.sh runs)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${OCCLUSION_ASAN_BUILD_DIR:-$root/build-asan}"
layers=("$@")
if ((${#layers[@]} == 0)); then layers=(core io analysis app cli server); fi
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g" \
  -DOCCLUSION_SANITIZE=ON -DOCCLUSION_WERROR=ON -DOCCLUSION_BUILD_TESTS=ON >/dev/null
targets=()
for layer in "${layers[@]}"; do targets+=("test_$layer"); done
cmake --build "$build" -j "$(nproc)" --target "${targets[@]}"
export ASAN_OPTIONS="${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$root/tests/fuzz/lsan_suppressions.txt}"
regex="^($(IFS='|'; echo "${layers[*]}"))\$"
ctest --test-dir "$build" -j "$(nproc)" --output-on-failure -L "$regex"
