#!/usr/bin/env bash
# Registration time (occlusion register): PCL's tutorial pair with each
# method, and a larger simulated pair (the sample room scanned at 0.2 degree
# steps from two stations, ~10x the tutorial's points; both in the room's
# frame, so the true pose is the identity and the start is 0.05 rad and
# 0.2 m off it). Prints one line per run: method, points, seconds, the fit,
# and for the simulated pair how far the refined pose is from the truth.
# Usage: bench/register.sh [BUILD_DIR] (default build); needs /usr/bin/python3.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-$here/build}/occlusion
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

matrix() { # yaw(rad) tx ty tz
  /usr/bin/python3 -c "
import math, sys
a, tx, ty, tz = map(float, sys.argv[1:])
c, s = math.cos(a), math.sin(a)
print(f'{c!r} {-s!r} 0 {tx!r}\n{s!r} {c!r} 0 {ty!r}\n0 0 1 {tz!r}\n0 0 0 1')" "$@"
}

summary() { # report.json
  /usr/bin/python3 -c "
import json, math, sys
r = json.load(open(sys.argv[1]))
m = r['refined_pose']['matrix']
print(f\"{r['parameters']['method']:9s} {r['source_points']:>8d} + {r['target_points']:<8d} \"
      f\"register {r['timings']['register_seconds']:6.2f} s  rms {r['rms']:.4f}  overlap {r['overlap']:.3f}  \"
      f\"iterations {[l['iterations'] for l in r['levels']]}  \"
      f\"translation {m[0][3]:.4f} {m[1][3]:.4f} {m[2][3]:.4f}  rotation {r['refined_pose']['rotation_deg']:.4f} deg\")" "$1"
}

matrix 0.6931 1.79387 0.720047 0 > "$work/guess.txt"
echo "tutorial pair (room_scan2 onto room_scan1, the tutorial's guess)"
for method in gicp icp_plane ndt; do
  "$bin" register "$here/files/pcl/room_scan2.pcd" --target "$here/files/pcl/room_scan1.pcd" \
    --initial-pose "$work/guess.txt" --method "$method" --json -q > "$work/r.json"
  summary "$work/r.json"
done

echo "simulated pair (sample room, 0.2 degree steps; truth: identity)"
for station in 2,2,1.4 5.5,4,1.6; do
  "$bin" simulate "$here/files/sample_room.obj" --station "$station" --out "$work/$station" -q > /dev/null
done
matrix 0.05 0.2 -0.2 0 > "$work/start.txt"
for method in gicp icp_plane ndt; do
  "$bin" register "$work/5.5,4,1.6/sample_room.sim.ply" --target "$work/2,2,1.4/sample_room.sim.ply" \
    --initial-pose "$work/start.txt" --method "$method" --json -q > "$work/r.json"
  summary "$work/r.json"
done
