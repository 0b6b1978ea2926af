#!/usr/bin/env bash
# Sets up, builds once and runs every test: C++ formatting, all GoogleTest
# cases in parallel through ctest, then again under ASan + UBSan
# (src/scripts/sanitize.sh), a brief fuzzing of every reader
# (src/scripts/fuzz.sh), the Python module's pytest suite, then the browser viewer's checks
# (src/scripts/web.sh installs and builds it): prettier, tsc, the Vitest unit
# tests, and the end-to-end tests in headless Chromium (Debian's chromium,
# installed here if missing) against a real `occlusion serve`.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
bash "$root/src/scripts/setup.sh"
bash "$root/src/scripts/check_format.sh"
bash "$root/src/scripts/build.sh"
build="${OCCLUSION_BUILD_DIR:-$root/build}"
ctest --test-dir "$build" -j "$(nproc)" --output-on-failure
# The whole C++ suite again with ASan + UBSan, in its own build-asan/
# (src/scripts/sanitize.sh, docs/fuzzing.md: about 10 min on 2 cores with a
# warm ccache); the limit keeps a stuck build or test from holding CI.
timeout --kill-after=20 "${SANITIZE_SECONDS:-1500}" bash "$root/src/scripts/sanitize.sh"
# Every reader under libFuzzer with ASan + UBSan, 15 s each (docs/fuzzing.md);
# the outer limit keeps a stuck build or target from holding CI.
FUZZ_SECONDS="${FUZZ_SECONDS:-15}" timeout --kill-after=20 1500 bash "$root/src/scripts/fuzz.sh"

# Debian's interpreter, the one the module is built for (not a pyenv shim).
if [[ ! -f "$build/python/occlusion/__init__.py" ]]; then
  echo "test: the Python module was not built (is pybind11-dev installed?)" >&2
  exit 1
fi
pytest_status=0
PYTHONPATH="$build/python" /usr/bin/python3 -m pytest -q -p no:cacheprovider "$root/tests/python" ||
  pytest_status=$?
if ((pytest_status == 5)); then
  echo "test: pytest collected no tests in tests/python" >&2
fi
((pytest_status == 0)) || exit "$pytest_status"

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
npm run --silent format:check
npm run --silent typecheck
npm test --silent
# Every wait inside is bounded; this is the outer limit (the tests stop their server).
OCCLUSION_BIN="$build/occlusion" CHROMIUM_PATH="$chromium" \
  timeout --kill-after=20 600 npm run --silent e2e
