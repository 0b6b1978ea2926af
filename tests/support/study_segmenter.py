"""A stand-in segmenter for the study's tests, good and misbehaving.

    python3 study_segmenter.py MODE INPUT OUTPUT

INPUT is the scanned PLY the study writes (binary little-endian or ascii,
x y z, maybe colours, the ground truth's label, `comment class ID NAME` lines).
OUTPUT gets, by its extension, a binary PLY (x y z as read, a label per point
and the input's class comments, so that labels are mapped by name), a text
cloud (.txt: x y z label, evaluation ids) or a bare label file (.labels: one
evaluation id per line). Evaluation ids are table 3.1's.

MODE: truth (the ground truth, points in reverse order), wall (evaluation id
0 everywhere), drop_last, extra_point (the first point twice), nan_point
(the ground truth and one more point at (NaN, NaN, NaN)), moved_point
(the first point 1 mm along x), binary_failure (binary bytes on stderr, exit
5), and two that write a bare label file whatever OUTPUT's extension:
labels_in_order (the ground truth) and off_by_one (the ground truth one line
late: the last point's label first). Only the standard library.

    python3 study_segmenter.py serve MODE STARTS [MISBEHAVIOUR RUN_TEXT]

is the same as a persistent worker (segmenter "worker: ..."): it appends a
line to STARTS when it starts, then reads "INPUT<TAB>OUTPUT" lines on stdin,
answers "ok" for each, and exits at the end of stdin. MISBEHAVIOUR, for an
input path containing RUN_TEXT: die (exit 9 without answering), hang (no
answer), refuse (answers "cannot segment this"), close_stdout (closes its
stdout and sleeps for an hour), flood (writes "x" on stdout without end or
line break, keeping the count of bytes written in STARTS.flooded), trickle
(one "." on stdout every millisecond, without end or line break) or
flood_then_hang (flood in the worker's first start, no answer in the next).
The last four first append the worker's process id to STARTS.pid, so that a
test can check that the study stopped it.
"""

import math
import os
import struct
import sys
import time

# Table 3.1's evaluation ids of S3DIS's classes (docs/metrics.md).
EVALUATION_IDS = {
    "ceiling": 1, "floor": 1, "wall": 0, "beam": 20, "column": 26,
    "window": 8, "door": 7, "table": 6, "chair": 4, "sofa": 5,
    "bookcase": 9, "board": 21, "clutter": 25, "stairs": 25,
}
PLY_TYPES = {
    "char": "b", "int8": "b", "uchar": "B", "uint8": "B",
    "short": "h", "int16": "h", "ushort": "H", "uint16": "H",
    "int": "i", "int32": "i", "uint": "I", "uint32": "I",
    "float": "f", "float32": "f", "double": "d", "float64": "d",
}


def read_ply(path):
    """(x, y, z, label) per point, the type of x y z, the class comments."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    binary = "format binary_little_endian 1.0" in header
    count = 0
    names, types = [], []
    comments = [line for line in header if line.startswith("comment class ")]
    for line in header:
        words = line.split()
        if words[:2] == ["element", "vertex"]:
            count = int(words[2])
        elif words[:1] == ["property"]:
            types.append(PLY_TYPES[words[1]])
            names.append(words[2])
    label = next(i for i, n in enumerate(names) if n.endswith("label"))
    if binary:
        record = struct.Struct("<" + "".join(types))
        rows = [record.unpack_from(data, end + i * record.size)
                for i in range(count)]
    else:
        lines = data[end:].decode("ascii").split("\n")[:count]
        rows = [tuple(float(w) for w in line.split()) for line in lines]
    points = [(r[0], r[1], r[2], int(r[label])) for r in rows]
    return points, types[0], comments


def class_names(comments):
    names = {}
    for line in comments:
        _, _, number, name = line.split(maxsplit=3)
        names[int(number)] = name
    return names


def write_ply(path, points, coordinate_type, comments):
    record = struct.Struct("<" + coordinate_type * 3 + "i")
    kind = "double" if coordinate_type == "d" else "float"
    header = ["ply", "format binary_little_endian 1.0", *comments,
              f"element vertex {len(points)}",
              f"property {kind} x", f"property {kind} y", f"property {kind} z",
              "property int label", "end_header"]
    with open(path, "wb") as f:
        f.write(("\n".join(header) + "\n").encode("ascii"))
        for point in points:
            f.write(record.pack(*point))


def serve(mode, starts, misbehaviour=None, run_text=None):
    with open(starts, "a") as f:
        f.write("started\n")
    for line in sys.stdin:
        input_path, output_path = line.rstrip("\n").split("\t")
        if run_text is not None and run_text in input_path:
            if misbehaviour == "die":
                print("worker dying", file=sys.stderr)
                sys.exit(9)
            if misbehaviour == "hang":
                time.sleep(3600)
            if misbehaviour == "refuse":
                print("cannot segment this", flush=True)
                continue
            if misbehaviour in ("close_stdout", "flood", "trickle",
                                "flood_then_hang"):
                misbehave(misbehaviour, starts)
        segment(mode, input_path, output_path)
        print("ok", flush=True)


def misbehave(misbehaviour, starts):
    """Never returns: the study must end it."""
    with open(starts, encoding="ascii") as f:
        first_start = f.read().count("\n") == 1
    with open(starts + ".pid", "a") as f:
        f.write(f"{os.getpid()}\n")
    sys.stdout.flush()
    if misbehaviour == "flood_then_hang":
        misbehaviour = "flood" if first_start else "hang"
    if misbehaviour == "close_stdout":
        os.close(1)
        time.sleep(3600)
    elif misbehaviour == "flood":
        chunk = b"x" * 65536
        written = 0
        with open(starts + ".flooded", "w") as count:
            while True:
                written += os.write(1, chunk)
                count.seek(0)
                count.write(f"{written:20d}\n")
                count.flush()
    elif misbehaviour == "hang":
        time.sleep(3600)
    else:
        while True:
            os.write(1, b".")
            time.sleep(0.001)


def main():
    if sys.argv[1] == "serve":
        serve(*sys.argv[2:])
        return
    segment(*sys.argv[1:4])


def segment(mode, input_path, output_path):
    if mode == "binary_failure":
        # Invalid UTF-8, NUL, an escape sequence, a C1 byte, a cut sequence.
        sys.stderr.buffer.write(b"model crashed \xff\xfe\x00\x1b[31m\x9b\xc3(")
        sys.exit(5)
    points, coordinate_type, comments = read_ply(input_path)
    names = class_names(comments)

    def evaluation_id(label):
        return EVALUATION_IDS[names[label]] if names else label

    bare_labels = output_path.endswith(".labels")
    if mode == "truth":
        points = points[::-1]
    elif mode == "wall":
        points = [(x, y, z, 0) for x, y, z, _ in points]
        names, comments = {}, []
    elif mode == "labels_in_order":
        bare_labels = True
    elif mode == "off_by_one":
        bare_labels = True
        labels = [p[3] for p in points]
        labels = labels[-1:] + labels[:-1]
        points = [(x, y, z, v) for (x, y, z, _), v in zip(points, labels)]
    elif mode == "drop_last":
        points = points[:-1]
    elif mode == "extra_point":
        points = points[:1] + points
    elif mode == "nan_point":
        points = points + [(math.nan, math.nan, math.nan, points[0][3])]
    elif mode == "moved_point":
        x, y, z, label = points[0]
        points[0] = (x + 0.001, y, z, label)
    else:
        sys.exit(f"unknown mode {mode}")
    if bare_labels:
        with open(output_path, "w") as f:
            f.writelines(f"{evaluation_id(p[3])}\n" for p in points)
    elif output_path.endswith(".txt"):
        # repr of a float32 read back: the shortest digits that round-trip.
        with open(output_path, "w") as f:
            f.writelines(f"{x!r} {y!r} {z!r} {evaluation_id(v)}\n"
                         for x, y, z, v in points)
    else:
        write_ply(output_path, points, coordinate_type, comments)


if __name__ == "__main__":
    main()
