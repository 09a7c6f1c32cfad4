# Type stubs of the `implicitfit` extension module, as python/*.cc bind it (docs/python.md).
# tests/python/test_stubs.py checks that every public name and every signature here matches the
# built module.
from os import PathLike
from typing import Any, Dict, Iterator, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str

_Array = npt.NDArray[np.float64]
_Indices = npt.NDArray[np.int64]
_Points = npt.ArrayLike  # an (N, 3) array (float64 is used without conversion)
_Report = Dict[str, Any]  # the JSON report of the command line, as Python objects
_Path = Union[str, "PathLike[str]"]

class Model:
    """An implicit surface model: f(x) < 0 inside, f > 0 outside, grad f outward."""

    @staticmethod
    def from_json(text: str) -> Model: ...
    @staticmethod
    def load(path: _Path) -> Model: ...
    def to_json(self, indent: int = 2) -> str: ...
    def save(self, path: _Path) -> None: ...
    def evaluate(self, points: _Points) -> _Array:
        """f at each row: an (N,) array."""
    def gradient(self, points: _Points) -> _Array:
        """grad f at each row: an (N, 3) array."""
    @property
    def parameters(self) -> Dict[str, Any]:
        """The parameters by field: floats, or arrays for vectors."""
    @property
    def kind(self) -> str:
        """The root node's type: "sphere", "union", "bernstein_patch", ..."""

class FitResult:
    """The result of fit(), fit_tree(), fit_patch() and fit_patch_mesh(); unpacks as (model, report)."""

    model: Optional[Model]  # None when the fit failed
    success: bool
    inliers: _Indices  # (K,) the points within the final inlier band, ascending
    report: _Report  # the `implicitfit fit --report` JSON
    def __iter__(self) -> Iterator[Any]: ...
    def __len__(self) -> int: ...
    def __getitem__(self, index: int) -> Any: ...

class SampleResult:
    """The result of sample(); unpacks as (points, normals)."""

    points: _Array  # (N, 3)
    normals: _Array  # (N, 3) unit, grad f at the drawn point
    outliers: npt.NDArray[np.bool_]  # (N,) True for the uniform outliers
    labels: _Indices  # (N,) the leaf drawn on (node order), -1 outliers and blends
    truth_kinds: Optional[List[str]]  # one kind per leaf, None unless detect knows them all
    report: _Report  # the sample job's report
    def __iter__(self) -> Iterator[Any]: ...
    def __len__(self) -> int: ...
    def __getitem__(self, index: int) -> Any: ...

class DetectedPrimitive:
    """One primitive found by detect()."""

    name: str  # "p0", "p1", ... as in the scene file
    kind: str  # plane, sphere, cylinder, cone, torus
    model: Dict[str, Any]  # the scene file's model node: {"type": "sphere", "center": ..., ...}
    indices: _Indices  # (K,) its points, ascending
    rms_distance: float
    normal_side: str  # "outward", "inward" or "unknown"

class DetectResult:
    """The result of detect()."""

    primitives: List[DetectedPrimitive]  # largest first
    labels: _Indices  # (N,) index into primitives, -1 unassigned
    report: _Report  # `implicitfit detect --report` without its header

class ReconstructResult:
    """The result of reconstruct()."""

    model: Optional[Dict[str, Any]]  # the model file; None unless verified (or keep_unverified)
    success: bool
    verified: bool
    expression: str
    message: str
    labels: _Indices  # (N,) detect's primitive per point, -1 unassigned
    report: _Report  # `implicitfit reconstruct --report` without its header

def fit(
    points: _Points,
    normals: Optional[_Points] = None,
    kind: str = "sphere",
    seed: int = 0,
    threshold: Optional[float] = None,
    fix: Optional[Mapping[str, Union[float, Sequence[float]]]] = None,
    estimator: str = "robust",
    band: Optional[float] = None,
) -> FitResult:
    """One primitive, as `implicitfit fit CLOUD --model KIND`; model is None when it fails.
    threshold: a fixed inlier distance; band: the adaptive band's start."""

def detect(
    points: _Points,
    normals: Optional[_Points] = None,
    *,
    seed: int = 1,
    threshold: Optional[float] = None,
    min_points: Optional[int] = None,
    kinds: Optional[Sequence[str]] = None,
) -> DetectResult:
    """Every primitive of a cloud, as `implicitfit detect CLOUD`."""

def reconstruct(
    points: _Points,
    normals: Optional[_Points] = None,
    *,
    seed: int = 1,
    keep_unverified: bool = False,
) -> ReconstructResult:
    """The verified solid of a cloud, as `implicitfit reconstruct CLOUD` (detect, then the solid)."""

def mesh(
    model: Union[Model, Mapping[str, Any]], cell: Optional[float] = None
) -> Tuple[_Array, _Indices]:
    """(V, F) of the zero set, as `implicitfit mesh MODEL.json`: (n, 3) float64, (m, 3) int64."""

def fit_tree(points: _Points, normals: Optional[_Points], init: Model) -> FitResult:
    """Every free parameter of a model tree, as `implicitfit fit CLOUD --init MODEL.json`."""

def fit_patch(
    points: _Points,
    normals: Optional[_Points],
    degree: int = 2,
    convex: bool = False,
    tetrahedron: Optional[_Points] = None,
) -> FitResult:
    """A Bernstein patch of degree 2..4, as `implicitfit fit CLOUD --model quadric-patch`."""

def fit_patch_mesh(
    points: _Points,
    normals: Optional[_Points] = None,
    degree: int = 3,
    cells: int = 0,
    cell: float = 0.0,
    continuity: int = 1,
    levels: int = 0,
    convex: bool = False,
) -> FitResult:
    """A C0/C1 mesh of Bernstein patches, as `implicitfit fit CLOUD --model patch-mesh`."""

def read_cloud(path: _Path, estimate: bool = False) -> Tuple[_Array, Optional[_Array]]:
    """(points, normals or None) of a .xyz/.pwn/.txt/.ply/.pcd file."""

def estimate_normals(
    points: _Points,
    viewpoint: Optional[Sequence[float]] = None,
    min_k: int = 8,
    max_k: int = 30,
) -> _Array:
    """Oriented PCA normals: an (N, 3) array."""

def sample(
    model: Model,
    count: int,
    noise: float = 0.0,
    outliers: float = 0.0,
    seed: int = 0,
    view: Optional[Sequence[float]] = None,
    view_angle: float = 180.0,
) -> SampleResult:
    """Oriented points on the zero set, as `implicitfit sample`; unpacks as (points, normals)."""

def check(model: Model) -> _Report:
    """Convexity certificates, as one file's entry of `implicitfit check --json`."""
