"""Per-point input features, the same in training and inference.

Colours alone do not tell the classes apart (the generator draws them from
palettes shared by several classes), so the network also sees where a point
is in the room (height, distance to the room's box) and the shape of its
neighbourhood: the normal and flatness of the points in its voxel.
"""

import numpy as np

VOXEL = 0.15      # metres: the neighbourhood of the local shape features
BLOCK = 2.0       # metres: the side of the square columns the network sees
NUM_FEATURES = 15  # point_features
INPUT_CHANNELS = NUM_FEATURES + 2  # and block_relative's x, y


def _voxel_shape(positions):
    """Per point: |normal| (3), and the voxel's eigenvalue ratios (2)."""
    keys = np.floor(positions / VOXEL).astype(np.int64)
    _, inverse, counts = np.unique(keys, axis=0, return_inverse=True,
                                   return_counts=True)
    inverse = inverse.reshape(-1)
    voxels = len(counts)
    mean = np.stack([np.bincount(inverse, positions[:, a], voxels)
                     for a in range(3)], 1) / counts[:, None]
    centred = positions - mean[inverse]
    cov = np.empty((voxels, 3, 3))
    for a in range(3):
        for b in range(a, 3):
            s = np.bincount(inverse, centred[:, a] * centred[:, b], voxels)
            cov[:, a, b] = cov[:, b, a] = s / counts
    values, vectors = np.linalg.eigh(cov + 1e-9 * np.eye(3))
    normal = np.abs(vectors[:, :, 0])
    total = values.sum(1) + 1e-12
    flat = values[:, 0] / total          # ~0 on a plane
    linear = values[:, 1] / total        # ~0 on an edge or a pole
    shape = np.concatenate([normal, flat[:, None], linear[:, None]], 1)
    return shape[inverse]


def point_features(positions, colours):
    """float32 (N, NUM_FEATURES): positions in metres, colours 0-255."""
    positions = np.asarray(positions, dtype=np.float64)
    low = positions.min(0)
    high = positions.max(0)
    local = positions - low
    size = np.maximum(high - low, 1e-6)
    to_side = np.minimum(local[:, :2], (high - positions)[:, :2])
    features = np.concatenate([
        local[:, 2:3],                       # height above the lowest point
        (high[2] - positions[:, 2:3]),       # depth below the highest point
        local / size,                        # where in the room's box
        to_side,                             # how far from the box's sides
        np.asarray(colours, dtype=np.float64) / 255.0 - 0.5,
        _voxel_shape(positions),
    ], 1)
    return features.astype(np.float32)


def block_ids(positions):
    """The square column (BLOCK metres) each point falls in, as one id."""
    cells = np.floor((positions[:, :2] - positions[:, :2].min(0)) / BLOCK)
    cells = cells.astype(np.int64)
    return cells[:, 0] * (cells[:, 1].max() + 1) + cells[:, 1]


def block_relative(features, positions, members):
    """The block's points' features with x, y relative to the block centre."""
    xy = positions[members, :2]
    centre = (xy.min(0) + xy.max(0)) / 2
    relative = ((xy - centre) / BLOCK).astype(np.float32)
    return np.concatenate([features[members], relative], 1)
