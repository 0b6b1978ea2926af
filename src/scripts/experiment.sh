#!/usr/bin/env bash
# Issue 27's whole experiment in one command: generate varied rooms, train the
# reference segmenter on some, measure its mIoU on others (every point), then
# run the study (config/experiment.json) over the held-out rooms with the
# trained model as a persistent worker. Seeded throughout: the same command
# gives the same rooms, checkpoint and study.csv.
#
#   bash src/scripts/experiment.sh [OUT]        (default out/experiment)
#
# Environment: TRAIN_ROOMS (24), TEST_ROOMS (16), SPACING (0.04), STEPS (3000),
# THREADS (2), OCCLUSION_BUILD (the folder with occlusion and
# generate_s3dis_room; default build). Stages whose output exists are skipped, so a stopped experiment
# resumes (the study resumes run by run); delete OUT to start again.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
out="$(realpath -m "${1:-$repo/out/experiment}")"
train_rooms="${TRAIN_ROOMS:-24}"
test_rooms="${TEST_ROOMS:-16}"
spacing="${SPACING:-0.04}"
steps="${STEPS:-3000}"
threads="${THREADS:-2}"
build="${OCCLUSION_BUILD:-$repo/build}"
occlusion="$build/occlusion"
generate="$build/generate_s3dis_room"
for tool in "$occlusion" "$generate"; do
  if [[ ! -x "$tool" ]]; then
    echo "experiment: $tool is missing: build first (bash src/scripts/build.sh)" >&2
    exit 2
  fi
done
if ! /usr/bin/python3 -c 'import torch' 2>/dev/null; then
  echo "experiment: python3-torch is missing: run bash src/scripts/setup.sh" >&2
  exit 2
fi
export PYTHONPATH="$repo/python${PYTHONPATH:+:$PYTHONPATH}"
mkdir -p "$out"
start=$(date +%s)
stage() {
  echo "experiment: $1 ($(($(date +%s) - start)) s so far)" >&2
}

# Training and test rooms come from different seeds: no test room is a
# training room.
if [[ ! -d "$out/rooms_train" ]]; then
  stage "generating $train_rooms training rooms"
  "$generate" --dataset "$out/rooms_train.partial" --rooms "$train_rooms" --seed 1 \
    --spacing "$spacing"
  mv "$out/rooms_train.partial" "$out/rooms_train"
fi
if [[ ! -d "$out/rooms_test" ]]; then
  stage "generating $test_rooms held-out rooms"
  "$generate" --dataset "$out/rooms_test.partial" --rooms "$test_rooms" --seed 2 \
    --spacing "$spacing"
  mv "$out/rooms_test.partial" "$out/rooms_test"
fi

if [[ ! -f "$out/segmenter.pt" ]]; then
  stage "training the segmenter ($steps steps, $threads threads)"
  # One OpenMP thread per core and no spinning: spinning threads on a busy
  # machine made each step tens of times slower.
  OMP_WAIT_POLICY=PASSIVE /usr/bin/python3 -m occlusion_segmenter train \
    "$out/rooms_train" "$out/segmenter.pt.partial" --seed 0 --steps "$steps" --threads "$threads"
  mv "$out/segmenter.pt.partial" "$out/segmenter.pt"
fi

if [[ ! -f "$out/evaluate.txt" ]]; then
  stage "scoring the segmenter on the held-out rooms"
  /usr/bin/python3 -m occlusion_segmenter evaluate "$out/segmenter.pt" "$out/rooms_test" \
    > "$out/evaluate.txt.partial"
  mv "$out/evaluate.txt.partial" "$out/evaluate.txt"
fi
cat "$out/evaluate.txt"

stage "the study"
scenes=()
for room in "$out"/rooms_test/Area_*/*/; do
  scenes+=(--scene "${room%/}")
done
"$occlusion" study --config "$repo/config/experiment.json" "${scenes[@]}" --out "$out/study" \
  --threads "$threads" \
  --segmenter "worker: /usr/bin/python3 -m occlusion_segmenter serve --threads $threads $out/segmenter.pt"
stage "done: $out/study/study.md"
