"""A project file (files/projects/mixed.project.json: E57, PCD, PLY and text
scans with their poses) read into Python and scanned: the same scene as the
library, the command line and the server load, the stations where the poses
put them (worked by hand in files/projects/SOURCES.md)."""

import json
import os
import pathlib
import subprocess

import numpy as np
import pytest

import occlusion

ROOT = pathlib.Path(__file__).resolve().parents[2]
BUILD = pathlib.Path(os.environ.get("OCCLUSION_BUILD_DIR", ROOT / "build"))
CLI = pathlib.Path(os.environ.get("OCCLUSION_CLI", BUILD / "occlusion"))
PROJECT = str(ROOT / "files" / "projects" / "mixed.project.json")
STATIONS_BY_HAND = [(5, 4, 6), (2, 0, 0), (0, 7, 0.5), (0, 3, 0)]


def station_positions(cloud):
    return np.array([s["origin"] for s in cloud.stations]) + np.array(cloud.shift)


def test_a_project_reads_as_one_cloud_with_its_stations():
    cloud = occlusion.read_cloud(PROJECT)
    assert len(cloud) == 16
    assert [s["name"] for s in cloud.stations][1:] == ["pcd", "wall", "text"]
    np.testing.assert_allclose(station_positions(cloud), STATIONS_BY_HAND, atol=1e-9)
    np.testing.assert_array_equal(cloud.station_ids, np.repeat(np.arange(4), 4))
    # The text scan in millimetres, moved 3 m along y: (1000, 500, 500) mm -> (1, 3.5, 0.5) m.
    np.testing.assert_allclose(cloud.positions[15] + np.array(cloud.shift), (1, 3.5, 0.5), atol=1e-6)
    # Only the PLY has colours: none are invented for the others, and it is said.
    assert cloud.colours is None
    assert any("colours were dropped" in w for w in cloud.warnings)


def test_a_scan_of_a_project_is_the_clis(tmp_path):
    if not CLI.exists():
        pytest.skip("the CLI is not built")
    result = occlusion.scan(PROJECT)
    run = subprocess.run(
        [str(CLI), "-fscan", PROJECT, "--out", str(tmp_path), "--json", "-q"],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert run.returncode == 0, run.stderr
    cli = json.loads(run.stdout)
    assert result.report["points"] == cli["points"] == 16
    assert result.report["visible_points"] == cli["visible_points"]
    full = occlusion.read_cloud(str(tmp_path / "mixed.project.scan_full.ply"))
    np.testing.assert_array_equal(full.station_ids, np.repeat(np.arange(4), 4))
    np.testing.assert_allclose(station_positions(full), STATIONS_BY_HAND, atol=1e-9)


def test_a_scan_that_cannot_be_placed_is_a_bad_input(tmp_path):
    (tmp_path / "plain.txt").write_text("1 2 3\n")
    project = tmp_path / "p.project.json"
    project.write_text('{"scans": [{"path": "plain.txt"}]}')
    with pytest.raises(occlusion.InputError, match="cannot be placed"):
        occlusion.read_cloud(str(project))
