#!/usr/bin/env bash
# Usage: repository_only.sh COMMAND [ARG...]
# Runs COMMAND with everything beside the repository hidden: in a private
# mount namespace the repository's parent folder is an empty tmpfs holding
# only the repository (and the build folder, where OCCLUSION_BUILD_DIR puts it
# beside the repository). A user's clone has nothing beside it, so a test that
# reads a sibling folder fails here as it would for them, instead of
# passing on a developer's machine (test.sh runs the suites through this).
#
# Hiding needs root and unshare(1); without them the command runs in place and
# this says so (CI runs as root, so there the check is real).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
parent="$(dirname "$root")"
build="${OCCLUSION_BUILD_DIR:-$root/build}"

if [[ "$parent" == "/" || $(id -u) -ne 0 ]] || ! command -v unshare >/dev/null; then
  echo "repository_only: cannot hide the folders beside $root (needs root, unshare and a" \
    "parent folder other than /); running in place" >&2
  exec "$@"
fi

# Folders to put back after the parent is hidden: the repository, and a build
# folder that lies beside it (one inside it comes along with it).
keep=("$root")
build_real="$(cd "$build" 2>/dev/null && pwd || true)"
if [[ -n "$build_real" && "$build_real" == "$parent"/* && "$build_real" != "$root"/* ]]; then
  keep+=("$build_real")
fi

# Where the kept folders wait while the parent is covered: a folder outside it.
held_in=""
for candidate in "${TMPDIR:-/tmp}" /tmp /dev/shm /run /var/tmp; do
  candidate="$(cd "$candidate" 2>/dev/null && pwd -P || true)"
  if [[ -n "$candidate" && -w "$candidate" && "$candidate" != "$parent" &&
    "$candidate" != "$parent"/* ]]; then
    held_in="$candidate"
    break
  fi
done
if [[ -z "$held_in" ]]; then
  echo "repository_only: no writable folder outside $parent; running in place" >&2
  exec "$@"
fi

# The parent becomes a tmpfs of the usual size (half the memory), so a parent
# that is also the temporary folder (/tmp) still takes the tests' files.
exec unshare --mount --propagation private bash -c '
  set -euo pipefail
  parent="$1"; held_in="$2"; count="$3"; shift 3
  keep=("${@:1:$count}"); shift "$count"
  held="$(mktemp -d "$held_in/repository_only.XXXXXX")"
  for i in "${!keep[@]}"; do
    mkdir "$held/$i"
    mount --bind "${keep[$i]}" "$held/$i"
  done
  mount -t tmpfs -o mode=1777 tmpfs "$parent"
  for i in "${!keep[@]}"; do
    mkdir -p "${keep[$i]}"
    mount --move "$held/$i" "${keep[$i]}"
  done
  rmdir "$held"/* "$held"
  exec "$@"
' repository_only "$parent" "$held_in" "${#keep[@]}" "${keep[@]}" "$@"
