"""The learned reference segmenter (python/occlusion_segmenter): a tiny
model trained for seconds on generated rooms is the same for the same seed,
labels the same input the same way every time, and serves the study as a
persistent worker whose model is loaded once per study."""

import os
import pathlib
import subprocess
import sys

import numpy as np
import pytest

torch = pytest.importorskip("torch")

ROOT = pathlib.Path(__file__).resolve().parents[2]
BUILD = pathlib.Path(os.environ.get("OCCLUSION_BUILD_DIR", ROOT / "build"))
sys.path.insert(0, str(ROOT / "python"))

from occlusion_segmenter import CLASSES, SEED_TABLE  # noqa: E402
from occlusion_segmenter.checkpoint import load  # noqa: E402
from occlusion_segmenter.ply import read_vertices  # noqa: E402
from occlusion_segmenter.predict import predict  # noqa: E402
from occlusion_segmenter.rooms import read_room, room_dirs  # noqa: E402
from occlusion_segmenter.train import train  # noqa: E402

TINY = {"steps": 6, "batch": 2, "points": 256, "width": 8,
        "learning_rate": 0.01}


def generate(out, rooms, seed):
    tool = BUILD / "generate_s3dis_room"
    if not tool.exists():
        pytest.skip(f"{tool} is not built")
    subprocess.run([str(tool), "--dataset", str(out), "--rooms", str(rooms),
                    "--seed", str(seed), "--spacing", "0.15"], check=True,
                   stderr=subprocess.DEVNULL)
    return out


@pytest.fixture(scope="module")
def dataset(tmp_path_factory):
    torch.set_num_threads(1)
    return generate(tmp_path_factory.mktemp("rooms"), 2, 3)


def test_the_same_seed_gives_the_same_checkpoint(dataset, tmp_path):
    quiet = dict(log=lambda text: None)
    train(str(dataset), str(tmp_path / "a.pt"), {**TINY, "seed": 1}, **quiet)
    train(str(dataset), str(tmp_path / "b.pt"), {**TINY, "seed": 1}, **quiet)
    train(str(dataset), str(tmp_path / "c.pt"), {**TINY, "seed": 2}, **quiet)
    a = torch.load(tmp_path / "a.pt")["state_dict"]
    b = torch.load(tmp_path / "b.pt")["state_dict"]
    c = torch.load(tmp_path / "c.pt")["state_dict"]
    assert a.keys() == b.keys()
    assert all(torch.equal(a[k], b[k]) for k in a)
    assert not all(torch.equal(a[k], c[k]) for k in a)
    saved = torch.load(tmp_path / "a.pt")
    assert saved["classes"] == list(CLASSES)
    assert len(saved["history"]) == TINY["steps"]
    assert saved["settings"]["rooms"] == [
        os.path.relpath(room, dataset) for room in room_dirs(str(dataset))]


def test_inference_is_deterministic_and_labels_every_point(dataset,
                                                           tmp_path):
    train(str(dataset), str(tmp_path / "m.pt"), {**TINY, "seed": 1},
          log=lambda text: None)
    model, _ = load(str(tmp_path / "m.pt"))
    positions, colours, truth = read_room(room_dirs(str(dataset))[0])
    first = predict(model, positions, colours)
    again = predict(load(str(tmp_path / "m.pt"))[0], positions, colours)
    assert first.shape == truth.shape
    assert np.array_equal(first, again)
    assert first.min() >= 0 and first.max() < len(CLASSES)


def test_a_checkpoint_of_something_else_is_refused(tmp_path):
    torch.save({"state_dict": {}}, tmp_path / "other.pt")
    with pytest.raises(ValueError, match="not an occlusion-segmenter"):
        load(str(tmp_path / "other.pt"))


def test_the_study_loads_the_model_once_and_scores(dataset, tmp_path):
    occlusion = BUILD / "occlusion"
    if not occlusion.exists():
        pytest.skip(f"{occlusion} is not built")
    checkpoint = tmp_path / "m.pt"
    train(str(dataset), str(checkpoint), {**TINY, "seed": 1},
          log=lambda text: None)
    room = room_dirs(str(dataset))[0]
    worker = (f"worker: PYTHONPATH={ROOT / 'python'} {sys.executable} -m "
              f"occlusion_segmenter serve {checkpoint}")
    result = subprocess.run(
        [str(occlusion), "study", "--scene", room,
         "--pattern", "7", "--pattern", "1",
         "--num-rays-per-vp", "300", "--point-radius", "0.2",
         "--segmenter", worker, "--out", str(tmp_path / "study")],
        capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    assert result.stderr.count("occlusion_segmenter: loaded") == 1
    csv = (tmp_path / "study" / "study.csv").read_text().splitlines()
    header = csv[0].split(",")
    rows = [dict(zip(header, line.split(","))) for line in csv[1:]]
    assert len(rows) == 2
    for row in rows:
        assert row["status"] == "ok", row["failure"]
        assert 0.0 <= float(row["miou"]) <= 1.0
    # The worker's prediction: every scanned point, labelled in the study's
    # default mapping's ids.
    runs = tmp_path / "study" / "runs"
    for prediction in runs.glob("*.prediction.ply"):
        scan = read_vertices(str(prediction).replace(".prediction.", ".scan."))
        labels = read_vertices(str(prediction))["label"]
        assert len(labels) == len(scan)
        assert set(labels) <= set(SEED_TABLE.values())
