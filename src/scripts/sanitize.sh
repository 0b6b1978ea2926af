#!/usr/bin/env bash
# Builds the tool and every C++ test suite with AddressSanitizer and
# UndefinedBehaviorSanitizer (gcc -O1 -g1: line tables are enough for reports and build faster, into build-asan/, through ccache when
# it is installed) and runs the whole ctest suite on them, in parallel; any
# sanitizer report or leak fails its test. Tests labelled <layer>_no_sanitizer
# are left out (tests/CMakeLists.txt, docs/fuzzing.md say which and why). test.sh runs
# it under a time limit.
#
#   bash src/scripts/sanitize.sh            # the whole suite (what test.sh runs)
#   bash src/scripts/sanitize.sh core io    # some layers' suites only
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${OCCLUSION_ASAN_BUILD_DIR:-$root/build-asan}"
jobs="${OCCLUSION_JOBS:-$(nproc)}"
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" \
  -DOCCLUSION_SANITIZE=ON -DOCCLUSION_WERROR=ON -DOCCLUSION_BUILD_TESTS=ON \
  -DOCCLUSION_BUILD_PYTHON=OFF "${launcher[@]}" >/dev/null
select=(-LE no_sanitizer)
if (($# == 0)); then
  # Everything: the study's script tests and the CLI and server suites run the tool.
  cmake --build "$build" -j "$jobs"
else
  targets=()
  for layer in "$@"; do targets+=("test_$layer"); done
  cmake --build "$build" -j "$jobs" --target "${targets[@]}"
  select+=(-L "^($(IFS='|'; echo "$*"))\$")
fi
export ASAN_OPTIONS="${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$root/tests/fuzz/lsan_suppressions.txt:print_suppressions=0}"
ctest --test-dir "$build" -j "$jobs" --output-on-failure "${select[@]}"
