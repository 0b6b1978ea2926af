#!/usr/bin/env bash
# src/scripts/experiment.sh end to end at a tiny size (one room to train on,
# one held out, two training steps): every stage runs and writes what the next
# reads, the study gets one ok row per configuration of config/experiment.json,
# and a second call resumes: it redoes nothing. Skips (exit 77) where
# python3-torch is missing (src/scripts/setup.sh installs it).
# usage: experiment_test.sh BUILD_DIR
set -euo pipefail
build="$(realpath "$1")"
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
fail() {
  echo "experiment_test: $*" >&2
  exit 1
}
/usr/bin/python3 -c 'import torch' 2>/dev/null || {
  echo "experiment_test: skipped: python3-torch is not installed" >&2
  exit 77
}
work="$(mktemp -d "${TMPDIR:-/tmp}/occlusion-experiment.XXXXXX")"
trap 'rm -rf "$work"' EXIT

run() {
  OCCLUSION_BUILD="$build" TRAIN_ROOMS=1 TEST_ROOMS=1 SPACING=0.08 STEPS=2 THREADS=1 \
    timeout --kill-after=10 500 bash "$source_dir/src/scripts/experiment.sh" "$work/out" \
    >"$work/$1.log" 2>&1 || {
    cat "$work/$1.log" >&2
    fail "the experiment failed ($1 call)"
  }
}
run first
for made in rooms_train/Area_1 rooms_test/Area_1 segmenter.pt evaluate.txt study/study.csv \
  study/study.md; do
  [[ -e "$work/out/$made" ]] || fail "no $made"
done
grep -q '^mIoU [0-9.]* over' "$work/out/evaluate.txt" || fail "evaluate.txt has no mIoU line"
configurations=$(grep -c '"pattern"' "$source_dir/config/experiment.json")
ok_rows=$(tail -n +2 "$work/out/study/study.csv" | grep -c ',ok,' || true)
[[ "$ok_rows" -eq "$configurations" ]] ||
  fail "study.csv has $ok_rows ok runs, want one per configuration ($configurations)"

cp "$work/out/segmenter.pt" "$work/first.pt"
run second
cmp -s "$work/out/segmenter.pt" "$work/first.pt" || fail "the second call trained again"
grep -q 'training the segmenter' "$work/second.log" && fail "the second call trained again"
grep -q "0 runs made, $configurations already in study.csv" "$work/second.log" ||
  fail "the second call did not resume the study: $(grep 'runs made' "$work/second.log")"
echo "experiment_test: ok"
