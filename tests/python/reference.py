"""Brute-force ray queries in float64 numpy: the references the scenes are
checked against. Each returns, per ray, the closest hit (t, id; inf and -1 for
none) and whether the ray lies within `margin` of a boundary case (an edge, a
tangent, an interval end, a tie), where float32 and float64 may rightly
disagree; tests compare only the other rays and require most rays to count."""

import numpy as np


def _closest(t, hit, ambiguous_each, margin):
    t = np.where(hit, t, np.inf)
    ids = np.argmin(t, axis=1)
    best = t[np.arange(len(t)), ids]
    second = np.partition(t, 1, axis=1)[:, 1] if t.shape[1] > 1 else np.full(len(t), np.inf)
    with np.errstate(invalid="ignore"):  # inf - inf where a ray hits nothing
        tie = np.isfinite(best) & (second - best <= margin * np.maximum(1.0, np.abs(best)))
    ambiguous = ambiguous_each.any(axis=1) | tie
    return best, np.where(np.isfinite(best), ids, -1), ambiguous


def triangles(vertices, faces, origins, directions, t_min, t_max, margin=1e-4):
    v0, v1, v2 = (vertices[faces[:, k]][None, :, :] for k in range(3))
    o = origins[:, None, :]
    d = directions[:, None, :]
    e1, e2 = v1 - v0, v2 - v0
    p = np.cross(d, e2)
    det = np.sum(e1 * p, axis=2)
    safe = np.where(np.abs(det) > 1e-12, det, 1.0)
    s = o - v0
    u = np.sum(s * p, axis=2) / safe
    q = np.cross(s, e1)
    v = np.sum(d * q, axis=2) / safe
    t = np.sum(e2 * q, axis=2) / safe
    lo, hi = np.asarray(t_min)[..., None], np.asarray(t_max)[..., None]
    inside = (u >= 0) & (v >= 0) & (u + v <= 1)
    hit = (np.abs(det) > 1e-12) & inside & (t >= lo) & (t <= hi)
    edge = np.minimum(np.minimum(np.abs(u), np.abs(v)), np.abs(1 - u - v)) < margin
    near_end = (np.abs(t - lo) < margin) | (np.abs(t - hi) < margin)
    grazing = np.abs(det) < margin * np.linalg.norm(d, axis=2) * np.linalg.norm(np.cross(e1, e2), axis=2)
    ambiguous_each = (edge & (t >= lo - margin) & (t <= hi + margin)) | (near_end & inside) | grazing
    return _closest(t, hit, ambiguous_each, margin)


def spheres(points, radius, origins, directions, t_min, t_max, margin=1e-4):
    o = origins[:, None, :]
    d = directions[:, None, :]
    offset = o - points[None, :, :]
    dd = np.sum(d * d, axis=2)
    t_c = -np.sum(offset * d, axis=2) / dd
    closest = offset + t_c[..., None] * d
    disc = radius * radius - np.sum(closest * closest, axis=2)
    half = np.sqrt(np.maximum(disc, 0.0)) / np.sqrt(dd)
    lo, hi = np.asarray(t_min)[..., None], np.asarray(t_max)[..., None]
    near, far = t_c - half, t_c + half
    t = np.where(near >= lo, near, far)
    hit = (disc >= 0) & (t >= lo) & (t <= hi)
    tangent = np.abs(disc) < margin * radius * radius
    ends = np.minimum.reduce([np.abs(near - lo), np.abs(near - hi), np.abs(far - lo), np.abs(far - hi)])
    ambiguous_each = tangent | ((disc >= 0) & (ends < margin))
    return _closest(t, hit, ambiguous_each, margin)
