#!/usr/bin/env bash
# The study's whole experiment in one command (issues 27 and 43): generate
# varied rooms with their meshes, train the reference segmenter twice, on the
# complete training rooms and on those rooms plus virtual laser scans of them
# (same network, steps, seed and rooms), measure both on the held-out rooms
# (every point), then run the study (config/experiment.json) over the
# held-out rooms four times: model (complete | scans) x scans (ideal |
# laser). The studies compare themselves pairwise (compare_with), and
# OUT/experiment.md sets the four within-scene slopes and the four paired
# differences side by side (src/scripts/experiment_summary.py, from the
# studies' study.json). Seeded throughout: the same command gives the same
# rooms, checkpoints and study.csv files.
#
#   bash src/scripts/experiment.sh [OUT]        (default out/experiment)
#
# Environment: TRAIN_ROOMS (24), TEST_ROOMS (6: four studies within the hour;
# an interval needs 5 scenes), SPACING (0.04), STEPS (1500, so that both
# models train within the hour; docs/study.md's answer is TEST_ROOMS=16
# STEPS=3000, about an hour and a half on a busy 2-core machine), SCANS
# (3 laser scans per training room), THREADS (2), CONFIG (the studies'
# config, whose laser_* keys the training scans use too; default
# config/experiment.json), OCCLUSION_BUILD (the folder with occlusion and
# generate_s3dis_room; default build). Stages whose output exists are skipped, so a stopped
# experiment resumes (each study run by run); delete OUT to start again.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
out="$(realpath -m "${1:-$repo/out/experiment}")"
train_rooms="${TRAIN_ROOMS:-24}"
test_rooms="${TEST_ROOMS:-6}"
spacing="${SPACING:-0.04}"
steps="${STEPS:-1500}"
scans="${SCANS:-3}"
threads="${THREADS:-2}"
build="${OCCLUSION_BUILD:-$repo/build}"
occlusion="$build/occlusion"
generate="$build/generate_s3dis_room"
config="$(realpath "${CONFIG:-$repo/config/experiment.json}")"
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
# One OpenMP thread per core and no spinning: spinning threads on a busy
# machine made each training step tens of times slower.
export OMP_WAIT_POLICY=PASSIVE
mkdir -p "$out"
start=$(date +%s)
stage() {
  echo "experiment: $1 ($(($(date +%s) - start)) s so far)" >&2
}

# Training and test rooms come from different seeds: no test room is a
# training room. --mesh: each room's surfaces, which the laser scans.
rooms() { # NAME COUNT SEED
  if [[ ! -d "$out/$1" ]]; then
    stage "generating $2 rooms ($1)"
    rm -rf "$out/$1.partial"
    "$generate" --dataset "$out/$1.partial" --rooms "$2" --seed "$3" --spacing "$spacing" --mesh
    mv "$out/$1.partial" "$out/$1"
  fi
}
rooms rooms_train "$train_rooms" 1
rooms rooms_test "$test_rooms" 2

# Both models: the same rooms, network, steps and seed; the second also
# trains on SCANS laser scans per room, from stations a crew would choose,
# made by the sensor the laser studies use (config/experiment.json's laser_*).
train() { # CHECKPOINT [EXTRA ARGUMENTS]
  local checkpoint="$1"
  shift
  if [[ ! -f "$out/$checkpoint" ]]; then
    stage "training $checkpoint ($steps steps, $threads threads)"
    /usr/bin/python3 -m occlusion_segmenter train "$out/rooms_train" "$out/$checkpoint.partial" \
      --seed 0 --steps "$steps" --threads "$threads" "$@"
    mv "$out/$checkpoint.partial" "$out/$checkpoint"
  fi
  if [[ ! -f "$out/$checkpoint.evaluate.txt" ]]; then
    stage "scoring $checkpoint on the held-out rooms"
    /usr/bin/python3 -m occlusion_segmenter evaluate "$out/$checkpoint" "$out/rooms_test" \
      --threads "$threads" >"$out/$checkpoint.evaluate.txt.partial"
    mv "$out/$checkpoint.evaluate.txt.partial" "$out/$checkpoint.evaluate.txt"
  fi
  tail -n 1 "$out/$checkpoint.evaluate.txt"
}
train segmenter.pt
train segmenter_scans.pt --scans "$scans" --scan-config "$config" --occlusion "$occlusion" \
  --scan-cache "$out/rooms_train.scans"

scenes=()
for room in "$out"/rooms_test/Area_*/*/; do
  scenes+=(--scene "${room%/}")
done
study() { # NAME CHECKPOINT SCAN_MODEL [--compare-with DIR ...]
  local name="$1" checkpoint="$2" scan_model="$3"
  shift 3
  stage "the study $name"
  "$occlusion" study --config "$config" "${scenes[@]}" --out "$out/$name" \
    --threads "$threads" --scan-model "$scan_model" "$@" \
    --segmenter "worker: /usr/bin/python3 -m occlusion_segmenter serve --threads $threads $out/$checkpoint"
}
study complete_ideal segmenter.pt ideal
study scans_ideal segmenter_scans.pt ideal --compare-with "$out/complete_ideal"
study complete_laser segmenter.pt laser --compare-with "$out/complete_ideal"
study scans_laser segmenter_scans.pt laser --compare-with "$out/scans_ideal" \
  --compare-with "$out/complete_laser"

/usr/bin/python3 "$repo/src/scripts/experiment_summary.py" "$out" >"$out/experiment.md.partial"
mv "$out/experiment.md.partial" "$out/experiment.md"
stage "done: $out/experiment.md"
