#!/usr/bin/env bash
# Sets up, builds once and runs every test: C++ formatting, all GoogleTest
# cases in parallel through ctest, then again under ASan + UBSan
# (src/scripts/sanitize.sh) and a brief fuzzing of every reader
# (src/scripts/fuzz.sh), both from one clang build, the Python module's
# pytest suite, then the browser viewer's checks (src/scripts/web.sh installs
# and builds it): prettier, tsc, the Vitest unit tests, and the end-to-end
# tests in headless Chromium (Debian's chromium, installed here if missing)
# against a real `occlusion serve`.
#
# Each stage's wall time is printed in a table at the end, whether the run
# passed or failed, so a slow stage shows in CI's log (docs/ci.md has the
# figures). No stage has a time budget: a slow machine only takes longer.
# The few stages that could hang (tests, fuzzing, the browser) run under a
# hang guard several times their cold duration, which says so when it fires.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="${OCCLUSION_BUILD_DIR:-$root/build}"

stage_names=()
stage_seconds=()
stage_cpu=()
stage_now=""
stage_start=0
run_start=$SECONDS
# CPU seconds (user + system) of all finished child processes so far, from
# bash's `times`: with other work on the same cores the wall clock says little
# about a stage's cost, its CPU time does.
times_file="$(mktemp)"
children_cpu_now=0
# Sets children_cpu_now; `times` must run in this shell (in $(...) it would
# see only that subshell's children), so it goes through a file.
children_cpu() {
  times >"$times_file"
  # Its last line, "0m12.345s 0m1.234s" -> 13
  children_cpu_now="$(tail -n 1 "$times_file" | awk '{ split($1, u, /[ms]/); split($2, s, /[ms]/)
    printf "%d\n", u[1] * 60 + u[2] + s[1] * 60 + s[2] }')"
}
stage_cpu_start=0
# Ends the running stage: its name, duration and CPU time join the table.
stage_end() {
  if [[ -n "$stage_now" ]]; then
    children_cpu
    stage_names+=("$stage_now")
    stage_seconds+=($((SECONDS - stage_start)))
    stage_cpu+=($((children_cpu_now - stage_cpu_start)))
    stage_now=""
  fi
}
stage() {
  stage_end
  stage_now="$1"
  stage_start=$SECONDS
  children_cpu
  stage_cpu_start=$children_cpu_now
  echo "test: == $1"
}
# On any exit: the table, with the stage that failed marked as such.
report() {
  local status=$? failed="$stage_now" i
  stage_end
  echo
  echo "test: stage durations (wall clock; CPU = user + system of its processes)"
  for i in "${!stage_names[@]}"; do
    local mark=""
    [[ "${stage_names[$i]}" == "$failed" ]] && mark="  <- FAILED (exit $status)"
    printf 'test:   %-38s %5d s wall  %5d s CPU  %s%s\n' "${stage_names[$i]}" \
      "${stage_seconds[$i]}" "${stage_cpu[$i]}" \
      "$(printf '%d:%02d' $((stage_seconds[i] / 60)) $((stage_seconds[i] % 60)))" "$mark"
  done
  local total=$((SECONDS - run_start))
  children_cpu
  rm -f "$times_file"
  printf 'test:   %-38s %5d s wall  %5d s CPU  %d:%02d\n' "total" "$total" "$children_cpu_now" \
    $((total / 60)) $((total % 60))
  if ((status == 0)); then echo "test: all stages passed"; else echo "test: FAILED (exit $status)"; fi
}
trap report EXIT

# guard SECONDS COMMAND...: runs COMMAND, stopping it only if it hangs. The
# limit is far above the stage's normal time (several times its cold figure on
# a loaded 2-core machine), so a slow machine never trips it; when it does
# fire it says so, rather than failing like a test. GUARD_SCALE multiplies
# every limit (GUARD_SCALE=0 turns them off).
guard() {
  local seconds=$(($1 * ${GUARD_SCALE:-1})) status=0
  shift
  if ((seconds == 0)); then "$@"; return; fi
  timeout --kill-after=30 "$seconds" "$@" || status=$?
  if ((status == 124 || status == 137)); then
    echo "test: HANG GUARD: stage '$stage_now' still running after ${seconds} s" \
      "(far above its normal time, see docs/ci.md); stopped as hung" >&2
  fi
  return "$status"
}

stage "setup (apt-get)"
bash "$root/src/scripts/setup.sh"
stage "C++ format"
bash "$root/src/scripts/check_format.sh"
stage "release build"
bash "$root/src/scripts/build.sh"
# The suites run with the folders beside the repository hidden
# (src/scripts/repository_only.sh): a user's clone has nothing beside it, so a
# test that reads outside the repository fails here too.
only="$root/src/scripts/repository_only.sh"
stage "release ctest"
guard 3600 "$only" ctest --test-dir "$build" -j "$(nproc)" --output-on-failure
# One clang-14 build with ASan + UBSan and libFuzzer's coverage serves the
# next two stages (src/scripts/build_sanitized.sh, docs/fuzzing.md). A
# compiler does not hang: the CI job's own limit is this stage's only one.
stage "clang ASan+UBSan build (tests, fuzz)"
bash "$root/src/scripts/build_sanitized.sh"
# The whole C++ suite again on that build. Each test has its own ctest
# TIMEOUT; the guard is the outer one.
stage "ASan+UBSan ctest"
guard 3600 "$only" bash "$root/src/scripts/sanitize.sh"
# Every reader under libFuzzer, 15 s each, a core each (docs/fuzzing.md); libFuzzer stops
# each by itself, and a slow input is a finding (-timeout=10).
stage "fuzz (every target)"
FUZZ_SECONDS="${FUZZ_SECONDS:-15}" guard 3600 bash "$root/src/scripts/fuzz.sh"

stage "pytest"
# Debian's interpreter, the one the module is built for (not a pyenv shim).
if [[ ! -f "$build/python/occlusion/__init__.py" ]]; then
  echo "test: the Python module was not built (is pybind11-dev installed?)" >&2
  exit 1
fi
pytest_status=0
PYTHONPATH="$build/python" guard 1800 "$only" /usr/bin/python3 -m pytest -q -p no:cacheprovider \
  "$root/tests/python" || pytest_status=$?
if ((pytest_status == 5)); then
  echo "test: pytest collected no tests in tests/python" >&2
fi
((pytest_status == 0)) || exit "$pytest_status"

stage "viewer install and build"
bash "$root/src/scripts/web.sh"
chromium="${CHROMIUM_PATH:-/usr/bin/chromium}"
if [[ ! -x "$chromium" ]]; then
  sudo=()
  if [[ $(id -u) -ne 0 ]]; then
    command -v sudo >/dev/null || { echo "test: run as root to install chromium" >&2; exit 1; }
    sudo=(sudo)
  fi
  echo "test: installing chromium (for the viewer's end-to-end tests)"
  export DEBIAN_FRONTEND=noninteractive
  "${sudo[@]}" apt-get update -qq
  "${sudo[@]}" apt-get install -y -qq chromium >/dev/null
fi
cd "$root/web"
stage "viewer format, types, unit tests"
npm run --silent format:check
npm run --silent typecheck
guard 1800 npm test --silent
# Every wait inside is bounded (the tests stop their server); the guard is the outer one.
stage "viewer end-to-end (chromium)"
OCCLUSION_BIN="$build/occlusion" CHROMIUM_PATH="$chromium" \
  guard 2400 "$only" npm run --silent e2e
stage_end
