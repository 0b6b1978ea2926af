#!/usr/bin/env bash
# The GNU parallel recipe of docs/study.md, for real: three shards of a study
# run by Debian's `parallel`, merged with `occlusion study merge`, must give
# the unsharded study's table and statistics exactly. Skips (exit 77) where
# `parallel` is missing (src/scripts/setup.sh installs it).
# usage: study_parallel_test.sh OCCLUSION_BINARY
set -euo pipefail
occlusion="$(realpath "$1")"
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
source "$source_dir/tests/scripts/study_shards_common.sh"

command -v parallel >/dev/null || skip "GNU parallel is not installed (apt-get install parallel)"
work="$(mktemp -d "${TMPDIR:-/tmp}/occlusion-parallel.XXXXXX")"
trap 'rm -rf "$work"' EXIT
cd "$work"

run_whole_study "$work/whole"
# The recipe, as documented; every wait bounded.
timeout --kill-after=10 300 parallel --will-cite -j 2 --halt now,fail=1 \
  "$occlusion" study "${study_options[@]}" --threads 1 \
  --shard {}/3 --out "$work/shard_{}" -q ::: 0 1 2 >/dev/null ||
  fail "a shard failed under GNU parallel"
"$occlusion" study merge "$work/merged" "$work"/shard_{0,1,2}/study.csv -q >/dev/null ||
  fail "study merge failed"
compare_studies "$work/whole" "$work/merged"
