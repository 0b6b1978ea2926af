#!/usr/bin/env bash
# src/scripts/experiment.sh end to end at a tiny size (one room to train on,
# one held out, two training steps, one training scan): every stage runs and
# writes what the next reads, each of the four studies gets one ok row per
# configuration of config/experiment.json, experiment.md has the four slopes
# and the four differences, and a second call resumes: it redoes nothing. Skips (exit 77) where
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

# The experiment's config with a coarse laser (4 degree steps), so that the
# laser studies of these tiny rooms take seconds.
/usr/bin/python3 - "$source_dir/config/experiment.json" "$work/experiment.json" <<'EOF'
import json, sys
config = json.load(open(sys.argv[1]))
config["occlusion"]["study"].update(laser_azimuth_step=4, laser_elevation_step=4)
json.dump(config, open(sys.argv[2], "w"))
EOF
run() {
  CONFIG="$work/experiment.json" OCCLUSION_BUILD="$build" TRAIN_ROOMS=1 TEST_ROOMS=1 SPACING=0.08 STEPS=2 SCANS=1 THREADS=1 \
    timeout --kill-after=10 500 bash "$source_dir/src/scripts/experiment.sh" "$work/out" \
    >"$work/$1.log" 2>&1 || {
    cat "$work/$1.log" >&2
    fail "the experiment failed ($1 call)"
  }
}
run first
studies="complete_ideal scans_ideal complete_laser scans_laser"
for made in rooms_train/Area_1 rooms_test/Area_1 segmenter.pt segmenter_scans.pt \
  segmenter.pt.evaluate.txt segmenter_scans.pt.evaluate.txt experiment.md; do
  [[ -e "$work/out/$made" ]] || fail "no $made"
done
for checkpoint in segmenter.pt segmenter_scans.pt; do
  grep -q '^mIoU [0-9.]* over' "$work/out/$checkpoint.evaluate.txt" ||
    fail "$checkpoint.evaluate.txt has no mIoU line"
done
configurations=$(grep -o '"pattern"' "$work/experiment.json" | wc -l)
for study in $studies; do
  ok_rows=$(tail -n +2 "$work/out/$study/study.csv" | grep -c ',ok,' || true)
  [[ "$ok_rows" -eq "$configurations" ]] ||
    fail "$study/study.csv has $ok_rows ok runs, want one per configuration ($configurations)"
done
# The laser's scans are not the ideal ones: other point counts.
[[ "$(cut -d, -f8 "$work/out/complete_laser/study.csv")" != \
  "$(cut -d, -f8 "$work/out/complete_ideal/study.csv")" ]] || fail "the laser scans are the ideal ones"
# Four cells and four differences.
[[ $(grep -c '^| rooms + scans \|^| complete rooms ' "$work/out/experiment.md") -eq 4 ]] ||
  fail "experiment.md has not the four cells: $(cat "$work/out/experiment.md")"
[[ $(grep -c '^| model: \|^| scans: ' "$work/out/experiment.md") -eq 4 ]] ||
  fail "experiment.md has not the four differences"

cp "$work/out/segmenter.pt" "$work/first.pt"
run second
cmp -s "$work/out/segmenter.pt" "$work/first.pt" || fail "the second call trained again"
grep -q 'training the segmenter' "$work/second.log" && fail "the second call trained again"
[[ $(grep -c "0 runs made, $configurations already in study.csv" "$work/second.log") -eq 4 ]] ||
  fail "the second call did not resume the studies: $(grep 'runs made' "$work/second.log")"
echo "experiment_test: ok"
