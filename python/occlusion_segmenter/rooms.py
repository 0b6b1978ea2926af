"""Labelled rooms in the S3DIS layout.

AREA/<room>/Annotations/<class>_<k>.txt, x y z r g b per line.
"""

import os

import numpy as np

from . import CLASSES


def _read_xyzrgb(path):
    with open(path, "rb") as stream:
        values = np.array(stream.read().split(), dtype=np.float64)
    if values.size % 6:
        raise ValueError(f"{path}: {values.size} numbers is not a whole "
                         "number of 'x y z r g b' lines")
    return values.reshape(-1, 6)


def read_room(room_dir):
    """(positions float64 (N, 3), colours float32 (N, 3), labels int64 (N,)),
    labels as indices into CLASSES."""
    annotations = os.path.join(room_dir, "Annotations")
    parts, labels = [], []
    for name in sorted(os.listdir(annotations)):
        if not name.endswith(".txt"):
            continue
        class_name = name.rsplit("_", 1)[0]
        if class_name not in CLASSES:
            raise ValueError(f"{annotations}/{name}: '{class_name}' is not "
                             "one of the 13 S3DIS classes")
        values = _read_xyzrgb(os.path.join(annotations, name))
        parts.append(values)
        labels.append(np.full(len(values), CLASSES.index(class_name)))
    if not parts:
        raise ValueError(f"{annotations}: no annotation files")
    values = np.concatenate(parts)
    return (values[:, :3], values[:, 3:].astype(np.float32),
            np.concatenate(labels).astype(np.int64))


def room_dirs(dataset):
    """Every room folder under DATASET/Area_*/, sorted."""
    rooms = []
    for area in sorted(os.listdir(dataset)):
        area_dir = os.path.join(dataset, area)
        if not (area.startswith("Area_") and os.path.isdir(area_dir)):
            continue
        for room in sorted(os.listdir(area_dir)):
            if os.path.isdir(os.path.join(area_dir, room, "Annotations")):
                rooms.append(os.path.join(area_dir, room))
    if not rooms:
        raise ValueError(f"{dataset}: no Area_*/<room>/Annotations folders")
    return rooms
