"""The tables of docs/simulate.md ("With the noise-tolerant model"): scans by
the virtual scanner with a sensor's noise, -fscan from their own stations and
per-point agreement with the mesh's truth from other viewpoints, noisy against
noise-free. Run by hand (a few minutes on 2 cores):

    PYTHONPATH=build/python python3 bench/noisy_scan_tables.py [-box] [-room1]
        [-room4] [-cam]
"""
import pathlib
import sys
import tempfile
import time

import numpy as np

import occlusion

ROOT = pathlib.Path(__file__).resolve().parents[1]
ROOM = str(ROOT / "files" / "sample_room.obj")


def write_box_room(path):
    """A 6 x 5 x 3 m room, a 1 m crate and a 10 cm thick wall stub."""
    vertices, faces, groups = [], [], []

    def box(lo, hi, name, inward):
        base = len(vertices)
        for x in (lo[0], hi[0]):
            for y in (lo[1], hi[1]):
                for z in (lo[2], hi[2]):
                    vertices.append((x, y, z))
        quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6),
                 (0, 2, 6, 4), (1, 5, 7, 3)]
        for quad in quads:
            a, b, c, d = [base + i for i in quad]
            if inward:
                faces.extend([(a, c, b), (a, d, c)])
            else:
                faces.extend([(a, b, c), (a, c, d)])
        groups.extend([name] * 12)

    box((0, 0, 0), (6, 5, 3), "room", True)
    box((2.5, 1.5, 0), (3.5, 2.5, 1), "crate", False)
    box((4, 0, 0), (4.1, 3, 2.2), "wall_1", False)
    with open(path, "w") as out:
        for v in vertices:
            out.write("v %g %g %g\n" % v)
        current = None
        for face, group in zip(faces, groups):
            if group != current:
                current = group
                out.write("g %s\n" % group)
            out.write("f %d %d %d\n" % tuple(i + 1 for i in face))


def truth_seen(scene, true_points, viewpoint, diagonal):
    d = true_points - viewpoint
    length = np.linalg.norm(d, axis=1)
    t_max = 1.0 - 1e-5 * diagonal / np.maximum(length, 1e-9)
    return ~scene.occluded(viewpoint, d, 0.0, t_max)


def agreement(cloud, scene, true_points, viewpoint, diagonal):
    result = occlusion.scan(cloud, viewpoints=[list(map(float, viewpoint))])
    seen = result.arrays["mask"]
    truth = truth_seen(scene, true_points, np.asarray(viewpoint, float),
                       diagonal)
    window = result.report.get("station_field_of_view")
    if window:
        # -fscan sees nothing outside the station's elevation window.
        low, high = window["elevation_degrees"]
        d = true_points - np.asarray(viewpoint, float)
        elevation = np.degrees(np.arctan2(d[:, 2], np.hypot(d[:, 0], d[:, 1])))
        truth &= (elevation >= low - 1e-6) & (elevation <= high + 1e-6)
    return float(np.mean(seen == truth))


def evaluate(name, mesh_path, stations, others, sensor, noise_levels):
    mesh = occlusion.read_mesh(mesh_path)
    scene = occlusion.TriangleScene(mesh.vertices, mesh.faces)
    low, high = scene.bounds
    diagonal = float(np.linalg.norm(high - low))
    for noise in noise_levels:
        keys = dict(sensor)
        if noise is None:
            keys["noise"] = False
        elif noise != "default":
            keys["range_noise"] = noise
        cloud = occlusion.simulate(mesh_path, stations=stations, truth=True,
                                   seed=7, **keys).cloud
        fields = cloud.fields
        true_points = np.stack([fields["true_x"], fields["true_y"],
                                fields["true_z"]], 1).astype(np.float64)
        kept = []
        for s, station in enumerate(stations):
            seen = occlusion.scan(cloud, viewpoints=[station]).arrays["mask"]
            kept.append(seen[cloud.station_ids == s])
        kept = np.concatenate(kept)
        agreements = [agreement(cloud, scene, true_points, v, diagonal)
                      for v in others]
        print(f"{name:24s} noise={str(noise):8s} "
              f"points={len(cloud.positions):8d} own={kept.mean() * 100:6.2f}% "
              "agreement=" + " ".join(f"{a:.3f}" for a in agreements),
              flush=True)


def main(args):
    chosen = set(args) or {"-box", "-room1", "-room4", "-cam"}
    laser = dict(azimuth_step=0.3, elevation_step=0.3)
    camera = dict(sensor="camera", width=640, height=480, fx=525, fy=525)
    start = time.time()
    with tempfile.TemporaryDirectory() as folder:
        box = str(pathlib.Path(folder) / "box_room.obj")
        write_box_room(box)
        if "-box" in chosen:
            evaluate("box, 1 station", box, [[1.5, 3.5, 1.5]],
                     [[5.0, 1.0, 1.6], [3.0, 4.0, 2.5]], laser,
                     [None, 0.001, 0.003, 0.005])
        if "-room1" in chosen:
            evaluate("room, 1 station", ROOM, [[2, 2, 1.5]],
                     [[3, 2.5, 0.8], [5.2, 4, 2]], laser,
                     [None, 0.001, 0.003, 0.005])
        if "-room4" in chosen:
            stations = [[1.5, 1.5, 1.5], [4.5, 1.5, 1.5], [1.5, 3.5, 1.5],
                        [4.5, 3.5, 1.5]]
            evaluate("room, 4 stations", ROOM, stations,
                     [[3, 2.5, 0.8], [5.2, 4, 2]],
                     dict(azimuth_step=0.5, elevation_step=0.5), [None, 0.003])
        if "-cam" in chosen:
            evaluate("room, camera", ROOM, [[1, 1, 1.2]],
                     [[3, 2.5, 0.8], [2.0, 3.5, 1.5]],
                     dict(camera, look_at=[[5, 4, 1]]), [None, "default"])
            evaluate("box, camera", box, [[0.5, 0.5, 1.2]],
                     [[5.0, 1.0, 1.6], [1.0, 4.0, 2.0]],
                     dict(camera, look_at=[[3.9, 4, 1]]), [None, "default"])
    print("seconds", round(time.time() - start, 1))


if __name__ == "__main__":
    main(sys.argv[1:])
