"""Labels for a whole cloud: every point, each in exactly one block."""

import numpy as np
import torch

from .features import block_ids, block_relative, point_features


def predict(model, positions, colours):
    """Class indices (into CLASSES), one per point, deterministic."""
    positions = np.asarray(positions, dtype=np.float64)
    labels = np.zeros(len(positions), dtype=np.int64)
    if len(positions) == 0:
        return labels
    features = point_features(positions, colours)
    blocks = block_ids(positions)
    order = np.argsort(blocks, kind="stable")
    starts = np.flatnonzero(np.r_[True, np.diff(blocks[order]) != 0])
    ends = np.r_[starts[1:], len(order)]
    with torch.no_grad():
        for start, end in zip(starts, ends):
            members = order[start:end]
            inputs = block_relative(features, positions, members)
            logits = model(torch.from_numpy(inputs.T.copy())[None])
            labels[members] = logits[0].argmax(0).numpy()
    return labels


def confusion(truth, predicted, classes):
    return np.bincount(truth * classes + predicted,
                       minlength=classes * classes).reshape(classes, classes)


def iou_per_class(matrix):
    """IoU per class; NaN for a class neither present nor predicted."""
    hits = np.diag(matrix).astype(np.float64)
    union = matrix.sum(0) + matrix.sum(1) - hits
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(union > 0, hits / union, np.nan)
