"""TriangleScene and SphereScene: analytic answers, brute force on random rays
with a fixed seed, dtypes and layouts, errors and interruption."""

import threading
import _thread

import numpy as np
import pytest

import occlusion
import reference

NO_HIT = occlusion.NO_PRIMITIVE


def unit_square():
    # Two triangles covering [0, 1]^2 at z = 2.
    vertices = np.array([[0, 0, 2], [1, 0, 2], [1, 1, 2], [0, 1, 2]], dtype=np.float64)
    faces = np.array([[0, 1, 2], [0, 2, 3]])
    return vertices, faces


def random_rays(rng, count, spread=1.0):
    origins = rng.uniform(-spread, spread, (count, 3))
    directions = rng.normal(size=(count, 3))
    return origins, directions


def random_triangles(rng, count):
    centres = rng.uniform(-1, 1, (count, 1, 3))
    vertices = (centres + rng.uniform(-0.3, 0.3, (count, 3, 3))).reshape(-1, 3)
    return vertices, np.arange(3 * count).reshape(count, 3)


class TestAnalytic:
    def test_square_hit_at_known_t(self):
        scene = occlusion.TriangleScene(*unit_square())
        origins = np.zeros((3, 3))
        # Aimed at (0.25, 0.5, 2), (0.75, 0.25, 2) and past the square.
        directions = np.array([[0.25, 0.5, 2], [0.75, 0.25, 2], [3, 0, 2]], dtype=np.float32)
        t, ids = scene.intersect(origins, directions)
        assert t.dtype == np.float32 and t.shape == (3,)
        assert ids.dtype == np.uint32 and ids.shape == (3,)
        np.testing.assert_array_equal(t, [1.0, 1.0, np.inf])
        np.testing.assert_array_equal(ids, [1, 0, NO_HIT])
        np.testing.assert_array_equal(scene.occluded(origins, directions), [True, True, False])

    def test_interval_is_closed(self):
        scene = occlusion.TriangleScene(*unit_square())
        d = np.array([[0.5, 0.25, 2.0]])
        assert scene.occluded([0, 0, 0], d, 0.0, 1.0)[0]
        assert not scene.occluded([0, 0, 0], d, 0.0, np.nextafter(np.float32(1), np.float32(0)))[0]
        assert not scene.occluded([0, 0, 0], d, np.nextafter(np.float32(1), np.float32(2)))[0]

    def test_sphere_entry_and_exit(self):
        scene = occlusion.SphereScene(np.array([[0.0, 0.0, 5.0], [0.0, 0.0, 9.0]]), 1.0)
        origins = np.array([[0, 0, 0], [0, 0, 5], [0, 0, 0]], dtype=np.float64)
        directions = np.array([[0, 0, 2], [0, 0, 1], [0, 1, 0]], dtype=np.float64)
        t, ids = scene.intersect(origins, directions)
        # Entry at z = 4 in units of |d| = 2; from inside, the exit at z = 6.
        np.testing.assert_array_equal(t, [2.0, 1.0, np.inf])
        np.testing.assert_array_equal(ids, [0, 0, NO_HIT])

    def test_tie_goes_to_lower_id(self):
        vertices, faces = unit_square()
        scene = occlusion.TriangleScene(np.vstack([vertices, vertices]), np.vstack([faces + 4, faces]))
        t, ids = scene.intersect([0, 0, 0], [[0.25, 0.5, 2.0]])
        assert t[0] == 1.0 and ids[0] == 1  # faces 1 and 3 coincide: the lower id

    def test_len_bounds_stats(self):
        scene = occlusion.TriangleScene(*unit_square())
        assert len(scene) == 2
        lo, hi = scene.bounds
        np.testing.assert_array_equal(lo, [0, 0, 2])
        np.testing.assert_array_equal(hi, [1, 1, 2])
        assert scene.stats["leaves"] >= 1 and scene.stats["memory_bytes"] > 0


@pytest.mark.parametrize("accelerated", [True, False])
def test_triangles_match_brute_force(accelerated):
    rng = np.random.default_rng(14)
    vertices, faces = random_triangles(rng, 150)
    origins, directions = random_rays(rng, 3000)
    t_max = rng.uniform(0.5, 4.0, len(directions))
    scene = occlusion.TriangleScene(vertices, faces, enable_acceleration=accelerated)
    t, ids = scene.intersect(origins, directions, 0.0, t_max)
    ref_t, ref_ids, ambiguous = reference.triangles(vertices, faces, origins, directions, 0.0, t_max)
    sure = ~ambiguous
    assert sure.sum() > 0.9 * len(sure)
    hits = sure & (ref_ids >= 0)
    assert hits.sum() > 300  # the scene is dense enough to test hits, not only misses
    np.testing.assert_array_equal(ids[sure].astype(np.int64), np.where(ref_ids[sure] < 0, NO_HIT, ref_ids[sure]))
    np.testing.assert_allclose(t[hits], ref_t[hits], rtol=1e-4, atol=1e-5)
    # occluded is "intersect found a hit", ray for ray, ambiguous ones included.
    np.testing.assert_array_equal(scene.occluded(origins, directions, 0.0, t_max), ids != NO_HIT)


def test_spheres_match_brute_force():
    rng = np.random.default_rng(41)
    points = rng.uniform(-1, 1, (400, 3))
    origins, directions = random_rays(rng, 3000, spread=1.5)
    t_min = rng.uniform(0.0, 0.2, len(directions))
    scene = occlusion.SphereScene(points, 0.05)
    t, ids = scene.intersect(origins, directions, t_min, 3.0)
    ref_t, ref_ids, ambiguous = reference.spheres(points, 0.05, origins, directions, t_min, 3.0)
    sure = ~ambiguous
    assert sure.sum() > 0.9 * len(sure)
    hits = sure & (ref_ids >= 0)
    assert hits.sum() > 300
    np.testing.assert_array_equal(ids[sure].astype(np.int64), np.where(ref_ids[sure] < 0, NO_HIT, ref_ids[sure]))
    np.testing.assert_allclose(t[hits], ref_t[hits], rtol=1e-4, atol=1e-5)
    np.testing.assert_array_equal(scene.occluded(origins, directions, t_min, 3.0), ids != NO_HIT)


def test_layouts_and_dtypes_give_the_same_answer():
    rng = np.random.default_rng(3)
    vertices, faces = random_triangles(rng, 60)
    origins, directions = random_rays(rng, 500)
    scene = occlusion.TriangleScene(vertices.astype(np.float32), faces.astype(np.int32))
    expected = scene.intersect(origins.astype(np.float32), directions.astype(np.float32))
    variants = [
        (origins, directions),  # float64
        (np.asfortranarray(origins), np.asfortranarray(directions)),
        (np.hstack([origins, origins])[:, :3], directions),  # rows 48 bytes apart
    ]
    interleaved = np.zeros((len(origins), 6))
    interleaved[:, ::2] = origins  # columns 16 bytes apart
    variants.append((interleaved[:, ::2], directions))
    doubled = np.repeat(directions.astype(np.float32), 2, axis=0)[::2]  # every other row
    variants.append((origins.astype(np.float32), doubled))
    for o, d in variants:
        t, ids = scene.intersect(o.astype(o.dtype), d)
        np.testing.assert_array_equal(ids, expected[1])
        np.testing.assert_array_equal(t, expected[0])
    # Threads do not change answers.
    t1, ids1 = scene.intersect(origins, directions, threads=1)
    np.testing.assert_array_equal(ids1, expected[1])


def test_one_origin_for_all_rays():
    scene = occlusion.TriangleScene(*unit_square())
    directions = np.array([[0.25, 0.5, 2.0], [0.5, 0.25, 2.0], [0, 0, -1]])
    t, ids = scene.intersect(np.zeros(3), directions)
    t2, ids2 = scene.intersect(np.zeros((3, 3)), directions)
    np.testing.assert_array_equal(ids, ids2)
    np.testing.assert_array_equal(t, t2)


def test_empty_batch():
    scene = occlusion.TriangleScene(*unit_square())
    t, ids = scene.intersect(np.zeros((0, 3)), np.zeros((0, 3)))
    assert t.shape == (0,) and ids.shape == (0,)


class TestErrors:
    def test_bad_shapes(self):
        scene = occlusion.TriangleScene(*unit_square())
        with pytest.raises(ValueError, match="directions"):
            scene.intersect(np.zeros((2, 3)), np.zeros((2, 2)))
        with pytest.raises(ValueError, match="origins"):
            scene.intersect(np.zeros((3, 3)), np.zeros((2, 3)))
        with pytest.raises(ValueError, match="t_max"):
            scene.occluded(np.zeros((2, 3)), np.ones((2, 3)), 0.0, np.ones(3))
        with pytest.raises(ValueError, match="directions"):
            scene.intersect(np.zeros(3), "up")

    def test_bad_faces(self):
        vertices, faces = unit_square()
        with pytest.raises(ValueError, match="vertex 4"):
            occlusion.TriangleScene(vertices, faces + 1)
        with pytest.raises(ValueError, match="vertex -1"):
            occlusion.TriangleScene(vertices, faces - 1)
        # An unsigned index past 2^63 was cast to int64 and reported negative.
        huge = faces.astype(np.uint64)
        huge[1, 2] = 2**64 - 1
        with pytest.raises(ValueError, match="face 1 uses vertex 18446744073709551615"):
            occlusion.TriangleScene(vertices, huge)
        with pytest.raises(ValueError, match="integer"):
            occlusion.TriangleScene(vertices, faces.astype(np.float64))
        with pytest.raises(ValueError, match="shape"):
            occlusion.TriangleScene(vertices, faces[:, :2])
        bad = vertices.copy()
        bad[0, 0] = np.nan
        with pytest.raises(ValueError):
            occlusion.TriangleScene(bad, faces)

    def test_bad_spheres(self):
        with pytest.raises(ValueError):
            occlusion.SphereScene(np.zeros((2, 3)), 0.0)
        with pytest.raises(ValueError):
            occlusion.SphereScene(np.array([[0, 0, np.inf]]), 0.1)
        with pytest.raises(ValueError, match="octree_resolution"):
            occlusion.SphereScene(np.zeros((2, 3)), 0.1, octree_resolution=-1.0)


def test_ctrl_c_interrupts_a_long_batch():
    rng = np.random.default_rng(5)
    # Brute force over 5000 spheres: a block of 65536 rays takes about a second,
    # the whole batch many; the interrupt must land after the first block.
    scene = occlusion.SphereScene(rng.uniform(-1, 1, (5000, 3)), 1e-3, enable_acceleration=False)
    directions = rng.normal(size=(400000, 3)).astype(np.float32)
    timer = threading.Timer(0.3, _thread.interrupt_main)
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            scene.occluded(np.zeros(3), directions)
    finally:
        timer.cancel()
    # The scene is still usable afterwards.
    assert scene.occluded(np.zeros(3), directions[:10]).shape == (10,)


class TestDiscs:
    def test_disc_hit_at_known_t_and_rim(self):
        scene = occlusion.DiscScene([[0.0, 0.0, 5.0]], [[0.0, 0.0, 3.0]], [1.0])
        origins = np.array([[0.5, 0.0, 0.0], [1.5, 0.0, 0.0], [0.0, 0.0, 5.0]])
        directions = np.array([[0.0, 0.0, 2.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0]])
        t, ids = scene.intersect(origins, directions)
        # Crossing at t = 2.5 in units of |d| = 2; outside the rim; in the plane.
        np.testing.assert_array_equal(t, [2.5, np.inf, np.inf])
        np.testing.assert_array_equal(ids, [0, NO_HIT, NO_HIT])
        np.testing.assert_allclose(scene.normals, [[0.0, 0.0, 1.0]])

    def test_zero_normal_is_a_sphere(self):
        discs = occlusion.DiscScene([[0.0, 0.0, 5.0]], [[0.0, 0.0, 0.0]], 1.0)
        spheres = occlusion.SphereScene([[0.0, 0.0, 5.0]], 1.0)
        origins = np.array([[0.6, 0.0, 0.0], [0.0, 0.0, 5.0]])
        directions = np.array([[0.0, 0.0, 1.0], [1.0, 0.0, 0.0]])
        np.testing.assert_array_equal(discs.intersect(origins, directions)[0],
                                      spheres.intersect(origins, directions)[0])

    def test_estimated_discs_close_a_plane_that_spheres_leak_through(self):
        rng = np.random.default_rng(1)
        points = np.c_[rng.uniform(0, 4, (20000, 2)), np.zeros(20000)]
        discs = occlusion.DiscScene(points)
        assert discs.normals.shape == (20000, 3) and discs.radii.shape == (20000,)
        np.testing.assert_allclose(np.abs(discs.normals[:, 2]), 1.0, atol=1e-5)
        origins = np.c_[rng.uniform(1, 3, (5000, 2)), np.ones(5000)]
        down = np.tile([0.3, 0.0, -1.0], (5000, 1))
        assert discs.occluded(origins, down).mean() >= 0.995
        # The thesis' spheres at 0.71 x the median spacing (-poc's old auto) leak.
        spacing = 0.47 / np.sqrt(20000 / 16)
        spheres = occlusion.SphereScene(points, 0.71 * spacing)
        assert spheres.occluded(origins, down).mean() < 0.5

    def test_bad_arguments_are_value_errors(self):
        with pytest.raises(ValueError):
            occlusion.DiscScene([[0.0, 0.0, 0.0]], [[0.0, 0.0, 1.0]])
        with pytest.raises(ValueError):
            occlusion.DiscScene([[0.0, 0.0, 0.0]], [[0.0, 0.0, 1.0]], [0.0])
        with pytest.raises(ValueError):
            occlusion.DiscScene([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]], [[0.0, 0.0, 1.0]], 1.0)
