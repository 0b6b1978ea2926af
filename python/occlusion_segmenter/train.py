"""Seeded training on generated rooms (generate_s3dis_room --dataset).

The same seed, settings, rooms and torch build give the same checkpoint:
every random draw comes from the seed, and torch runs deterministically on
the threads it is given.
"""

import os
import time

import numpy as np
import torch

from . import CLASSES
from .checkpoint import save
from .features import BLOCK, INPUT_CHANNELS, block_relative, point_features
from .rooms import read_room, room_dirs

# The real settings: about 14 minutes on 2 quiet cores (docs/study.md).
DEFAULTS = {"steps": 3000, "batch": 8, "points": 2048, "width": 64,
            "learning_rate": 0.002, "seed": 0, "scans": 0}
# How training scans are made (scans > 0): the `occlusion` program, the
# study config whose laser_* keys describe the sensor, and the cache folder
# ("": DATASET/scans).
SCAN_SETTINGS = {"occlusion": "occlusion", "scan_config": "", "scan_cache": ""}


def _room_samples(paths, settings, dataset, log):
    """Each complete room and, with settings["scans"] = N, N virtual scans of
    it (scans.py): (positions, features, labels) each."""
    rooms, scans = [], []
    options = None
    if settings["scans"] > 0:
        from .scans import sensor_options
        if not settings["scan_config"]:
            raise ValueError("--scans needs --scan-config: the study config "
                             "whose laser_* keys describe the sensor")
        options = sensor_options(settings["scan_config"])
    cache = settings["scan_cache"] or os.path.join(dataset, "scans")
    for path in paths:
        positions, colours, labels = read_room(path)
        rooms.append((positions, point_features(positions, colours), labels))
        if options is None:
            continue
        from .scans import room_scans
        for p, c, lab in room_scans(path, (positions, colours, labels),
                                    settings["scans"], settings["seed"],
                                    settings["occlusion"], options, cache):
            scans.append((p, point_features(p, c), lab))
        log(f"{path}: {settings['scans']} scans, "
            f"{sum(len(s[0]) for s in scans[-settings['scans']:])} points")
    return rooms + scans


def _class_weights(rooms):
    counts = np.zeros(len(CLASSES))
    for _, _, labels in rooms:
        counts += np.bincount(labels, minlength=len(CLASSES))
    frequency = counts / counts.sum()
    # Rare classes (columns, beams, boards) weigh more, but not by their
    # full rarity, which would make the network call everything a column.
    weights = np.where(counts > 0, 1.0 / np.sqrt(frequency + 1e-6), 0.0)
    return torch.tensor(weights / weights[counts > 0].mean(),
                        dtype=torch.float32)


def _batch(rooms, rng, batch, points):
    inputs, targets = [], []
    for _ in range(batch):
        positions, features, labels = rooms[rng.integers(len(rooms))]
        centre = positions[rng.integers(len(positions)), :2]
        inside = np.all(np.abs(positions[:, :2] - centre) <= BLOCK / 2, 1)
        members = np.flatnonzero(inside)
        members = rng.choice(members, points, replace=len(members) < points)
        inputs.append(block_relative(features, positions, members).T)
        targets.append(labels[members])
    return (torch.from_numpy(np.stack(inputs)),
            torch.from_numpy(np.stack(targets)))


def train(dataset, checkpoint, settings, log=print):
    settings = {**DEFAULTS, **SCAN_SETTINGS, **settings}
    torch.manual_seed(settings["seed"])
    torch.use_deterministic_algorithms(True)
    rng = np.random.default_rng(settings["seed"])
    paths = room_dirs(dataset)
    started = time.monotonic()
    rooms = _room_samples(paths, settings, dataset, log)
    from .model import PointNetSeg
    model = PointNetSeg(INPUT_CHANNELS, len(CLASSES), settings["width"])
    optimiser = torch.optim.Adam(model.parameters(),
                                 lr=settings["learning_rate"])
    schedule = torch.optim.lr_scheduler.CosineAnnealingLR(
        optimiser, max(1, settings["steps"]))
    loss_of = torch.nn.CrossEntropyLoss(weight=_class_weights(rooms))
    history = []
    model.train()
    for step in range(settings["steps"]):
        inputs, targets = _batch(rooms, rng, settings["batch"],
                                 settings["points"])
        optimiser.zero_grad()
        loss = loss_of(model(inputs), targets)
        loss.backward()
        optimiser.step()
        schedule.step()
        history.append(float(loss))
        if step % 50 == 0 or step + 1 == settings["steps"]:
            log(f"step {step + 1}/{settings['steps']} loss {float(loss):.4f} "
                f"({time.monotonic() - started:.0f} s)")
    settings["in_channels"] = INPUT_CHANNELS
    settings["rooms"] = [p[len(dataset):].lstrip("/") for p in paths]
    save(checkpoint, model, settings, history)
    return model
