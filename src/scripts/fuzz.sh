#!/usr/bin/env bash
# Runs each libFuzzer target (clang-14, ASan + UBSan: the build in build-clang/
# that the sanitized test suite shares; src/scripts/build_sanitized.sh builds
# it, or finds it built) for FUZZ_SECONDS (default 15) from its seed corpus in
# tests/fuzz/corpus/<name>. New inputs go to build-clang/corpus/<name>, never
# into the committed seeds. A finding stops that target, leaves its input in
# build-clang/findings/ and makes this script fail. docs/fuzzing.md explains.
#
#   bash src/scripts/fuzz.sh                       # the brief run of test.sh
#   FUZZ_SECONDS=1800 bash src/scripts/fuzz.sh     # a long run, 30 min per target
#   bash src/scripts/fuzz.sh fuzz_pcd_compressed   # only the named targets
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${OCCLUSION_SANITIZED_BUILD_DIR:-$root/build-clang}"
seconds="${FUZZ_SECONDS:-15}"
targets=("$@")
if ((${#targets[@]} == 0)); then
  targets=(fuzz_obj fuzz_ply fuzz_pcd_ascii fuzz_pcd_binary fuzz_pcd_compressed fuzz_text_cloud
           fuzz_e57 fuzz_las fuzz_depth_frame fuzz_s3dis fuzz_labels fuzz_class_names fuzz_scannet
           fuzz_openings fuzz_config
           fuzz_server_message fuzz_binary_frame)
fi

bash "$root/src/scripts/build_sanitized.sh" "${targets[@]}"

mkdir -p "$build/findings" "$build/logs"
# Leaks are findings too; an input that takes over 10 s or 2 GB is a hang or a bomb.
export ASAN_OPTIONS="${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
# One target a core at a time (libFuzzer runs one process each); each writes
# its verdict to a file, read in the targets' order once all have ended.
jobs="${OCCLUSION_JOBS:-$(nproc)}"
fuzz_one() {
  local target="$1" seeds corpus log start status=0 elapsed runs
  seeds="$root/tests/fuzz/corpus/${target#fuzz_}"
  corpus="$build/corpus/${target#fuzz_}"
  mkdir -p "$corpus"
  log="$build/logs/$target.log"
  start=$(date +%s)
  "$build/tests/fuzz/$target" "$corpus" "$seeds" -max_total_time="$seconds" -timeout=10 \
    -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 \
    -artifact_prefix="$build/findings/$target-" >"$log" 2>&1 || status=$?
  elapsed=$(($(date +%s) - start))
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo "?")
  if ((status == 0)); then
    echo "fuzz: $target ran ${elapsed} s, $runs inputs, no finding" >"$log.verdict"
  else
    {
      echo "fuzz: $target FOUND a problem after ${elapsed} s (log $log, input in $build/findings/)"
      grep -m 5 -E 'ERROR|fuzz:|runtime error' "$log" || true
    } >"$log.verdict"
    echo "$target" >"$log.failed"
  fi
}
running=0
for target in "${targets[@]}"; do
  rm -f "$build/logs/$target.log.verdict" "$build/logs/$target.log.failed"
  if ((running >= jobs)); then
    wait -n
    running=$((running - 1))
  fi
  fuzz_one "$target" &
  running=$((running + 1))
done
wait
failed=()
for target in "${targets[@]}"; do
  cat "$build/logs/$target.log.verdict"
  [[ -f "$build/logs/$target.log.failed" ]] && failed+=("$target")
done
if ((${#failed[@]} > 0)); then
  echo "fuzz: findings in ${failed[*]}" >&2
  exit 1
fi
