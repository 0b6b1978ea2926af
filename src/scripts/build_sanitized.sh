#!/usr/bin/env bash
# Configures and builds the one clang-14 build that both the sanitized test
# suite (src/scripts/sanitize.sh) and the fuzz targets (src/scripts/fuzz.sh)
# run from, into build-clang/: every library of ours, the tool and the test
# suites with ASan + UBSan and libFuzzer's coverage (-fsanitize=fuzzer-no-link,
# CMake option OCCLUSION_FUZZ); the tests link GoogleTest's main, the fuzz
# targets libFuzzer's. -O1 -g1: line tables are enough for reports and build
# faster. Through ccache when it is installed. docs/fuzzing.md, docs/ci.md.
#
#   bash src/scripts/build_sanitized.sh                 # tests, the tool, fuzz targets
#   bash src/scripts/build_sanitized.sh test_core       # some targets only
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${OCCLUSION_SANITIZED_BUILD_DIR:-$root/build-clang}"
jobs="${OCCLUSION_JOBS:-$(nproc)}"
targets=("$@")
# What sanitize.sh and fuzz.sh run, and nothing else (not the sample generators).
((${#targets[@]} > 0)) || targets=(test_suites fuzz_targets)
launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  # Without these ccache compiles every file that uses a precompiled header
  # (CMake's OCCLUSION_PCH) afresh (ccache's manual, "Precompiled headers").
  export CCACHE_SLOPPINESS="${CCACHE_SLOPPINESS:-pch_defines,time_macros,include_file_mtime,include_file_ctime}"
fi
# Ninja for a new build directory (setup.sh installs it); an existing one keeps its generator.
export CMAKE_GENERATOR="${CMAKE_GENERATOR:-Ninja}"
cmake -S "$root" -B "$build" -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=Debug \
  -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" -DOCCLUSION_FUZZ=ON -DOCCLUSION_WERROR=ON \
  -DOCCLUSION_BUILD_TESTS=ON -DOCCLUSION_BUILD_PYTHON=OFF "${launcher[@]}" >/dev/null
cmake --build "$build" -j "$jobs" --target "${targets[@]}"
