"""Readers and writers: round trips through every format, dtypes and shapes,
real public files the repository carries (files/), and the error classification."""

import pathlib

import numpy as np
import pytest

import occlusion

ROOT = pathlib.Path(__file__).resolve().parents[2]
PCL_DATA = ROOT / "files" / "pcl"


def sample_cloud(rng, count=50):
    return dict(
        positions=rng.uniform(-5, 5, (count, 3)).astype(np.float32),
        colours=rng.integers(0, 256, (count, 3)).astype(np.uint8),
        labels=rng.integers(-1, 3, count).astype(np.int32),
        instances=rng.integers(-1, 7, count).astype(np.int32),
    )


@pytest.mark.parametrize(
    "name,fmt",
    [
        ("c.pcd", None),
        ("c.pcd", "pcd_binary"),
        ("c.pcd", "pcd_ascii"),
        ("c.ply", None),
        ("c.ply", "ply_ascii"),
    ],
)
def test_cloud_round_trip(tmp_path, name, fmt):
    rng = np.random.default_rng(7)
    data = sample_cloud(rng)
    intensity = rng.uniform(0, 1, 50).astype(np.float32)
    ring = rng.integers(0, 16, 50)
    path = str(tmp_path / name)
    occlusion.write_cloud(
        path,
        data["positions"],
        colours=data["colours"],
        labels=data["labels"],
        instances=data["instances"],
        class_names=["wall", "floor", "chair"],
        intensities=intensity,
        fields={"ring": ring},
        format=fmt,
    )
    cloud = occlusion.read_cloud(path)
    assert len(cloud) == 50
    assert cloud.positions.dtype == np.float32 and cloud.positions.shape == (50, 3)
    assert cloud.colours.dtype == np.uint8 and cloud.colours.shape == (50, 3)
    assert cloud.labels.dtype == np.int32 and cloud.instances.dtype == np.int32
    np.testing.assert_array_equal(cloud.positions, data["positions"])
    np.testing.assert_array_equal(cloud.colours, data["colours"])
    np.testing.assert_array_equal(cloud.labels, data["labels"])
    np.testing.assert_array_equal(cloud.instances, data["instances"])
    assert cloud.class_names == ["wall", "floor", "chair"]
    assert cloud.intensities.dtype == np.float32
    np.testing.assert_array_equal(cloud.intensities, intensity)
    assert cloud.station_ids is None and cloud.stations == []
    assert "intensity" not in cloud.fields
    assert cloud.fields["ring"].dtype == np.int32
    np.testing.assert_array_equal(cloud.fields["ring"], ring)


def test_cloud_without_attributes_has_none(tmp_path):
    path = tmp_path / "c.txt"
    path.write_text("0 0 0\n1 2 3\nnan 0 0\n")
    cloud = occlusion.read_cloud(str(path))
    np.testing.assert_array_equal(cloud.positions, [[0, 0, 0], [1, 2, 3]])
    assert cloud.colours is None and cloud.labels is None and cloud.instances is None
    assert cloud.dropped_nan == 1 and cloud.fields == {}


def test_skip_bad_lines(tmp_path):
    path = tmp_path / "c.txt"
    path.write_text("0 0 0\n1 x 3\n2 2 2\n")
    with pytest.raises(occlusion.InputError) as error:
        occlusion.read_cloud(str(path))
    assert error.value.line == 2
    cloud = occlusion.read_cloud(str(path), skip_bad_lines=True)
    assert len(cloud) == 2 and cloud.skipped_lines == 1


def test_real_scan_reads():
    cloud = occlusion.read_cloud(str(PCL_DATA / "room_scan1.pcd"))
    assert cloud.positions.shape[1] == 3 and len(cloud) > 1000
    assert np.isfinite(cloud.positions).all()


def test_e57_reads():
    cloud = occlusion.read_cloud(str(ROOT / "files" / "e57" / "ColouredCubeFloat.e57"))
    assert len(cloud) == 7680  # the scan's recordCount
    assert np.abs(cloud.positions).max() <= 0.5 + 1e-6  # its cartesianBounds
    assert cloud.colours.shape == (7680, 3)
    with pytest.raises(occlusion.InputError, match="page 0 .* is corrupt"):
        occlusion.read_cloud(str(ROOT / "files" / "e57" / "bad-crc.e57"))


def test_read_cloud_docstring_names_every_file_kind_it_reads():
    doc = occlusion.read_cloud.__doc__
    for path in (PCL_DATA / "room_scan1.pcd", ROOT / "files" / "e57" / "ColouredCubeFloat.e57",
                 ROOT / "files" / "las" / "simple.las"):
        assert len(occlusion.read_cloud(str(path))) > 0
        assert path.suffix in doc, f"{path.suffix} is read but not named: {doc}"


def write_depth_png(path, depth):
    """A 16-bit greyscale PNG of `depth` (uint16, rows x columns)."""
    import struct
    import zlib

    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data
                + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))

    rows, columns = depth.shape
    raw = b"".join(b"\x00" + row.astype(">u2").tobytes() for row in depth)
    path.write_bytes(b"\x89PNG\r\n\x1a\n"
                     + chunk(b"IHDR", struct.pack(">IIBBBBB", columns, rows, 16, 0, 0, 0, 0))
                     + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def test_a_depth_frame_beyond_indoor_range_reads_with_a_warning(tmp_path):
    # A wall 3.6 m away in millimetres, then with SUN RGB-D's bits rotated
    # by three places (28.8 m): only the second is beyond what sensors measure.
    wall = np.full((12, 16), 3600, dtype=np.uint16)
    rotated = ((wall.astype(np.uint32) << 3) | (wall >> 13)).astype(np.uint16)
    for name, depth in (("wall", wall), ("rotated", rotated)):
        write_depth_png(tmp_path / f"{name}.png", depth)
        (tmp_path / f"{name}.frame.json").write_text(
            f'{{"depth": "{name}.png", "depth_scale": 1000, '
            '"intrinsics": {"fx": 10, "fy": 10, "cx": 7.5, "cy": 5.5}}')
    assert occlusion.read_cloud(str(tmp_path / "wall.frame.json")).warnings == []
    warnings = occlusion.read_cloud(str(tmp_path / "rotated.frame.json")).warnings
    assert len(warnings) == 1
    assert "192 of 192 depths" in warnings[0] and "SUN RGB-D" in warnings[0]


def test_las_sample_reads_with_its_classes():
    cloud = occlusion.read_cloud(str(ROOT / "files" / "las" / "simple.las"))
    assert len(cloud) == 1065
    assert cloud.class_names == ["never_classified", "unclassified", "ground"]
    assert np.bincount(cloud.labels).tolist() == [0, 789, 276]
    # The header's x range, in the file's frame (State Plane feet).
    x = cloud.positions[:, 0].astype(np.float64) + cloud.shift[0]
    assert abs(x.min() - 635619.85) < 0.005 and abs(x.max() - 638982.55) < 0.005


def test_laz_is_refused_saying_how_to_decompress():
    with pytest.raises(occlusion.InputError, match="LASzip-compressed") as error:
        occlusion.read_cloud(str(ROOT / "files" / "las" / "simple.laz"))
    assert "pdal translate" in str(error.value)


def test_mesh_round_trip(tmp_path):
    vertices = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1]], dtype=np.float64) / 3
    faces = np.array([[0, 1, 2], [0, 2, 3], [0, 1, 4]])
    path = str(tmp_path / "m.obj")
    occlusion.write_obj(path, vertices, faces, face_group=[0, 0, 1], group_names=["floor", "wall"])
    mesh = occlusion.read_mesh(path)
    assert mesh.vertices.dtype == np.float64 and mesh.vertices.shape == (5, 3)
    assert mesh.faces.dtype == np.uint32 and mesh.faces.shape == (3, 3)
    np.testing.assert_array_equal(mesh.vertices, vertices)  # shortest round-trip decimals
    np.testing.assert_array_equal(mesh.faces, faces)
    np.testing.assert_array_equal(mesh.face_group, [0, 0, 1])
    assert mesh.group_names == ["floor", "wall"]
    ply = tmp_path / "m.ply"
    occlusion.write_mesh_ply(str(ply), mesh.vertices, mesh.faces, [0.0, 0.5, 1.0])
    assert ply.read_bytes().startswith(b"ply\n")
    with pytest.raises(ValueError, match="face_values"):
        occlusion.write_mesh_ply(str(ply), mesh.vertices, mesh.faces, [0.0, 0.5])


def test_degenerate_faces_are_skipped_and_counted(tmp_path):
    path = tmp_path / "d.obj"
    path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 1 2 4\nf 3 3 1\n")
    mesh = occlusion.read_mesh(str(path))
    assert len(mesh) == 1 and mesh.degenerate_faces == 2


def test_scannet_scene_reads_with_nyu40_names(tmp_path):
    header = (
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "property uchar red\nproperty uchar green\nproperty uchar blue\n{}element face 1\n"
        "property list uchar int vertex_indices\nend_header\n"
    )
    scene = tmp_path / "scene0000_00"
    scene.mkdir()
    (scene / "scene0000_00_vh_clean_2.ply").write_text(
        header.format("") + "0 0 0 10 20 30\n1 0 0 40 50 60\n0 1 0 70 80 90\n3 0 1 2\n"
    )
    (scene / "scene0000_00_vh_clean_2.labels.ply").write_text(
        header.format("property ushort label\n") + "0 0 0 1 1 1 2\n1 0 0 1 1 1 1\n0 1 0 1 1 1 0\n3 0 1 2\n"
    )
    cloud = occlusion.read_cloud(str(scene))
    np.testing.assert_array_equal(cloud.labels, [2, 1, 0])
    np.testing.assert_array_equal(cloud.colours[1], [40, 50, 60])
    assert cloud.class_names[:3] == ["unannotated", "wall", "floor"] and len(cloud.class_names) == 41


def test_cornell_box_reads():
    mesh = occlusion.read_mesh(str(ROOT / "files" / "cornell_box" / "CornellBox-Original.obj"))
    assert mesh.faces.shape[1] == 3 and len(mesh.group_names) > 1
    assert mesh.faces.max() < len(mesh.vertices)


def test_labels_polygons_csv_round_trip(tmp_path):
    labels = np.array([0, 1, 25, -1])
    occlusion.write_labels(str(tmp_path / "p.labels"), labels)
    read = occlusion.read_labels(str(tmp_path / "p.labels"))
    assert read.dtype == np.int32
    np.testing.assert_array_equal(read, labels)
    assert occlusion.is_label_file(str(tmp_path / "p.labels"))

    polygons = [np.array([[0, 0, 0], [1, 0, 0], [1, 0, 1.5]]), np.array([[0, 2, 0], [0, 3, 0], [0, 3, 1], [0, 2, 1]])]
    occlusion.write_polygons(str(tmp_path / "o.txt"), polygons)
    back = occlusion.read_polygons(str(tmp_path / "o.txt"))
    assert len(back) == 2
    for a, b in zip(back, polygons):
        np.testing.assert_array_equal(a, b)

    occlusion.write_csv(str(tmp_path / "t.csv"), ["a", "b"], [["1", "x,y"], ["2", 'q"']])
    assert occlusion.read_csv(str(tmp_path / "t.csv")) == (["a", "b"], [["1", "x,y"], ["2", 'q"']])
    assert occlusion.s3dis_class_names()[0] == "ceiling" and len(occlusion.s3dis_class_names()) == 13


class TestErrors:
    def test_missing_file_is_file_not_found(self, tmp_path):
        missing = str(tmp_path / "nope.ply")
        with pytest.raises(FileNotFoundError) as error:
            occlusion.read_cloud(missing)
        assert error.value.filename == missing
        with pytest.raises(FileNotFoundError):
            occlusion.read_mesh(str(tmp_path / "nope.obj"))

    def test_malformed_file_names_file_and_line(self, tmp_path):
        path = tmp_path / "bad.obj"
        path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n")
        with pytest.raises(occlusion.InputError) as error:
            occlusion.read_mesh(str(path))
        e = error.value
        assert isinstance(e, ValueError) and isinstance(e, OSError)
        assert e.path == str(path) and e.filename == str(path) and e.line == 4
        assert str(e).startswith(f"{path}:4: ")

    def test_unwritable_output(self, tmp_path):
        target = tmp_path / "dir.pcd"
        target.mkdir()
        with pytest.raises(occlusion.OutputError) as error:
            occlusion.write_cloud(str(target / "x" / "c.pcd"), np.zeros((1, 3)))
        assert isinstance(error.value, OSError)

    def test_bad_arrays(self, tmp_path):
        path = str(tmp_path / "c.ply")
        with pytest.raises(ValueError, match="colours"):
            occlusion.write_cloud(path, np.zeros((2, 3)), colours=np.full((2, 3), 300))
        with pytest.raises(ValueError, match="labels"):
            occlusion.write_cloud(path, np.zeros((2, 3)), labels=[-2, 0])
        with pytest.raises(ValueError):
            occlusion.write_cloud(path, np.zeros((2, 3)), labels=[0, 0, 0])
        with pytest.raises(ValueError, match="format"):
            occlusion.write_cloud(path, np.zeros((2, 3)), format="las")
        with pytest.raises(ValueError, match="face_group"):
            occlusion.write_obj(path + ".obj", np.eye(3), [[0, 1, 2]], face_group=[0])
