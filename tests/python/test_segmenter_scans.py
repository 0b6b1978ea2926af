"""Training on virtual scans (python/occlusion_segmenter/scans.py): crew
stations stand where a crew would set a tripod, a scan is the room's mesh as
the laser sees it (labels from its groups, colours from its points), and a
model trained with scans is the same for the same seed, its scans read back
from the cache."""

import json
import os
import pathlib
import shutil
import subprocess
import sys

import numpy as np
import pytest

torch = pytest.importorskip("torch")

ROOT = pathlib.Path(__file__).resolve().parents[2]
BUILD = pathlib.Path(os.environ.get("OCCLUSION_BUILD_DIR", ROOT / "build"))
CLI = pathlib.Path(os.environ.get("OCCLUSION_CLI", BUILD / "occlusion"))
sys.path.insert(0, str(ROOT / "python"))

from occlusion_segmenter import CLASSES  # noqa: E402
from occlusion_segmenter.rooms import read_room, room_dirs  # noqa: E402
from occlusion_segmenter.scans import (CLEARANCE, TRIPOD_HEIGHT,  # noqa: E402
                                       crew_stations, room_scans,
                                       sensor_options)
from occlusion_segmenter.train import train  # noqa: E402


def test_crew_stations_stand_on_the_floor_away_from_walls_and_furniture():
    # A 4 x 3 m room: floor every 5 cm, walls on its sides, a 1 x 1 m table
    # in its middle; stations must keep 0.5 m from both, 1.5 m up.
    grid = np.mgrid[0:4:0.05, 0:3:0.05].reshape(2, -1).T
    floor = np.c_[grid, np.zeros(len(grid))]
    heights = np.arange(0, 2.5, 0.1)
    wall = np.concatenate(
        [np.c_[np.full(len(heights), x), np.full(len(heights), y), heights]
         for x, y in grid if x < 0.01 or y < 0.01 or x > 3.94 or y > 2.94])
    table = np.c_[np.mgrid[1.5:2.5:0.05, 1:2:0.05].reshape(2, -1).T,
                  np.full(400, 0.75)]
    positions = np.concatenate([floor, wall, table])
    labels = np.concatenate([np.full(len(floor), CLASSES.index("floor")),
                             np.full(len(wall), CLASSES.index("wall")),
                             np.full(len(table), CLASSES.index("table"))])
    stations = crew_stations(positions, labels, np.random.default_rng(5), 40)
    assert stations.shape == (40, 3)
    assert np.all(stations[:, 2] == TRIPOD_HEIGHT)
    x, y = stations[:, 0], stations[:, 1]
    # The walls' points stand at x 0 and 3.95, y 0 and 2.95.
    assert np.all((x >= CLEARANCE) & (x <= 3.95 - CLEARANCE))
    assert np.all((y >= CLEARANCE) & (y <= 2.95 - CLEARANCE))
    to_table = np.min(np.linalg.norm(
        table[None, :, :2] - stations[:, None, :2], axis=2), axis=1)
    assert np.all(to_table >= CLEARANCE)
    # Seeded: the same generator state, the same stations.
    again = crew_stations(positions, labels, np.random.default_rng(5), 40)
    assert np.array_equal(stations, again)


@pytest.fixture(scope="module")
def rooms_with_meshes(tmp_path_factory):
    tool = BUILD / "generate_s3dis_room"
    if not (tool.exists() and CLI.exists()):
        pytest.skip("generate_s3dis_room or occlusion is not built")
    out = tmp_path_factory.mktemp("rooms")
    subprocess.run([str(tool), "--dataset", str(out), "--rooms", "1",
                    "--seed", "3", "--spacing", "0.15", "--mesh"], check=True,
                   stderr=subprocess.DEVNULL)
    config = out / "sensor.json"
    config.write_text(json.dumps({"occlusion": {"study": {
        "laser_azimuth_step": 3, "laser_elevation_step": 3,
        "max_incidence": 80}}}))
    return out, config


def test_a_scan_is_the_rooms_mesh_seen_by_the_laser(rooms_with_meshes,
                                                    tmp_path):
    dataset, config = rooms_with_meshes
    options = sensor_options(str(config))
    assert options == ["--azimuth-step", "3", "--elevation-step", "3",
                       "--max-incidence", "80"]
    room = room_dirs(str(dataset))[0]
    positions, colours, labels = read_room(room)
    (p, c, lab), = room_scans(room, (positions, colours, labels), 1, 0,
                              str(CLI), options, str(tmp_path))
    # Every return is near a point of the room of its own class, and takes
    # that room's colours (the nearest point's).
    for k in np.random.default_rng(0).choice(len(p), 200, replace=False):
        distance = np.linalg.norm(positions - p[k], axis=1)
        assert np.min(distance) < 0.25  # the points are 15 cm apart
        # (A near tie may go either way in single precision.)
        near = distance <= np.min(distance) + 0.001
        assert any(np.array_equal(colour, c[k]) for colour in colours[near])
        same = labels == lab[k]
        assert np.min(distance[same]) < 0.25, CLASSES[lab[k]]
    # Fewer points than the room: a scan misses what its stations cannot see.
    assert 0 < len(p)
    assert len(set(lab)) >= 3


def test_a_model_trained_on_scans_is_seeded_and_reads_its_cache(
        rooms_with_meshes, tmp_path):
    dataset, config = rooms_with_meshes
    torch.set_num_threads(1)
    settings = {"steps": 4, "batch": 2, "points": 128, "width": 8,
                "seed": 1, "scans": 2, "scan_config": str(config),
                "occlusion": str(CLI), "scan_cache": str(tmp_path / "cache")}
    quiet = dict(log=lambda text: None)
    train(str(dataset), str(tmp_path / "a.pt"), settings, **quiet)
    cached = sorted(os.listdir(tmp_path / "cache"))
    assert len(cached) == 1 and cached[0].endswith(".npz")
    # Without the program the second training can only read the cache.
    train(str(dataset), str(tmp_path / "b.pt"),
          {**settings, "occlusion": "/nonexistent/occlusion"}, **quiet)
    assert sorted(os.listdir(tmp_path / "cache")) == cached
    a = torch.load(tmp_path / "a.pt")
    b = torch.load(tmp_path / "b.pt")
    assert all(torch.equal(a["state_dict"][k], b["state_dict"][k])
               for k in a["state_dict"])
    assert a["settings"]["scans"] == 2
    # A model without scans is another model (the same seed and rooms).
    train(str(dataset), str(tmp_path / "c.pt"), {**settings, "scans": 0},
          **quiet)
    c = torch.load(tmp_path / "c.pt")
    assert not all(torch.equal(a["state_dict"][k], c["state_dict"][k])
                   for k in a["state_dict"])
    # Rooms without meshes: training on scans says how to make them.
    bare = tmp_path / "bare"
    shutil.copytree(dataset, bare)
    for obj in bare.rglob("*.obj"):
        obj.unlink()
    with pytest.raises(ValueError, match="--mesh"):
        train(str(bare), str(tmp_path / "d.pt"),
              {**settings, "scan_cache": str(tmp_path / "other")}, **quiet)


def test_colours_from_a_cloud_without_colours_are_refused(rooms_with_meshes,
                                                          tmp_path):
    dataset, _ = rooms_with_meshes
    room = room_dirs(str(dataset))[0]
    bare = tmp_path / "bare.ply"
    bare.write_text("ply\nformat ascii 1.0\nelement vertex 2\n"
                    "property float x\nproperty float y\nproperty float z\n"
                    "end_header\n0 0 0\n1 1 1\n")
    mesh = os.path.join(room, os.path.basename(room) + ".obj")
    done = subprocess.run([str(CLI), "simulate", mesh, "--colour-from",
                           str(bare), "--azimuth-step", "5",
                           "--elevation-step", "5", "--out", str(tmp_path)],
                          capture_output=True, text=True)
    assert done.returncode != 0
    assert "--colour-from" in done.stderr and "no coloured points" in \
        done.stderr, done.stderr
    assert not list(tmp_path.glob("*.sim.ply"))
