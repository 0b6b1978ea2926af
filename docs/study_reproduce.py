"""Recompute the experiment's table (OUT/experiment.md, docs/study.md) from
the four studies' study.csv alone, with Python's standard library:

    python3 docs/study_reproduce.py out/experiment

Each figure is the tool's (src/analysis/clustered_inference.cpp), redone:
- the runs: rows whose status is ok with an occlusion_level and an miou,
  less a run that places the same viewpoints as an earlier run of its scene;
- the within-scene slope: occlusion level and mIoU centred on their scene's
  means, least squares through the origin;
- its 95 % interval: 2000 bootstrap draws of whole scenes with replacement,
  from the tool's generator (xoshiro256** seeded by SplitMix64, seed 1,
  stream 2), the percentile interval of the defined draws;
- a difference: two studies' runs paired by (scene, configuration), every
  draw taking the same scenes for both, the interval of second - first.
Sums run in the tool's order, so the figures agree to the last digit.
"""

import csv
import math
import os
import sys

# Which study is which cell, and which pairs are compared: as
# experiment_summary.py (the tool's side of the table) names them.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "src", "scripts"))
from experiment_summary import CELLS, DIFFERENCES, MEASURE  # noqa: E402

MASK = (1 << 64) - 1
SEED, STREAM, RESAMPLES, MIN_SCENES = 1, 2, 2000, 5


def mix64(x):
    x = (x + 0x9e3779b97f4a7c15) & MASK
    x = ((x ^ (x >> 30)) * 0xbf58476d1ce4e5b9) & MASK
    x = ((x ^ (x >> 27)) * 0x94d049bb133111eb) & MASK
    return x ^ (x >> 31)


class Rng:
    """core/random.hpp's generator."""

    def __init__(self, seed, stream):
        state = mix64(seed) ^ mix64((stream * 0xd1342543de82ef95 + 1) & MASK)
        self.s = []
        for _ in range(4):
            state = mix64(state)
            self.s.append(state)

    def next(self):
        s = self.s
        times5 = (s[1] * 5) & MASK
        result = (((times5 << 7) | (times5 >> 57)) & MASK) * 9 & MASK
        t = (s[1] << 17) & MASK
        s[2] ^= s[0]
        s[3] ^= s[1]
        s[1] ^= s[2]
        s[0] ^= s[3]
        s[2] ^= t
        s[3] = ((s[3] << 45) | (s[3] >> 19)) & MASK
        return result

    def below(self, n):
        uniform = (self.next() >> 11) * 2.0 ** -53
        return min(n - 1, int(uniform * n))


def within_scene_slope(groups, x, y):
    """groups: each scene's run indices, in order; None where x does not
    vary within any scene."""
    sxx = sxy = scale = 0.0
    count = 0
    for runs in groups:
        mean_x = mean_y = 0.0
        for r in runs:
            mean_x += x[r]
            mean_y += y[r]
        mean_x /= len(runs)
        mean_y /= len(runs)
        for r in runs:
            dx = x[r] - mean_x
            sxx += dx * dx
            sxy += dx * (y[r] - mean_y)
            scale = max(scale, abs(x[r]))
        count += len(runs)
    noise = 1e-12 * scale
    return None if sxx <= noise * noise * count else sxy / sxx


def percentile(values, share):
    at = share * (len(values) - 1)
    below = math.floor(at)
    above = min(len(values) - 1, below + 1)
    return values[below] + (at - below) * (values[above] - values[below])


def interval(draws, undefined, scenes):
    if scenes < MIN_SCENES or undefined > 0.05 * RESAMPLES or not draws:
        return None
    draws = sorted(draws)
    return percentile(draws, 0.025), percentile(draws, 0.975)


def bootstrap(scene, series):
    """series: [(x, y), ...] over the same runs. Per series the slope and its
    interval; with two, the difference second - first and its interval."""
    groups = {}
    for run, s in enumerate(scene):
        groups.setdefault(s, []).append(run)
    groups = list(groups.values())  # scenes in order of first appearance
    values = [within_scene_slope(groups, x, y) for x, y in series]
    rng = Rng(SEED, STREAM)
    draws = [[] for _ in range(len(series) + 1)]
    undefined = [0] * (len(series) + 1)
    for _ in range(RESAMPLES):
        # Each drawn scene is a scene of its own (one drawn twice is two).
        flat, regrouped = [], []
        for _ in range(len(groups)):
            runs = groups[rng.below(len(groups))]
            regrouped.append(list(range(len(flat), len(flat) + len(runs))))
            flat.extend(runs)
        slopes = []
        for k, (x, y) in enumerate(series):
            slope = within_scene_slope(regrouped, [x[r] for r in flat],
                                       [y[r] for r in flat])
            slopes.append(slope)
            if slope is None:
                undefined[k] += 1
            else:
                draws[k].append(slope)
        if len(series) == 2:
            if None in slopes:
                undefined[2] += 1
            else:
                draws[2].append(slopes[1] - slopes[0])
    result = [(v, interval(d, u, len(groups)))
              for v, d, u in zip(values, draws, undefined)]
    if len(series) == 2:
        difference = None if None in values else values[1] - values[0]
        result.append((difference, interval(draws[2], undefined[2],
                                            len(groups))))
    return result


def number(cell):
    try:
        value = float(cell)
    except ValueError:
        return None
    return value if math.isfinite(value) else None


def measured_runs(path, measure=MEASURE):
    """{(scene, configuration): (x, mIoU)} in the CSV's order (Python dicts
    keep it), as the tool takes them."""
    with open(path, newline="") as stream:
        rows = list(csv.DictReader(stream))
    rows.sort(key=lambda row: int(row["run"]))
    seen, runs, miou = set(), {}, []
    for row in rows:
        if row["status"] == "failed":
            continue
        points = sorted(row["viewpoint_positions"].split(";"))
        key = row["scene"] + "\n" + "".join(p + ";" for p in points)
        repeated = key in seen
        seen.add(key)
        x, y = number(row[measure]), number(row["miou"])
        if x is not None and y is not None and not repeated:
            runs[(row["scene"], row["configuration"])] = (x, y)
    for row in rows:
        if number(row["miou"]) is not None:
            miou.append(number(row["miou"]))
    return runs, miou


def scene_numbers(keys):
    numbers = {}
    return [numbers.setdefault(scene, len(numbers)) for scene, _ in keys]


def slope_of(runs):
    keys = list(runs)
    x = [runs[k][0] for k in keys]
    y = [runs[k][1] for k in keys]
    return bootstrap(scene_numbers(keys), [(x, y)])[0], len(keys), \
        len(set(s for s, _ in keys))


def paired(there, here):
    keys = [k for k in here if k in there]
    series = [([there[k][0] for k in keys], [there[k][1] for k in keys]),
              ([here[k][0] for k in keys], [here[k][1] for k in keys])]
    return bootstrap(scene_numbers(keys), series), len(keys), \
        len(set(s for s, _ in keys))


def text(estimate):
    value, bounds = estimate
    if value is None:
        return "–"
    out = f"{value:.3f}"
    if bounds:
        out += f" [{bounds[0]:.3f}, {bounds[1]:.3f}]"
    return out


def table(out):
    studies = {name: measured_runs(os.path.join(out, name, "study.csv"))
               for name, _, _ in CELLS}
    lines = ["| model trained on | scans | runs | scenes | mean mIoU | "
             "within-scene slope [95 %] |", "|---|---|---:|---:|---:|---|"]
    for name, model, scans in CELLS:
        runs, miou = studies[name]
        estimate, n, scenes = slope_of(runs)
        lines.append(f"| {model} | {scans} | {n} | {scenes} | "
                     f"{sum(miou) / len(miou):.3f} | {text(estimate)} |")
    lines += ["", "| difference of slopes | paired runs | scenes | "
              "slope there | slope here | difference [95 %] |",
              "|---|---:|---:|---|---|---|"]
    for here, there, label in DIFFERENCES:
        (first, second, difference), n, scenes = paired(studies[there][0],
                                                        studies[here][0])
        lines.append(f"| {label} | {n} | {scenes} | {text(first)} | "
                     f"{text(second)} | {text(difference)} |")
    return "\n".join(lines)


if __name__ == "__main__":
    print(table(sys.argv[1]))
