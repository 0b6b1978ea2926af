"""Reading the study's scanned clouds and writing predictions (PLY).

Only what the study writes is read: one `vertex` element of scalar
properties, ascii or binary little/big endian. Anything else is refused
with the file and the reason.
"""

import numpy as np

_TYPES = {"char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1",
          "short": "i2", "int16": "i2", "ushort": "u2", "uint16": "u2",
          "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4",
          "float": "f4", "float32": "f4", "double": "f8", "float64": "f8"}


class PlyError(ValueError):
    pass


def read_vertices(path):
    """The vertex element as a numpy structured array."""
    with open(path, "rb") as stream:
        data = stream.read()
    end = data.find(b"end_header")
    if not data.startswith(b"ply") or end < 0:
        raise PlyError(f"{path}: not a PLY file (no 'ply' magic or "
                       "end_header)")
    body = data.index(b"\n", end) + 1
    header = data[:body].decode("ascii", "replace").splitlines()
    fmt = None
    elements = []  # (name, count, [(property, dtype)])
    for number, line in enumerate(header, 1):
        words = line.split()
        if not words or words[0] in ("ply", "comment", "obj_info",
                                     "end_header"):
            continue
        if words[0] == "format":
            fmt = words[1]
        elif words[0] == "element":
            elements.append((words[1], int(words[2]), []))
        elif words[0] == "property":
            if words[1] == "list" or words[1] not in _TYPES or not elements:
                raise PlyError(f"{path}: header line {number}: unsupported "
                               f"property '{line}'")
            elements[-1][2].append((words[2], _TYPES[words[1]]))
    if not elements or elements[0][0] != "vertex":
        raise PlyError(f"{path}: the first element is not 'vertex'")
    _, count, properties = elements[0]
    if fmt == "ascii":
        text = data[body:].decode("ascii").split("\n")[:count]
        dtype = np.dtype(properties)
        values = np.loadtxt(text, ndmin=2) if count else np.zeros((0, 0))
        out = np.empty(count, dtype=dtype)
        for column, (name, _) in enumerate(properties):
            out[name] = values[:, column]
        return out
    order = {"binary_little_endian": "<", "binary_big_endian": ">"}.get(fmt)
    if order is None:
        raise PlyError(f"{path}: unsupported PLY format '{fmt}'")
    dtype = np.dtype([(name, order + kind) for name, kind in properties])
    if len(data) - body < count * dtype.itemsize:
        raise PlyError(f"{path}: {count} vertices need "
                       f"{count * dtype.itemsize} bytes after the header, "
                       f"the file has {len(data) - body}")
    return np.frombuffer(data, dtype=dtype, count=count, offset=body)


def write_labelled(path, vertices, labels):
    """Every point with x y z as read (their own type) and its label."""
    fields = [(axis, vertices.dtype[axis].newbyteorder("<"))
              for axis in "xyz"] + [("label", "<i4")]
    out = np.empty(len(vertices), dtype=fields)
    for axis in "xyz":
        out[axis] = vertices[axis]
    out["label"] = labels
    header = ["ply", "format binary_little_endian 1.0",
              f"element vertex {len(out)}"]
    names = {"f4": "float", "f8": "double"}
    for axis in "xyz":
        header.append(f"property {names[out.dtype[axis].str[1:]]} {axis}")
    header += ["property int label", "end_header", ""]
    temporary = path + ".partial"
    with open(temporary, "wb") as stream:
        stream.write("\n".join(header).encode("ascii"))
        stream.write(out.tobytes())
    import os
    os.replace(temporary, path)


def read_class_names(path):
    """The class names the header's `comment class ID NAME` lines give, in
    id order (occlusion writes them for labelled clouds)."""
    with open(path, "rb") as stream:
        data = stream.read(1 << 20)
    end = data.find(b"end_header")
    names = {}
    for line in data[:max(end, 0)].decode("ascii", "replace").splitlines():
        words = line.split(None, 3)
        if len(words) == 4 and words[:2] == ["comment", "class"]:
            names[int(words[2])] = words[3]
    if sorted(names) != list(range(len(names))):
        raise PlyError(f"{path}: class comments do not number 0, 1, 2, ...")
    return [names[i] for i in range(len(names))]
