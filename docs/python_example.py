"""The occlusion module from Python: run from the repository root after a build,

    PYTHONPATH=build/python /usr/bin/python3 docs/python_example.py [AREA_FOLDER]

(default: the synthetic S3DIS area in files/). Writes out/python_example/.
"""

import pathlib
import sys

import numpy as np

import occlusion

area = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "files/s3dis_synthetic/Area_1")
out = pathlib.Path("out/python_example")
out.mkdir(parents=True, exist_ok=True)

# 1. The occlusion level of every room of an S3DIS area.
rooms = sorted(p for p in area.iterdir() if (p / "Annotations").is_dir())
for room in rooms:
    r = occlusion.cloud_occlusion(room, point_radius=0.06, num_rays_per_vp=5000, seed=0)
    print(f"{room.name:24s} occlusion_level {r.occlusion_level:.3f} ({r.points} points)")

# 2. A scan mask used to occlude a training cloud: keep only the points a
#    scanner at the room's centre would see, labels and colours with them.
cloud = occlusion.read_cloud(rooms[0])
seen = occlusion.scan(cloud, pattern=1, point_radius=0.02).mask
occlusion.write_cloud(
    str(out / f"{rooms[0].name}.occluded.ply"),
    cloud.positions[seen],
    colours=None if cloud.colours is None else cloud.colours[seen],
    labels=cloud.labels[seen],
    class_names=cloud.class_names,
)
print(f"scan from the centre keeps {seen.sum()} of {len(cloud)} points")

# 3. Tracing your own rays: which points see the ceiling's centre directly?
scene = occlusion.SphereScene(cloud.positions, 0.02)
target = cloud.positions.mean(axis=0) + np.array([0, 0, 1.0], dtype=np.float32)
blocked = scene.occluded(cloud.positions, target - cloud.positions, 0.05, 1.0)
print(f"{(~blocked).sum()} points have a clear line to {target}")
