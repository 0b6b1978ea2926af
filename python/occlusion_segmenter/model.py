"""The network: PointNet's segmentation form, small enough for a CPU.

Each point's features go through a shared MLP; the block's max over its
points is the context every point's head sees beside its own features.
"""

import torch
from torch import nn


def _mlp(sizes):
    layers = []
    for a, b in zip(sizes[:-1], sizes[1:]):
        layers += [nn.Conv1d(a, b, 1), nn.BatchNorm1d(b), nn.ReLU()]
    return nn.Sequential(*layers)


class PointNetSeg(nn.Module):
    def __init__(self, in_channels, num_classes, width=64):
        super().__init__()
        self.local = _mlp([in_channels, width, width])
        self.deep = _mlp([width, 2 * width, 4 * width])
        self.head = nn.Sequential(
            _mlp([width + 4 * width, 2 * width, width]),
            nn.Conv1d(width, num_classes, 1))

    def forward(self, points):
        """points (B, C, N) -> logits (B, classes, N)."""
        local = self.local(points)
        context = self.deep(local).max(2, keepdim=True).values
        context = context.expand(-1, -1, points.shape[2])
        return self.head(torch.cat([local, context], 1))
