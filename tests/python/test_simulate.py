"""The virtual scanner from Python: the CLI's report, a Cloud that the other
jobs take as it is, the truth beside it, and arrays in giving what files give."""

import numpy as np
import pytest

import occlusion
from test_jobs import ROOM_MESH, assert_same_report, cli_json

COARSE = dict(azimuth_step=1.0, elevation_step=1.0)


def test_simulate_equals_cli_and_returns_a_cloud():
    cli = cli_json("simulate", ROOM_MESH, "--azimuth-step", "1", "--elevation-step", "1",
                   "--station", "2,2,1.5", "--seed", "4")
    result = occlusion.simulate(ROOM_MESH, stations=[[2, 2, 1.5]], seed=4, **COARSE)
    assert_same_report(result.report, cli)
    cloud = result.cloud
    assert isinstance(cloud, occlusion.Cloud)
    assert cloud.positions.dtype == np.float32 and cloud.positions.shape == (cli["points"], 3)
    assert cloud.labels.shape == cloud.instances.shape == cloud.station_ids.shape == (cli["points"],)
    assert len(cloud.stations) == 1 and "bookcase" in cloud.class_names


def test_the_truth_lies_within_the_noise_of_each_point():
    result = occlusion.simulate(ROOM_MESH, stations=[[2, 2, 1.5]], range_noise=0.002, truth=True,
                                **COARSE)
    fields = result.cloud.fields
    truth = np.stack([fields["true_x"], fields["true_y"], fields["true_z"]], axis=1)
    error = np.linalg.norm(result.cloud.positions - truth, axis=1)
    # |N(0, 1)| over ~50k beams: a few sigma at most, and not all zero.
    assert 0.002 < error.max() < 0.002 * 6
    assert fields["face"].dtype == np.int32


def test_a_simulated_camera_frame_is_scanned_on_its_grid():
    """One camera is an organised frame: its Cloud keeps the sensor and pixels,
    and scan() of it is seen from the camera by default."""
    result = occlusion.simulate(ROOM_MESH, sensor="camera", width=160, height=120, fx=145, fy=145,
                                stations=[[1, 1, 1.2]], look_at=[[5, 4, 1]], noise=False)
    cloud = result.cloud
    assert cloud.pixels is not None and cloud.pixels.shape == (len(cloud.positions),)
    assert cloud.sensor is not None
    seen = occlusion.scan(cloud)
    assert seen.report["viewpoint_source"] == "stations of the file"
    assert seen.viewpoints[0]["position"] == pytest.approx([1, 1, 1.2])
    assert len(np.unique(cloud.pixels)) == len(cloud.pixels) < 160 * 120


def test_arrays_in_give_what_the_file_gives():
    mesh = occlusion.read_mesh(ROOM_MESH)
    from_file = occlusion.simulate(ROOM_MESH, stations=[[2, 2, 1.5]], **COARSE)
    from_arrays = occlusion.simulate((mesh.vertices, mesh.faces, mesh.face_group, mesh.group_names),
                                     stations=[[2, 2, 1.5]], **COARSE)
    np.testing.assert_array_equal(from_arrays.cloud.positions, from_file.cloud.positions)
    assert from_arrays.cloud.class_names == from_file.cloud.class_names


def test_a_camera_without_its_target_is_a_usage_error():
    with pytest.raises(occlusion.UsageError, match="look_at"):
        occlusion.simulate(ROOM_MESH, sensor="camera", stations=[[1, 1, 1]])
