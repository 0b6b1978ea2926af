# Shared by the sharded-study tests (study_slurm_test.sh, study_parallel_test.sh);
# sourced, not run. The study they shard: the labelled synthetic office (three
# configurations, so three runs), traced with few rays to stay quick.

study_options=(
  --config "$source_dir/config/study.json"
  --num-rays-per-vp 3000
)

skip() {
  echo "SKIPPED: $*" >&2
  exit 77  # ctest's SKIP_RETURN_CODE for these tests
}

fail() {
  echo "FAILED: $*" >&2
  exit 1
}

# The unsharded study into $1.
run_whole_study() {
  "$occlusion" study "${study_options[@]}" --out "$1" -q >/dev/null ||
    fail "the unsharded study failed"
}

# study.csv without its timing columns (the last four, plain numbers): what
# must be byte-for-byte the same however the runs were spread.
figures() {
  sed -E 's/(,[^,]*){4}$//' "$1"
}

# The "correlations" array of a study.json.
correlations() {
  perl -0ne 'print $1 if /("correlations"\s*:\s*\[.*?\n  \])/s' "$1"
}

# Compares the merged study in $2 with the unsharded one in $1.
compare_studies() {
  local whole="$1" merged="$2"
  [[ -s "$merged/study.csv" ]] || fail "no merged $merged/study.csv"
  local rows
  rows=$(($(wc -l <"$whole/study.csv") - 1))
  ((rows == 3)) || fail "the unsharded study has $rows rows, not 3"
  if ! diff <(figures "$whole/study.csv") <(figures "$merged/study.csv") >&2; then
    fail "the merged table differs from the unsharded one"
  fi
  local a b
  a="$(correlations "$whole/study.json")"
  b="$(correlations "$merged/study.json")"
  [[ -n "$a" ]] || fail "no correlations in $whole/study.json"
  [[ "$a" == "$b" ]] || fail "the correlations differ: $a vs $b"
  cmp "$whole/study.svg" "$merged/study.svg" || fail "the plots differ"
  echo "the merged study equals the unsharded one ($rows runs)"
}
