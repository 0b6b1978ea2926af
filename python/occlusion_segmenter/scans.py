"""Training scans: a training room as the virtual scanner sees it from
stations a survey crew would choose, so that a segmenter learns what scans
lack (holes behind furniture, density falling with range, range noise).

Each scan is `occlusion simulate` of the room's mesh (ROOM/ROOM.obj, written
by generate_s3dis_room --mesh) from 1 to 3 stations, each return coloured
from the room's nearest point (--colour-from), with the sensor the study's
config describes (its laser_* keys and max_incidence), so that the model
trained on scans and the study's laser scans come from one scanner. Scans
are cached as .npz files named by everything that makes them.
"""

import hashlib
import json
import os
import subprocess
import tempfile

import numpy as np

from . import CLASSES
from .ply import read_class_names, read_vertices

# Where a crew sets a tripod: the scanner's head this high above the floor,
# on the floor of the room (a floor point within FLOOR_REACH), and at least
# CLEARANCE from walls and furniture seen from above, between the floor and
# head height.
TRIPOD_HEIGHT = 1.5
FLOOR_REACH = 0.3
CLEARANCE = 0.5
MAX_STATIONS = 3


def crew_stations(positions, labels, rng, count):
    """`count` stations (x, y, z) in the room, drawn by rejection."""
    floor = labels == CLASSES.index("floor")
    if not floor.any():
        raise ValueError("the room has no floor points to stand on")
    floor_z = float(np.median(positions[floor, 2]))
    standing = ~np.isin(labels, [CLASSES.index("floor"),
                                 CLASSES.index("ceiling")])
    height = positions[:, 2] - floor_z
    obstacles = positions[standing & (height > 0.05) &
                          (height < TRIPOD_HEIGHT + 0.3), :2]
    floor_xy = positions[floor, :2]
    lo, hi = floor_xy.min(0), floor_xy.max(0)
    stations = []
    for _ in range(10000):
        xy = lo + rng.random(2) * (hi - lo)
        if np.min(np.sum((floor_xy - xy) ** 2, 1)) > FLOOR_REACH ** 2:
            continue  # outside the room (an L's missing corner)
        if len(obstacles) and np.min(
                np.sum((obstacles - xy) ** 2, 1)) < CLEARANCE ** 2:
            continue
        stations.append((xy[0], xy[1], floor_z + TRIPOD_HEIGHT))
        if len(stations) == count:
            return np.array(stations)
    raise ValueError(f"no room for {count} stations {CLEARANCE} m from "
                     "walls and furniture")


def sensor_options(config_path):
    """simulate's options for the study config's sensor: its laser_* keys
    (the laser's own names without the prefix) and max_incidence."""
    with open(config_path) as stream:
        study = json.load(stream).get("occlusion", {}).get("study", {})
    options = []
    for key in sorted(study):
        if key.startswith("laser_") or key == "max_incidence":
            name = key[len("laser_"):] if key.startswith("laser_") else key
            options += ["--" + name.replace("_", "-"), str(study[key])]
    return options


def mesh_of(room_dir):
    name = os.path.basename(os.path.normpath(room_dir))
    mesh = os.path.join(room_dir, name + ".obj")
    if not os.path.isfile(mesh):
        raise ValueError(f"{room_dir}: no {name}.obj: make the rooms with "
                         "generate_s3dis_room --mesh to train on scans")
    return mesh


def simulate(occlusion, room_dir, stations, seed, options):
    """One scan: (positions, colours, labels as CLASSES indices)."""
    with tempfile.TemporaryDirectory() as out:
        command = [occlusion, "simulate", mesh_of(room_dir), "--colour-from",
                   room_dir, "--seed", str(seed), "--format", "ply",
                   "--out", out, "-q"] + options
        for x, y, z in stations:
            command += ["--station", f"{x:.6f},{y:.6f},{z:.6f}"]
        done = subprocess.run(command, stdout=subprocess.DEVNULL,
                              stderr=subprocess.PIPE, text=True)
        if done.returncode != 0:
            raise RuntimeError(f"{' '.join(command)} failed: "
                               f"{done.stderr.strip()}")
        ply = [f for f in os.listdir(out) if f.endswith(".sim.ply")]
        path = os.path.join(out, ply[0])
        vertices = read_vertices(path)
        names = read_class_names(path)
    to_class = np.array([CLASSES.index(n) for n in names], dtype=np.int64)
    positions = np.stack([vertices[a] for a in "xyz"], 1).astype(np.float64)
    colours = np.stack([vertices[c] for c in ("red", "green", "blue")], 1)
    # occlusion writes labels as scalar_label (CloudCompare's scalar field).
    label = "label" if "label" in vertices.dtype.names else "scalar_label"
    return positions, colours.astype(np.float32), to_class[vertices[label]]


def room_scans(room_dir, room, count, seed, occlusion, options, cache):
    """`count` scans of one room (positions, colours, labels each), drawn
    from (seed, the room's name): the same arguments give the same scans."""
    positions, _, labels = room
    name = os.path.basename(os.path.normpath(room_dir))
    key = hashlib.sha256(json.dumps(
        [name, count, seed, options, TRIPOD_HEIGHT, FLOOR_REACH, CLEARANCE,
         MAX_STATIONS, os.path.getsize(mesh_of(room_dir))]).encode())
    cached = os.path.join(cache, f"{name}.{key.hexdigest()[:16]}.npz")
    if os.path.isfile(cached):
        with np.load(cached) as data:
            return [(data[f"p{k}"], data[f"c{k}"], data[f"l{k}"])
                    for k in range(count)]
    digest = int.from_bytes(hashlib.sha256(name.encode()).digest()[:8],
                            "little")
    rng = np.random.default_rng([seed, digest])
    scans = []
    for k in range(count):
        stations = crew_stations(positions, labels, rng,
                                 int(rng.integers(1, MAX_STATIONS + 1)))
        scans.append(simulate(occlusion, room_dir, stations,
                              int(rng.integers(2 ** 31)), options))
    os.makedirs(cache, exist_ok=True)
    arrays = {}
    for k, (p, c, lab) in enumerate(scans):
        arrays.update({f"p{k}": p, f"c{k}": c, f"l{k}": lab})
    partial = cached + ".partial.npz"
    np.savez(partial, **arrays)
    os.replace(partial, cached)
    return scans
