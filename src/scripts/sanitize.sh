#!/usr/bin/env bash
# Runs the whole ctest suite on the tool and every C++ test suite built with
# AddressSanitizer and UndefinedBehaviorSanitizer: clang-14's build in
# build-clang/, which the fuzz targets share (src/scripts/build_sanitized.sh
# builds it, or finds it built), in parallel; any sanitizer report or leak
# fails its test. Tests labelled <layer>_no_sanitizer are left out
# (tests/CMakeLists.txt, docs/fuzzing.md say which and why).
#
#   bash src/scripts/sanitize.sh            # the whole suite (what test.sh runs)
#   bash src/scripts/sanitize.sh core io    # some layers' suites only
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${OCCLUSION_SANITIZED_BUILD_DIR:-$root/build-clang}"
jobs="${OCCLUSION_JOBS:-$(nproc)}"
select=(-LE no_sanitizer)
if (($# == 0)); then
  # Everything: the study's script tests and the CLI and server suites run the tool.
  bash "$root/src/scripts/build_sanitized.sh" test_suites
else
  targets=()
  for layer in "$@"; do targets+=("test_$layer"); done
  bash "$root/src/scripts/build_sanitized.sh" "${targets[@]}"
  select+=(-L "^($(IFS='|'; echo "$*"))\$")
fi
export ASAN_OPTIONS="${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$root/tests/fuzz/lsan_suppressions.txt:print_suppressions=0}"
ctest --test-dir "$build" -j "$jobs" --output-on-failure "${select[@]}"
