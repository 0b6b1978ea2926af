"""occlusion.plan: the stations, the coverage curve and the per-target array
of a scan plan, from arrays and from a file, checked against what the scene
makes certain."""

import _thread
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


def room(lo, hi):
    """A box seen from inside: 8 vertices, 12 triangles facing in."""
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    vertices = np.array(
        [[x, y, z] for z in (z0, z1) for y in (y0, y1) for x in (x0, x1)], dtype=np.float64
    )
    quads = [
        (0, 1, 3, 2),  # floor, normal +z
        (4, 6, 7, 5),  # ceiling, -z
        (0, 4, 5, 1),  # y = y0, +y
        (2, 3, 7, 6),  # y = y1, -y
        (0, 2, 6, 4),  # x = x0, +x
        (1, 5, 7, 3),  # x = x1, -x
    ]
    faces = []
    for a, b, c, d in quads:
        faces += [(a, b, c), (a, c, d)]
    return vertices, np.array(faces, dtype=np.uint32)


def test_an_empty_room_needs_one_station_and_every_sample_is_covered_by_it():
    vertices, faces = room((0, 0, 0), (4, 3, 2.5))
    result = occlusion.plan((vertices, faces), samples_per_unit_area=20, seed=1)
    assert result.stations.shape == (1, 3)
    assert result.coverage_curve.shape == (1,)
    assert result.coverage_curve[0] == pytest.approx(1.0)
    assert result.covered_by.dtype == np.int32
    assert result.covered_by.shape == (result.report["target_count"],)
    assert (result.covered_by == 1).all()
    assert result.target_reached
    # The station stands inside the room, at the height asked above its floor.
    x, y, z = result.stations[0]
    assert 0 < x < 4 and 0 < y < 3 and z == pytest.approx(1.5)
    assert result.candidates.shape[1] == 3
    assert result.gain_left.shape == (len(result.candidates),)


def test_the_best_k_of_two_rooms_puts_one_station_in_each():
    # Two 4 x 4 rooms side by side, joined by nothing: each station sees one.
    a_vertices, a_faces = room((0, 0, 0), (4, 4, 3))
    b_vertices, b_faces = room((6, 0, 0), (10, 4, 3))
    vertices = np.vstack([a_vertices, b_vertices])
    faces = np.vstack([a_faces, b_faces + len(a_vertices)])
    result = occlusion.plan((vertices, faces), stations=2, samples_per_unit_area=10)
    xs = sorted(result.stations[:, 0])
    assert xs[0] < 4 < 6 < xs[1]
    assert result.coverage_curve[0] == pytest.approx(0.5, abs=0.01)
    assert result.coverage_curve[1] == pytest.approx(1.0)
    assert set(np.unique(result.covered_by)) == {1, 2}
    assert "1 - 1/e" in result.guarantee


def test_keys_are_checked_as_everywhere(tmp_path):
    vertices, faces = room((0, 0, 0), (4, 3, 2.5))
    with pytest.raises(ValueError, match="target_coverage"):
        occlusion.plan((vertices, faces), target_coverage=1.5)
    with pytest.raises(ValueError, match="spacing"):
        occlusion.plan((vertices, faces), spacing=-1)


def test_an_empty_scene_in_memory_is_a_usage_error_as_for_the_other_jobs():
    # It was FileNotFoundError, naming "<arrays>" as a file that does not exist.
    with pytest.raises(occlusion.UsageError):
        occlusion.cloud_occlusion(np.zeros((0, 3)))
    with pytest.raises(occlusion.UsageError, match="no points"):
        occlusion.plan(np.zeros((0, 3)))
    with pytest.raises(occlusion.UsageError, match="no faces"):
        occlusion.plan((np.zeros((3, 3)), np.zeros((0, 3), dtype=np.int64)))


def test_a_file_gives_what_the_cli_gives(tmp_path):
    if not CLI.exists():
        pytest.skip("the CLI is not built")
    vertices, faces = room((0, 0, 0), (4, 3, 2.5))
    path = tmp_path / "box.obj"
    lines = [f"v {x} {y} {z}" for x, y, z in vertices]
    lines += [f"f {a + 1} {b + 1} {c + 1}" for a, b, c in faces]
    path.write_text("\n".join(lines) + "\n")
    result = occlusion.plan(str(path), samples_per_unit_area=20)
    run = subprocess.run(
        [str(CLI), "plan", str(path), "--samples-per-unit-area", "20", "--json"],
        capture_output=True, text=True, timeout=300,
    )
    assert run.returncode == 0, run.stderr
    cli = json.loads(run.stdout)
    assert [s["candidate"] for s in cli["stations"]] == [
        s["candidate"] for s in result.report["stations"]
    ]
    assert cli["coverage"] == pytest.approx(result.coverage)


def test_ctrl_c_stops_the_tracing_within_a_small_share_of_it():
    # One candidate (spacing wider than the room) to 590,000 samples: Ctrl-C,
    # which Python sees when a progress report returns, waited for the whole
    # candidate's rays (5-14 s late on larger scenes; issue 44, 2.10). Here it
    # comes in the first report of some tracing done; nothing is traced after.
    vertices, faces = room((0, 0, 0), (4, 3, 2.5))
    tracing = []

    def ctrl_c(stage, fraction):
        if stage == "tracing" and fraction > 0:
            tracing.append(fraction)
            if len(tracing) == 1:
                _thread.interrupt_main()

    with pytest.raises(KeyboardInterrupt):
        occlusion.plan((vertices, faces), samples_per_unit_area=10_000, spacing=10, threads=2,
                       progress=ctrl_c)
    assert tracing and tracing[0] < 0.2
    assert len(tracing) == 1


def test_a_target_out_of_reach_says_what_was_asked_reachable_and_chosen():
    # A room and, beside it, a closed crate (its faces out) that no station
    # can see: 59 of the 65 m^2 can be covered, 90.8 %, short of 99 %.
    r_vertices, r_faces = room((0, 0, 0), (4, 3, 2.5))
    c_vertices, c_faces = room((5, 0, 0), (6, 1, 1))
    vertices = np.vstack([r_vertices, c_vertices])
    faces = np.vstack([r_faces, c_faces[:, ::-1] + len(r_vertices)])
    result = occlusion.plan((vertices, faces), target_coverage=0.99, samples_per_unit_area=20)
    report = result.report
    assert not report["target_reached"]
    assert report["reachable_coverage"] == pytest.approx(59 / 65, abs=0.02)
    # The most that can be reached is what the stations aim at and cover.
    assert report["aimed_coverage"] == pytest.approx(report["reachable_coverage"])
    assert report["coverage"] == pytest.approx(report["reachable_coverage"])
    reach = report["out_of_reach"]
    assert reach["chosen"] == "most"
    assert reach["share_coverage"] == pytest.approx(0.99 * report["reachable_coverage"])
    assert 1 <= reach["share_reached_by_first_new_stations"] <= len(result.stations)
    share = occlusion.plan(
        (vertices, faces), target_coverage=0.99, samples_per_unit_area=20, out_of_reach="share"
    )
    assert share.report["aimed_coverage"] == pytest.approx(reach["share_coverage"])
    assert share.report["out_of_reach"]["chosen"] == "share"
