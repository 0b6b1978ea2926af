"""experiment_summary.py OUT: the experiment's table (experiment.md) from
its four studies' study.json, as the tool computed every figure: each
cell's within-scene slope of mIoU on the occlusion level with its 95 %
scene-clustered interval, and the paired differences (model trained on scans
- on complete rooms; laser scans - ideal scans) with theirs. Nothing is
computed here but the formatting; docs/study_reproduce.py recomputes the
figures from the study.csv files.
"""

import json
import os
import sys

CELLS = [("complete_ideal", "complete rooms", "ideal"),
         ("scans_ideal", "rooms + scans", "ideal"),
         ("complete_laser", "complete rooms", "laser"),
         ("scans_laser", "rooms + scans", "laser")]
# (study, the study it is compared with, what the difference measures)
DIFFERENCES = [("scans_ideal", "complete_ideal",
                "model: scans − complete, ideal scans"),
               ("scans_laser", "complete_laser",
                "model: scans − complete, laser scans"),
               ("complete_laser", "complete_ideal",
                "scans: laser − ideal, model complete"),
               ("scans_laser", "scans_ideal",
                "scans: laser − ideal, model scans")]
MEASURE = "occlusion_level"


def interval(estimate):
    value = estimate["value"]
    if value is None:
        return "–"
    text = f"{value:.3f}"
    if estimate["interval95"]:
        lo, hi = estimate["interval95"]
        text += f" [{lo:.3f}, {hi:.3f}]"
    return text


def main(out):
    studies = {}
    for name, _, _ in CELLS:
        with open(os.path.join(out, name, "study.json")) as stream:
            studies[name] = json.load(stream)
    lines = ["| model trained on | scans | runs | scenes | mean mIoU | "
             "within-scene slope [95 %] |", "|---|---|---:|---:|---:|---|"]
    for name, model, scans in CELLS:
        study = studies[name]
        entry = next(c for c in study["correlations"]
                     if c["measure"] == MEASURE)
        miou = [r["miou"] for r in study["rows"] if r["miou"] is not None]
        lines.append(f"| {model} | {scans} | {entry['n']} | "
                     f"{entry['scenes']} | {sum(miou) / len(miou):.3f} | "
                     f"{interval(entry['inference']['within_scene_slope'])} |")
    lines += ["", "| difference of slopes | paired runs | scenes | "
              "slope there | slope here | difference [95 %] |",
              "|---|---:|---:|---|---|---|"]
    for here, there, label in DIFFERENCES:
        folder = os.path.join(out, there)
        entry = next(c for c in studies[here]["comparisons"]
                     if c["measure"] == MEASURE and
                     os.path.realpath(c["study"]) == os.path.realpath(folder))
        lines.append(f"| {label} | {entry['runs']} | {entry['scenes']} | "
                     f"{interval(entry['slope_there'])} | "
                     f"{interval(entry['slope_here'])} | "
                     f"{interval(entry['difference'])} |")
    print("\n".join(lines))


if __name__ == "__main__":
    main(sys.argv[1])
