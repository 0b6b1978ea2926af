"""docs/study_reproduce.py recomputes the experiment's table from the four
studies' study.csv alone: on four small studies made here (six scenes, a
failed run, a run that repeats another's viewpoints, a run one study lacks),
its table is the one experiment_summary.py writes from the tool's own
study.json, and its slopes, differences and intervals are the tool's to
the digits study.json holds."""

import os
import pathlib
import json
import random
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
BUILD = pathlib.Path(os.environ.get("OCCLUSION_BUILD_DIR", ROOT / "build"))
CLI = pathlib.Path(os.environ.get("OCCLUSION_CLI", BUILD / "occlusion"))
sys.path.insert(0, str(ROOT / "docs"))
sys.path.insert(0, str(ROOT / "src" / "scripts"))

import study_reproduce  # noqa: E402

# A study.csv's columns (the default mapping's), as the tool writes them.
HEADER = (ROOT / "tests/support/study_before_overrides/study.csv").read_text(
).splitlines()[0].split(",")
VIEWPOINTS = {"one": "1 1 1.5", "two": "1 1 1.5;3 2 1.5",
              "three": "1 1 1.5;3 2 1.5;2 4 1.5",
              "again": "3 2 1.5;1 1 1.5"}  # "two"'s viewpoints again


def write_study(path, slope_per_scene, seed, drop=None):
    rng = random.Random(seed)
    lines = [",".join(HEADER)]
    run = 0
    for s in range(6):
        for configuration in VIEWPOINTS:
            row = dict.fromkeys(HEADER, "")
            level = rng.uniform(0.05, 0.4)
            miou = 0.7 - slope_per_scene[s] * level + rng.gauss(0, 0.01)
            failed = s == 2 and configuration == "three"
            row.update(run=str(run), scene=f"room_{s}",
                       configuration=configuration,
                       status="failed" if failed else "ok",
                       viewpoints=str(VIEWPOINTS[configuration].count(";")
                                      + 1),
                       viewpoint_positions=VIEWPOINTS[configuration],
                       points="1000", scanned_points="800",
                       visible_fraction=f"{1 - level:.10g}",
                       occlusion_level=f"{level:.10g}",
                       segmenter="worker: test", mean_over="support",
                       fingerprint="0")
            if failed:
                row["failure"] = "the segmenter crashed"
            else:
                row["miou"] = f"{miou:.10g}"
            run += 1
            if (s, configuration) == drop:
                continue
            lines.append(",".join(row[c] for c in HEADER))
    path.write_text("\n".join(lines) + "\n")


def merge(out, name, compare_with=()):
    command = [str(CLI), "study", "merge", str(out / name),
               str(out / "in" / f"{name}.csv"), "-q"]
    for other in compare_with:
        command += ["--compare-with", str(out / other)]
    done = subprocess.run(command, stdout=subprocess.DEVNULL,
                          stderr=subprocess.PIPE, text=True)
    # Status 1: the failed run each study holds (the tool says so).
    assert done.returncode == 1, done.stderr


def test_the_script_reproduces_the_tools_table(tmp_path):
    if not CLI.exists():
        pytest.skip(f"{CLI} is not built")
    (tmp_path / "in").mkdir()
    slopes = [0.2, 0.5, 0.3, 0.6, 0.1, 0.4]
    write_study(tmp_path / "in/complete_ideal.csv", slopes, 1)
    write_study(tmp_path / "in/scans_ideal.csv", [s * 0.5 for s in slopes], 2,
                drop=(4, "one"))
    write_study(tmp_path / "in/complete_laser.csv", [s + 0.2 for s in slopes],
                3)
    write_study(tmp_path / "in/scans_laser.csv", [s * 0.7 for s in slopes], 4)
    merge(tmp_path, "complete_ideal")
    merge(tmp_path, "scans_ideal", ["complete_ideal"])
    merge(tmp_path, "complete_laser", ["complete_ideal"])
    merge(tmp_path, "scans_laser", ["scans_ideal", "complete_laser"])

    tool = subprocess.run(
        [sys.executable, str(ROOT / "src/scripts/experiment_summary.py"),
         str(tmp_path)], check=True, capture_output=True, text=True).stdout
    script = subprocess.run(
        [sys.executable, str(ROOT / "docs/study_reproduce.py"), str(tmp_path)],
        check=True, capture_output=True, text=True).stdout
    assert script == tool
    assert "[" in tool  # six scenes: every figure has its interval

    # To the last bit: the paired comparison of scans_ideal with
    # complete_ideal (one run unpaired), as study.json holds it.
    report = json.loads((tmp_path / "scans_ideal/study.json").read_text())
    entry = next(c for c in report["comparisons"]
                 if c["measure"] == "occlusion_level")
    there, _ = study_reproduce.measured_runs(
        tmp_path / "complete_ideal/study.csv")
    here, _ = study_reproduce.measured_runs(tmp_path / "scans_ideal/study.csv")
    (first, second, difference), runs, scenes = study_reproduce.paired(there,
                                                                       here)
    # 6 scenes x 4 configurations, less the failed run (scene 2), the
    # repeated viewpoints ("again", every scene) and the dropped run.
    assert (runs, scenes) == (6 * 3 - 1 - 1, 6) == (entry["runs"],
                                                    entry["scenes"])
    # (study.json holds 15 significant digits.)
    def same(mine, theirs):
        return mine == pytest.approx(theirs, rel=1e-13, abs=1e-15)

    for mine, theirs in ((first, entry["slope_there"]),
                         (second, entry["slope_here"]),
                         (difference, entry["difference"])):
        assert same(mine[0], theirs["value"])
        assert same(list(mine[1]), theirs["interval95"])
    # And each study's own slope and interval, as its correlations give them.
    own = next(c for c in report["correlations"]
               if c["measure"] == "occlusion_level")
    (value, bounds), n, _ = study_reproduce.slope_of(here)
    assert n == own["n"]
    assert same(value, own["inference"]["within_scene_slope"]["value"])
    assert same(list(bounds),
                own["inference"]["within_scene_slope"]["interval95"])


def test_the_docs_table_reproduces_from_the_runs_tables():
    # files/study_issue43 holds the four study.csv of the run docs/study.md
    # reports: the script's table from them is the doc's, line for line.
    table = study_reproduce.table(str(ROOT / "files/study_issue43"))
    doc = (ROOT / "docs/study.md").read_text()
    assert table in doc
