"""python3 -m occlusion_segmenter COMMAND ...

  train DATASET CHECKPOINT [--steps N --batch B --points P --width W
                            --learning-rate R --seed S --threads T
                            --scans N --scan-config STUDY.json
                            --occlusion PATH --scan-cache DIR]
  infer CHECKPOINT INPUT.ply OUTPUT.ply [--ids seed|s3dis]
  serve CHECKPOINT [--ids seed|s3dis]      the study's persistent worker
  evaluate CHECKPOINT DATASET              mIoU on full rooms

serve loads the model once, then reads one request a line on stdin,
INPUT<TAB>OUTPUT, writes OUTPUT (a PLY of every input point, x y z as read,
and its label) and answers one line on stdout: "ok" or "error: <why>".
Labels are the study's default mapping's ids (the seed's table 3.1) unless
--ids s3dis asks for the 13 classes' indices.
"""

import argparse
import os
import sys
import time

import numpy as np

from . import CLASSES, SEED_TABLE


def _ids(kind):
    if kind == "seed":
        return np.array([SEED_TABLE[name] for name in CLASSES])
    return np.arange(len(CLASSES))


def _segment_file(model, to_ids, input_path, output_path):
    from .ply import read_vertices, write_labelled
    from .predict import predict
    vertices = read_vertices(input_path)
    names = vertices.dtype.names
    for needed in ("x", "y", "z", "red", "green", "blue"):
        if needed not in names:
            raise ValueError(f"{input_path}: no '{needed}' property (the "
                             "segmenter needs x y z and red green blue)")
    positions = np.stack([vertices[a] for a in "xyz"], 1).astype(np.float64)
    colours = np.stack([vertices[c] for c in ("red", "green", "blue")], 1)
    labels = predict(model, positions, colours.astype(np.float32))
    write_labelled(output_path, vertices, to_ids[labels])


def _load(checkpoint, threads):
    import torch
    from .checkpoint import load
    torch.set_num_threads(threads)
    torch.use_deterministic_algorithms(True)
    started = time.monotonic()
    model, _ = load(checkpoint)
    print(f"occlusion_segmenter: loaded {checkpoint} in "
          f"{time.monotonic() - started:.1f} s", file=sys.stderr, flush=True)
    return model


def serve(model, to_ids, requests, answers):
    """One answer line per request line, until stdin closes."""
    for line in requests:
        line = line.rstrip("\n")
        if not line:
            continue
        try:
            input_path, output_path = line.split("\t")
            _segment_file(model, to_ids, input_path, output_path)
            answer = "ok"
        except Exception as error:  # a bad request fails that run only
            answer = "error: " + " ".join(str(error).split())
        answers.write(answer + "\n")
        answers.flush()


def main(argv=None):
    parser = argparse.ArgumentParser(prog="occlusion_segmenter",
                                     description=__doc__.split("\n")[0])
    commands = parser.add_subparsers(dest="command", required=True)
    train_parser = commands.add_parser("train")
    train_parser.add_argument("dataset")
    train_parser.add_argument("checkpoint")
    from .train import DEFAULTS
    for key, value in DEFAULTS.items():
        train_parser.add_argument("--" + key.replace("_", "-"),
                                  type=type(value), default=value)
    train_parser.add_argument("--threads", type=int, default=1)
    from .train import SCAN_SETTINGS
    for key, value in SCAN_SETTINGS.items():
        train_parser.add_argument("--" + key.replace("_", "-"), default=value)
    infer_parser = commands.add_parser("infer")
    infer_parser.add_argument("checkpoint")
    infer_parser.add_argument("input")
    infer_parser.add_argument("output")
    serve_parser = commands.add_parser("serve")
    serve_parser.add_argument("checkpoint")
    for sub in (infer_parser, serve_parser):
        sub.add_argument("--ids", choices=("seed", "s3dis"), default="seed")
        sub.add_argument("--threads", type=int, default=1)
    evaluate_parser = commands.add_parser("evaluate")
    evaluate_parser.add_argument("checkpoint")
    evaluate_parser.add_argument("dataset")
    evaluate_parser.add_argument("--threads", type=int, default=1)
    args = parser.parse_args(argv)

    if args.command == "train":
        import torch
        torch.set_num_threads(args.threads)
        from .train import train
        settings = {key: getattr(args, key)
                    for key in list(DEFAULTS) + list(SCAN_SETTINGS)}
        train(args.dataset, args.checkpoint, settings,
              log=lambda text: print(text, file=sys.stderr, flush=True))
        return 0
    if args.command == "evaluate":
        return _evaluate(_load(args.checkpoint, args.threads), args.dataset)
    model = _load(args.checkpoint, args.threads)
    to_ids = _ids(args.ids)
    if args.command == "infer":
        _segment_file(model, to_ids, args.input, args.output)
        return 0
    # The protocol owns stdout: answers go to a copy of it, and file
    # descriptor 1 becomes stderr, so that nothing else printed (by Python
    # or by torch's C++) can pass for an answer.
    sys.stdout.flush()
    answers = os.fdopen(os.dup(1), "w")
    os.dup2(2, 1)
    sys.stdout = sys.stderr
    serve(model, to_ids, sys.stdin, answers)
    return 0


def _evaluate(model, dataset):
    from .predict import confusion, iou_per_class, predict
    from .rooms import read_room, room_dirs
    total = np.zeros((len(CLASSES), len(CLASSES)), dtype=np.int64)
    for room in room_dirs(dataset):
        positions, colours, labels = read_room(room)
        matrix = confusion(labels, predict(model, positions, colours),
                           len(CLASSES))
        total += matrix
        print(f"{room}: mIoU {np.nanmean(iou_per_class(matrix)):.3f}")
    iou = iou_per_class(total)
    for name, value in zip(CLASSES, iou):
        print(f"  {name:9s} IoU {value:.3f}")
    accuracy = np.trace(total) / total.sum()
    print(f"mIoU {np.nanmean(iou):.3f} over {int(np.sum(~np.isnan(iou)))} "
          f"classes, overall accuracy {accuracy:.3f}, "
          f"{int(total.sum())} points")
    return 0


if __name__ == "__main__":
    sys.exit(main())
