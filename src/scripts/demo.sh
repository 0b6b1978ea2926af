#!/usr/bin/env bash
# Sets up, builds and runs the main job on the bundled sample room:
# mesh occlusion from the three viewpoints of pattern 7, outputs in out/demo.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
bash "$root/src/scripts/setup.sh"
bash "$root/src/scripts/build.sh"
build="${OCCLUSION_BUILD_DIR:-$root/build}"
"$build/occlusion" -moc "$root/files/sample_room.obj" --pattern 7 --out "$root/out/demo"
