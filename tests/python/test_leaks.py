"""No references or memory kept over a loop of calls: inputs keep their
reference counts, and arrays handed out are freed with their last reference."""

import gc
import sys

import numpy as np

import occlusion


def resident_bytes():
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * 4096


def test_inputs_keep_their_reference_counts():
    rng = np.random.default_rng(9)
    points = rng.uniform(-1, 1, (200, 3))
    origins = rng.uniform(-1, 1, (100, 3)).astype(np.float32)
    directions = rng.normal(size=(100, 3))
    t_max = np.full(100, 2.0)
    scene = occlusion.SphereScene(points, 0.05)
    before = [sys.getrefcount(a) for a in (points, origins, directions, t_max, scene)]
    for _ in range(500):
        scene.intersect(origins, directions, 0.0, t_max)
        scene.occluded(origins, directions, 0.0, t_max)
        occlusion.SphereScene(points, 0.05)
    gc.collect()
    after = [sys.getrefcount(a) for a in (points, origins, directions, t_max, scene)]
    assert before == after


def test_results_and_errors_are_freed(tmp_path):
    rng = np.random.default_rng(10)
    path = str(tmp_path / "c.ply")
    occlusion.write_cloud(path, rng.uniform(0, 1, (20000, 3)), labels=np.zeros(20000, dtype=np.int32))
    scene = occlusion.TriangleScene(np.eye(3), [[0, 1, 2]])
    directions = rng.normal(size=(20000, 3))

    def work():
        cloud = occlusion.read_cloud(path)
        assert cloud.positions.shape == (20000, 3)
        scene.intersect(np.zeros(3), directions)
        try:
            occlusion.read_cloud(str(tmp_path / "missing.ply"))
        except FileNotFoundError:
            pass

    for _ in range(20):  # warm up allocator pools
        work()
    gc.collect()
    start = resident_bytes()
    objects = len(gc.get_objects())
    for _ in range(200):  # about 100 MB of arrays pass through
        work()
    gc.collect()
    assert resident_bytes() - start < 8 * 2**20
    assert len(gc.get_objects()) - objects < 50
