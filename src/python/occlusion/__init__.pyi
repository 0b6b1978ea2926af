# Type stubs for the occlusion package (the extension occlusion._occlusion).
# Shapes are in the docstrings: N points, M faces, V vertices, R rays.
import os
from typing import Any, Callable, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

_Path = Union[str, os.PathLike[str]]
_Points = npt.ArrayLike  # (N, 3) float32 or float64 (read in place), other numbers converted
_Progress = Optional[Callable[[str, float], None]]

NO_PRIMITIVE: int

class UsageError(ValueError):
    """A bad argument: unknown key, wrong type or value out of range. The message names it."""

class InputError(OSError, ValueError):
    """A file that cannot be read or does not say what it should."""

    path: str
    filename: str
    line: int
    reason: str

class OutputError(OSError):
    """An output that could not be written."""

    path: str
    filename: str
    reason: str

class TriangleScene:
    """A triangle mesh for ray queries; primitive ids are face indices."""

    def __init__(
        self,
        vertices: _Points,
        faces: npt.ArrayLike,
        *,
        octree_resolution: float = 0.0,
        enable_acceleration: bool = True,
    ) -> None: ...
    def intersect(
        self,
        origins: _Points,
        directions: _Points,
        t_min: Union[float, npt.ArrayLike] = 0.0,
        t_max: Union[float, npt.ArrayLike] = ...,
        *,
        threads: int = 0,
    ) -> Tuple[npt.NDArray[np.float32], npt.NDArray[np.uint32]]:
        """Closest hit per ray: t float32 (R,) (inf: none), id uint32 (R,) (NO_PRIMITIVE: none)."""
    def occluded(
        self,
        origins: _Points,
        directions: _Points,
        t_min: Union[float, npt.ArrayLike] = 0.0,
        t_max: Union[float, npt.ArrayLike] = ...,
        *,
        threads: int = 0,
    ) -> npt.NDArray[np.bool_]:
        """Whether each ray hits anything in [t_min, t_max]: bool (R,)."""
    def __len__(self) -> int: ...
    @property
    def bounds(self) -> Tuple[npt.NDArray[np.float32], npt.NDArray[np.float32]]: ...
    @property
    def stats(self) -> dict[str, int]: ...

class SphereScene:
    """A point cloud for ray queries, one sphere of `radius` per point; ids are point indices."""

    def __init__(
        self,
        points: _Points,
        radius: float,
        *,
        octree_resolution: float = 0.0,
        enable_acceleration: bool = True,
    ) -> None: ...
    def intersect(
        self,
        origins: _Points,
        directions: _Points,
        t_min: Union[float, npt.ArrayLike] = 0.0,
        t_max: Union[float, npt.ArrayLike] = ...,
        *,
        threads: int = 0,
    ) -> Tuple[npt.NDArray[np.float32], npt.NDArray[np.uint32]]: ...
    def occluded(
        self,
        origins: _Points,
        directions: _Points,
        t_min: Union[float, npt.ArrayLike] = 0.0,
        t_max: Union[float, npt.ArrayLike] = ...,
        *,
        threads: int = 0,
    ) -> npt.NDArray[np.bool_]: ...
    def __len__(self) -> int: ...
    @property
    def bounds(self) -> Tuple[npt.NDArray[np.float32], npt.NDArray[np.float32]]: ...
    @property
    def stats(self) -> dict[str, int]: ...

class DiscScene:
    """A point cloud for ray queries as the jobs trace it: one disc per point; ids are point indices."""

    def __init__(
        self,
        points: _Points,
        normals: Optional[_Points] = None,
        radii: Union[float, npt.ArrayLike, None] = None,
        *,
        disc_coverage: float = 0.99,
        normal_neighbours: int = 16,
        octree_resolution: float = 0.0,
        enable_acceleration: bool = True,
    ) -> None: ...
    def intersect(
        self,
        origins: _Points,
        directions: _Points,
        t_min: Union[float, npt.ArrayLike] = 0.0,
        t_max: Union[float, npt.ArrayLike] = ...,
        *,
        threads: int = 0,
    ) -> Tuple[npt.NDArray[np.float32], npt.NDArray[np.uint32]]: ...
    def occluded(
        self,
        origins: _Points,
        directions: _Points,
        t_min: Union[float, npt.ArrayLike] = 0.0,
        t_max: Union[float, npt.ArrayLike] = ...,
        *,
        threads: int = 0,
    ) -> npt.NDArray[np.bool_]: ...
    def __len__(self) -> int: ...
    @property
    def normals(self) -> npt.NDArray[np.float32]: ...
    @property
    def radii(self) -> npt.NDArray[np.float32]: ...
    @property
    def bounds(self) -> Tuple[npt.NDArray[np.float32], npt.NDArray[np.float32]]: ...
    @property
    def stats(self) -> dict[str, int]: ...

class Cloud:
    """A point cloud read by read_cloud."""

    positions: npt.NDArray[np.float32]  # (N, 3), relative to shift
    shift: tuple[float, float, float]  # the global shift: a point in the file is position + shift
    colours: Optional[npt.NDArray[np.uint8]]  # (N, 3)
    labels: Optional[npt.NDArray[np.int32]]  # (N,), -1 = unlabelled
    instances: Optional[npt.NDArray[np.int32]]  # (N,)
    intensities: Optional[npt.NDArray[np.float32]]  # (N,)
    station_ids: Optional[npt.NDArray[np.int32]]  # (N,), index into stations
    # {"name", "origin" (relative to shift), "orientation" (w, x, y, z), "width", "height"}
    stations: list[dict[str, Any]]
    # A single-view frame's camera: {"origin", "orientation", "width", "height"}, else None
    sensor: Optional[dict[str, Any]]
    pixels: Optional[npt.NDArray[np.uint32]]  # (N,), row * width + column in sensor's grid
    class_names: list[str]
    fields: dict[str, npt.NDArray[Any]]  # float32 or int32 (N,)
    dropped_nan: int
    skipped_lines: int
    rooms: list[str]
    warnings: list[str]  # what reading found, one sentence each (far depths of a depth frame)
    def __len__(self) -> int: ...

class Mesh:
    """A triangle mesh read by read_mesh."""

    vertices: npt.NDArray[np.float64]  # (V, 3)
    faces: npt.NDArray[np.uint32]  # (M, 3)
    face_group: npt.NDArray[np.uint32]  # (M,)
    group_names: list[str]
    degenerate_faces: int  # zero-area triangles the reader skipped
    def __len__(self) -> int: ...

def read_cloud(path: _Path, *, skip_bad_lines: bool = False) -> Cloud: ...
def write_cloud(
    path: _Path,
    positions: _Points,
    *,
    colours: Optional[npt.ArrayLike] = None,
    labels: Optional[npt.ArrayLike] = None,
    instances: Optional[npt.ArrayLike] = None,
    class_names: Optional[Sequence[str]] = None,
    intensities: Optional[npt.ArrayLike] = None,
    station_ids: Optional[npt.ArrayLike] = None,
    stations: Optional[Sequence[dict[str, Any]]] = None,
    fields: dict[str, npt.ArrayLike] = ...,
    format: Optional[str] = None,
    shift: tuple[float, float, float] = (0.0, 0.0, 0.0),
) -> None: ...
def read_mesh(path: _Path) -> Mesh: ...
def write_obj(
    path: _Path,
    vertices: _Points,
    faces: npt.ArrayLike,
    *,
    face_group: Optional[npt.ArrayLike] = None,
    group_names: Optional[Sequence[str]] = None,
    comment: str = "",
) -> None: ...
def write_mesh_ply(
    path: _Path,
    vertices: _Points,
    faces: npt.ArrayLike,
    face_values: npt.ArrayLike,
    value_name: str = "visible_fraction",
    *,
    face_group: Optional[npt.ArrayLike] = None,
    group_names: Optional[Sequence[str]] = None,
) -> None: ...
def read_labels(path: _Path) -> npt.NDArray[np.int32]: ...
def write_labels(path: _Path, labels: npt.ArrayLike) -> None: ...
def is_label_file(path: _Path) -> bool: ...
def read_polygons(path: _Path) -> list[npt.NDArray[np.float64]]: ...
def write_polygons(path: _Path, polygons: Sequence[_Points]) -> None: ...
def read_csv(path: _Path) -> Tuple[list[str], list[list[str]]]: ...
def write_csv(path: _Path, columns: Sequence[str], rows: Sequence[Sequence[str]]) -> None: ...
def s3dis_class_names() -> list[str]: ...

class Result:
    """A job's JSON report (as the CLI prints it with --json) and its arrays; both read as attributes."""

    report: dict[str, Any]
    arrays: dict[str, Any]
    def __getattr__(self, name: str) -> Any: ...

# Jobs. Keyword arguments are the job's config keys (README, `occlusion --help`).
def mesh_occlusion(
    source: Union[_Path, Tuple[_Points, npt.ArrayLike]], *, progress: _Progress = None, **keys: Any
) -> Result: ...
def cloud_occlusion(
    source: Union[_Path, _Points, Cloud],
    *,
    labels: Optional[npt.ArrayLike] = None,
    class_names: Optional[Sequence[str]] = None,
    progress: _Progress = None,
    **keys: Any,
) -> Result: ...
def scan(
    source: Union[_Path, _Points, Cloud],
    *,
    labels: Optional[npt.ArrayLike] = None,
    class_names: Optional[Sequence[str]] = None,
    progress: _Progress = None,
    **keys: Any,
) -> Result: ...
def plan(
    source: Union[_Path, Tuple[_Points, npt.ArrayLike], _Points, Cloud],
    *,
    labels: Optional[npt.ArrayLike] = None,
    class_names: Optional[Sequence[str]] = None,
    progress: _Progress = None,
    **keys: Any,
) -> Result: ...
def region_growing_occlusion(source: _Path, *, progress: _Progress = None, **keys: Any) -> Result: ...
def evaluate(*, progress: _Progress = None, **keys: Any) -> Result: ...
def reconstruct(source: _Path, *, progress: _Progress = None, **keys: Any) -> Result: ...
def study(*, progress: _Progress = None, **keys: Any) -> Result: ...
def register(source: _Path, *, progress: _Progress = None, **keys: Any) -> Result: ...
