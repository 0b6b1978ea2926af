"""Registration from Python: the CLI's report and the refined pose as an
array, and a pair that does not overlap refused as the CLI refuses it."""

import math

import numpy as np
import pytest

import occlusion
from test_jobs import ROOT, assert_same_report, cli_json

SCAN1 = str(ROOT / "files" / "pcl" / "room_scan1.pcd")
SCAN2 = str(ROOT / "files" / "pcl" / "room_scan2.pcd")


def tutorial_guess(path, dx=0.0):
    """PCL's tutorial guess, 0.6931 rad about z then (1.79387, 0.720047, 0), as a 4 x 4."""
    c, s = math.cos(0.6931), math.sin(0.6931)
    pose = np.array([[c, -s, 0, 1.79387 + dx], [s, c, 0, 0.720047], [0, 0, 1, 0], [0, 0, 0, 1]])
    np.savetxt(path, pose, fmt="%.17g")
    return str(path)


def test_register_equals_cli_and_returns_the_pose(tmp_path):
    guess = tutorial_guess(tmp_path / "guess.txt")
    cli = cli_json("register", SCAN2, "--target", SCAN1, "--initial-pose", guess)
    result = occlusion.register(SCAN2, target=SCAN1, initial_pose=guess)
    assert_same_report(result.report, cli)
    assert result.report["converged"]
    pose = result.refined_pose
    assert pose.shape == (4, 4) and pose.dtype == np.float64
    np.testing.assert_array_equal(pose, np.array(result.report["refined_pose"]["matrix"]))
    # A rigid motion: the refined rotation is orthonormal.
    np.testing.assert_allclose(pose[:3, :3] @ pose[:3, :3].T, np.eye(3), atol=1e-12)


def test_scans_that_do_not_overlap_are_refused(tmp_path):
    far = tutorial_guess(tmp_path / "far.txt", dx=100.0)
    with pytest.raises(occlusion.InputError, match="do not overlap") as error:
        occlusion.register(SCAN2, target=SCAN1, initial_pose=far)
    assert error.value.path == SCAN2
