#!/usr/bin/env bash
# Writes (and with --submit, submits) a Slurm job array that runs an occlusion
# study in N shards, one array task per shard, and a merge job that waits for
# the whole array (afterany: a shard with failed runs still has rows to merge)
# and joins the shards with `occlusion study merge`. docs/study.md explains it.
#
# usage: study_slurm.sh --shards N --out DIR [--occlusion BIN] [--sbatch OPTION]...
#                       [--submit] -- STUDY_OPTIONS...
#   --shards N        array tasks 0 .. N-1; task I runs --shard I/N
#   --out DIR         DIR/shard_I/ for each shard, DIR/study.* for the merge,
#                     DIR/slurm/ for the two scripts and their logs
#   --occlusion BIN   the occlusion executable (default: `occlusion` on PATH)
#   --sbatch OPTION   an #SBATCH line for the array task, e.g. --sbatch --time=04:00:00
#                     or --sbatch --cpus-per-task=8 (repeatable)
#   --submit          submit both scripts; prints "array JOBID" and "merge JOBID"
#   STUDY_OPTIONS     passed to every `occlusion study` (e.g. --config study.json);
#                     not --shard or --out, which the script sets
# Relative paths in STUDY_OPTIONS are resolved in the folder this is run from:
# the jobs start there (--chdir). Exit 2 for bad usage.
set -euo pipefail

usage() {
  sed -n '8,19p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//' >&2
  exit 2
}

shards="" out="" occlusion="occlusion" submit=false
sbatch_options=()
while (($# > 0)); do
  case "$1" in
    --shards) shards="${2:-}"; shift 2 || usage ;;
    --out) out="${2:-}"; shift 2 || usage ;;
    --occlusion) occlusion="${2:-}"; shift 2 || usage ;;
    --sbatch) sbatch_options+=("${2:-}"); shift 2 || usage ;;
    --submit) submit=true; shift ;;
    --) shift; break ;;
    -h | --help) usage ;;
    *) echo "study_slurm: unknown option '$1' (study options go after --)" >&2; usage ;;
  esac
done
study_options=("$@")
if ! [[ "$shards" =~ ^[1-9][0-9]{0,4}$ ]]; then
  echo "study_slurm: --shards must be a whole number from 1 to 99999, got '$shards'" >&2
  exit 2
fi
[[ -n "$out" ]] || { echo "study_slurm: --out DIR is required" >&2; exit 2; }
for option in "${study_options[@]}"; do
  case "$option" in
    --shard | --shard=* | --out | --out=*)
      echo "study_slurm: give no $option after --: each task's shard and folder are set here" >&2
      exit 2 ;;
  esac
done
if [[ "$occlusion" == */* ]]; then
  occlusion="$(cd "$(dirname "$occlusion")" && pwd)/$(basename "$occlusion")"
fi

workdir="$(pwd)"
mkdir -p "$out/slurm"
out="$(cd "$out" && pwd)"
array_script="$out/slurm/study_array.sbatch"
merge_script="$out/slurm/study_merge.sbatch"
last=$((shards - 1))

# Both scripts are written whole to a temporary file, then renamed into place.
{
  echo "#!/bin/bash"
  echo "#SBATCH --job-name=occlusion-study"
  echo "#SBATCH --array=0-$last"
  echo "#SBATCH --chdir=$workdir"
  echo "#SBATCH --output=$out/slurm/shard_%a.log"
  for option in "${sbatch_options[@]}"; do echo "#SBATCH $option"; done
  echo "# Task I makes the runs k with k mod $shards = I; a resubmitted task"
  echo "# (sbatch --array=I $array_script) resumes from its own study.csv."
  echo "set -euo pipefail"
  printf 'exec %q study' "$occlusion"
  if ((${#study_options[@]} > 0)); then printf ' %q' "${study_options[@]}"; fi
  printf ' --shard "$SLURM_ARRAY_TASK_ID/%s" --out %q/shard_"$SLURM_ARRAY_TASK_ID" -q\n' \
    "$shards" "$out"
} >"$array_script.tmp"
mv "$array_script.tmp" "$array_script"

{
  echo "#!/bin/bash"
  echo "#SBATCH --job-name=occlusion-study-merge"
  echo "#SBATCH --chdir=$workdir"
  echo "#SBATCH --output=$out/slurm/merge.log"
  echo "set -euo pipefail"
  printf 'exec %q study merge %q' "$occlusion" "$out"
  for ((i = 0; i < shards; i++)); do printf ' %q' "$out/shard_$i/study.csv"; done
  printf '\n'
} >"$merge_script.tmp"
mv "$merge_script.tmp" "$merge_script"

echo "wrote $array_script"
echo "wrote $merge_script"
if $submit; then
  array_job="$(sbatch --parsable "$array_script")"
  array_job="${array_job%%;*}"
  merge_job="$(sbatch --parsable --dependency="afterany:$array_job" "$merge_script")"
  merge_job="${merge_job%%;*}"
  echo "array $array_job"
  echo "merge $merge_job"
fi
