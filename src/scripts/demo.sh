#!/usr/bin/env bash
# Sets up and builds everything (the C++ tool and the browser viewer), runs the
# main job on the bundled sample room (mesh occlusion from the three viewpoints
# of pattern 7, outputs in out/demo), then serves the viewer on the sample data
# until Ctrl-C: open the printed URL in a browser.
#   OCCLUSION_HOST (default 127.0.0.1), OCCLUSION_PORT (default 8080)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
bash "$root/src/scripts/setup.sh"
bash "$root/src/scripts/build.sh"
bash "$root/src/scripts/web.sh"
build="${OCCLUSION_BUILD_DIR:-$root/build}"
"$build/occlusion" -moc "$root/files/sample_room.obj" --pattern 7 --out "$root/out/demo"

# The server writes job outputs, uploads and saved openings into its data
# directory: serve a working copy of files/ (in out/, ignored by git), updated
# from files/ on every run, so the repository's samples stay untouched.
data="$root/out/viewer-data"
mkdir -p "$data"
cp -R -u "$root/files/." "$data/"
host="${OCCLUSION_HOST:-127.0.0.1}"
port="${OCCLUSION_PORT:-8080}"
echo
echo "demo: viewer at http://$host:$port/ (data: out/viewer-data, a copy of files/); Ctrl-C stops it"
exec "$build/occlusion" serve --host "$host" --port "$port" --data "$data" --web "$root/web/dist"
