"""Scanner stations from Python: a Cloud's stations, each point's station and
intensity survive write_cloud and read_cloud, and are the jobs' default
viewpoints; scans, min_range and max_range filter by them."""

import numpy as np
import pytest

import occlusion


def two_station_room():
    """A floor seen by "west" and a wall x = 4 seen by "east"."""
    grid = np.arange(41) * 0.1
    floor = np.array([[x, y, 0.0] for x in grid for y in grid], np.float32)
    wall = np.array([[4.0, y, 0.075 * k] for y in grid for k in range(41)], np.float32)
    positions = np.vstack([floor, wall])
    station_ids = np.repeat([0, 1], [len(floor), len(wall)]).astype(np.int32)
    stations = [
        {"name": "west", "origin": (1.5, 2.0, 1.5)},
        {"name": "east \"b\"", "origin": (6.0, 2.0, 1.5),
         "orientation": (0.0, 0.0, 0.0, 1.0), "width": 8640, "height": 3600},
    ]
    return positions, station_ids, stations


def test_stations_round_trip_through_ply(tmp_path):
    positions, station_ids, stations = two_station_room()
    intensities = np.linspace(0, 1, len(positions), dtype=np.float32)
    path = str(tmp_path / "room.ply")
    occlusion.write_cloud(path, positions, intensities=intensities,
                          station_ids=station_ids, stations=stations)
    cloud = occlusion.read_cloud(path)
    np.testing.assert_array_equal(cloud.intensities, intensities)
    np.testing.assert_array_equal(cloud.station_ids, station_ids)
    assert [s["name"] for s in cloud.stations] == ["west", "east \"b\""]
    assert cloud.stations[1]["origin"] == (6.0, 2.0, 1.5)
    assert cloud.stations[1]["orientation"] == (0.0, 0.0, 0.0, 1.0)
    assert (cloud.stations[1]["width"], cloud.stations[1]["height"]) == (8640, 3600)
    assert cloud.stations[0]["orientation"] == (1.0, 0.0, 0.0, 0.0)


def test_a_clouds_stations_are_the_default_viewpoints(tmp_path):
    positions, station_ids, stations = two_station_room()
    path = str(tmp_path / "room.ply")
    occlusion.write_cloud(path, positions, station_ids=station_ids, stations=stations)
    cloud = occlusion.read_cloud(path)
    keys = dict(primitive="sphere", point_radius=0.05)
    from_file = occlusion.scan(path, **keys)
    in_memory = occlusion.scan(cloud, **keys)
    for result in (from_file, in_memory):
        assert result.viewpoint_source == "stations of the file"
        assert [v["name"] for v in result.viewpoints] == ["west", "east \"b\""]
    assert in_memory.visible_points == from_file.visible_points
    # A pattern given wins; bare points have no stations.
    assert occlusion.scan(cloud, pattern=1, **keys).viewpoint_source == "pattern 1"
    assert occlusion.scan(cloud.positions, **keys).viewpoint_source == "pattern 7"


def test_scans_and_ranges_filter_in_memory():
    positions, station_ids, stations = two_station_room()
    path_free = dict(primitive="sphere", point_radius=0.05)
    with pytest.raises(occlusion.UsageError, match="'west', 'east \"b\"'"):
        occlusion.scan(_cloud(positions, station_ids, stations), scans=["north"], **path_free)
    result = occlusion.scan(_cloud(positions, station_ids, stations), scans=["west"],
                            min_range=1.0, **path_free)
    assert result.station_filter["dropped_other_scans"] == 41 * 41
    # Floor points within 1 m of (1.5, 2, 1.5): none, it stands 1.5 m above.
    assert result.station_filter["dropped_too_near"] == 0
    assert result.points == 41 * 41
    with pytest.raises(occlusion.UsageError, match="measures each point's range"):
        occlusion.scan(positions, max_range=3.0, **path_free)


def _cloud(positions, station_ids, stations):
    class Arrays:
        pass

    cloud = Arrays()
    cloud.positions = positions
    cloud.labels = None
    cloud.colours = None
    cloud.class_names = []
    cloud.intensities = None
    cloud.station_ids = station_ids
    cloud.stations = stations
    return cloud


def plate_before_wall():
    """The wall x = 0 every 2 cm, a plate x = 1 around (1, 0, 1), stations A
    (2, -1, 1) and B (2, 1, 1): the plate's shadow from A is y, z in
    [0.6, 1.4] on the wall, from B y in [-1.4, -0.6] (the wall is twice as far
    as the plate), and a patch at x = 0.9 behind the plate is hidden from both."""
    ys = -1.59 + 0.02 * np.arange(160)
    zs = 0.01 + 0.02 * np.arange(100)
    wall = np.array([[0.0, y, z] for y in ys for z in zs], np.float32)
    plate = np.array([[1.0, -0.2 + 0.02 * i, 0.8 + 0.02 * j]
                      for i in range(21) for j in range(21)], np.float32)
    patch = np.array([[0.9, -0.04 + 0.02 * i, 0.96 + 0.02 * j]
                      for i in range(5) for j in range(5)], np.float32)
    positions = np.vstack([wall, plate, patch])
    stations = [{"name": "A", "origin": (2.0, -1.0, 1.0)},
                {"name": "B", "origin": (2.0, 1.0, 1.0)}]
    return positions, len(wall), stations


def test_scan_answers_per_station():
    positions, walls, stations = plate_before_wall()
    cloud = _cloud(positions, None, stations)
    result = occlusion.scan(cloud, primitive="sphere", point_radius=0.02)
    count, first = result.visible_count, result.covered_by
    assert first.dtype == np.int32 and first.shape == (len(positions),)
    assert [v["name"] for v in result.viewpoints] == ["A", "B"]
    # The arrays' marginals are the per-station figures.
    for v in range(2):
        assert result.only_by_viewpoint[v] == np.sum((count == 1) & (first == v + 1))
        assert result.viewpoints[v]["only_points"] == result.only_by_viewpoint[v]
    assert result.seen_by_viewpoint.sum() == count.sum()
    assert np.all((first == -1) == (count == 0))
    # They add up: only A, only B, both, none.
    assert (result.only_by_viewpoint.sum() + result.seen_by_several_points
            + result.seen_by_none_points) == len(positions)
    # The hand-worked shadows, away from their edges: A's seen by B alone, B's by A alone.
    y, z = positions[:walls, 1], positions[:walls, 2]
    core = np.abs(z - 1.0) < 0.34
    in_a_shadow = core & (np.abs(y - 1.0) < 0.34)
    in_b_shadow = core & (np.abs(y + 1.0) < 0.34)
    assert np.all(count[:walls][in_a_shadow] == 1)
    assert np.all(first[:walls][in_a_shadow] == 2)
    assert np.all(count[:walls][in_b_shadow] == 1)
    assert np.all(first[:walls][in_b_shadow] == 1)
    assert np.all(count[-25:] == 0)
    assert result.seen_by_none_points == 25
