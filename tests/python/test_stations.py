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
