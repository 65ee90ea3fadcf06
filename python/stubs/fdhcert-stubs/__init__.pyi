# Type stubs of the module fdhcert (pybind11, python/src; docs/python.md), a PEP 561 stub-only
# package: fdhcert is one extension module, which cannot hold a py.typed of its own.
# tests/package/test_stubs.py checks that every public name, parameter and default here is the
# module's, and the reverse.
from fractions import Fraction
from os import PathLike
from typing import Dict, List, Optional, Sequence, Tuple, TypedDict, Union

import numpy as np
import numpy.typing as npt

_Path = Union[str, bytes, PathLike[str], PathLike[bytes]]
_Bools = npt.NDArray[np.bool_]
_Floats = npt.NDArray[np.float64]

class InputError(ValueError):
    """Bad input, with the message the fdhcert program prints ("FILE:LINE: message")."""

# The dicts the module returns (stub-only types, hence private names). classify and classify_arrays return `fdhcert classify --json`'s
# object (docs/formats.md), audit `fdhcert audit --json`'s (docs/audit.md).

class _ContactTime(TypedDict):
    hit: bool
    time: Optional[Fraction]  # the earliest contact when rational
    interval: Optional[Tuple[Fraction, Fraction]]  # around it; None without a hit

class _AgainstExact(TypedDict):
    misses: int
    false_alarms: int
    broken: int
    allowed: int

class _MethodTally(TypedDict):
    tp: Optional[int]  # None (and ns_per_query) where the method applies to no query
    tn: Optional[int]
    fp: Optional[int]
    fn: Optional[int]
    na: int
    ns_per_query: Optional[float]
    promise: str  # "exact", "conservative" or "none"
    against_exact: Optional[_AgainstExact]

class _Counts(TypedDict):
    queries: int
    static_vf: int
    moving_vf: int
    edge_edge: int
    truth: str  # "file", "exact" or "mixed"
    methods: Dict[str, _MethodTally]

class _FileCounts(_Counts):
    file: str

class _CpuTime(TypedDict):
    queries: int
    median_ns: Optional[float]
    p90_ns: Optional[float]
    max_ns: Optional[float]
    slowest: Optional[str]  # "FILE:LINE (query ID)"

class _CpuTimes(TypedDict):
    rounds: int
    methods: Dict[str, _CpuTime]

class _ClassificationBase(_Counts):
    gate: int
    files: List[_FileCounts]

class _Classification(_ClassificationBase, total=False):
    min_distance: float  # only when asked at a minimum separation > 0
    cpu_time: _CpuTimes  # only with time=True

class _SceneSummary(TypedDict):
    grid: int
    frames: int
    particles: int
    dt: float
    ms_per_frame: float
    candidates: int
    collisions: int
    fp: int
    fn: int
    inside: int
    crossing: int

class _SceneRun(TypedDict):
    positions: _Floats  # F×N×3, every `every`-th frame
    frames: List[int]  # their frame numbers
    triangles: npt.NDArray[np.int32]  # M×3
    final: _Floats  # N×3, after the last frame
    summary: _SceneSummary

class _AuditMesh(TypedDict):
    vertices: int
    triangles: int

class _AuditCandidates(TypedDict):
    static: int
    ccd: int

class _AuditToi(TypedDict):
    t_lo: float
    t_hi: float

class _AuditViolationBase(TypedDict):
    kind: str  # "self-intersection", "self-vertex-face", ...
    step: bool  # in a step (vertices, triangle, to_frame) or in a frame (triangles)
    frame: int
    toi: Optional[_AuditToi]

class _AuditViolation(_AuditViolationBase, total=False):
    to_frame: int
    vertices: List[int]
    triangle: Optional[int]
    triangles: List[int]
    triangle_vertices: List[List[int]]
    places: List[str]
    case_file: str

class _AuditCost(TypedDict):
    audit_seconds: float
    wall_seconds: float
    ns_per_vertex_step: Optional[float]
    peak_memory_bytes: int
    threads: int

class _AuditNearRule(TypedDict):
    rings: int
    first_frame: bool

class _AuditExcluded(TypedDict):
    rings: int
    first_frame: int
    first_frame_pairs: int

class _AuditNearestPair(TypedDict):
    frame: int
    triangles: List[int]
    squared: str  # the exact squared distance, "p/q"
    distance_lo: float
    distance_hi: float

class _AuditNearest(TypedDict):
    self: Optional[_AuditNearestPair]  # the cloth against itself
    obstacle: Optional[_AuditNearestPair]  # the cloth against the obstacles

class _AuditProximity(TypedDict):
    min_distance: float
    near_rule: _AuditNearRule
    excluded: _AuditExcluded
    nearest: _AuditNearest

class _AuditBase(TypedDict):
    clean: bool
    summary: str
    frames: int
    steps: int
    cloth: _AuditMesh
    obstacles: _AuditMesh
    k: int
    violations: int
    totals: Dict[str, int]  # per violation kind
    candidates: _AuditCandidates
    first_violation: Optional[_AuditViolation]
    per_frame: List[Dict[str, int]]  # "frame" and the counts per kind
    kept: List[_AuditViolation]
    cost: _AuditCost

class _Audit(_AuditBase, total=False):
    proximity: _AuditProximity  # with min_distance > 0 only

def methods() -> List[str]: ...
def min_distance_methods() -> List[str]: ...
def point_triangle(
    queries: npt.ArrayLike, method: str = "robust", min_distance: float = 0.0
) -> _Bools: ...
def vertex_face_ccd(
    queries: npt.ArrayLike, method: str = "robust", min_distance: float = 0.0
) -> _Bools: ...
def edge_edge_ccd(
    queries: npt.ArrayLike, method: str = "robust", min_distance: float = 0.0
) -> _Bools: ...
def vertex_face_toi(
    queries: npt.ArrayLike,
    method: str = "robust",
    width: float = 9.313225746154785e-10,
    min_distance: float = 0.0,
) -> Tuple[_Bools, _Floats, _Floats]: ...
def edge_edge_toi(
    queries: npt.ArrayLike,
    method: str = "robust",
    width: float = 9.313225746154785e-10,
    min_distance: float = 0.0,
) -> Tuple[_Bools, _Floats, _Floats]: ...
def contact_time(query: npt.ArrayLike, kind: str = "vertex-face") -> _ContactTime: ...
def kdop(points: npt.ArrayLike, k: int = 18) -> Tuple[_Floats, _Floats, npt.NDArray[np.int32]]: ...
def classify(
    files: Sequence[_Path],
    methods: Sequence[str] = [],
    kind: str = "",
    gate: int = 0,
    time: bool = False,
    rounds: int = 7,
    min_distance: float = 0.0,
) -> _Classification: ...
def classify_arrays(
    queries: npt.ArrayLike,
    kind: str = "vertex-face",
    truth: Optional[npt.ArrayLike] = None,
    methods: Sequence[str] = [],
) -> _Classification: ...
def simulate(
    scene: _Path,
    frames: Optional[int] = None,
    grid: int = 0,
    every: int = 1,
    narrow: str = "robust",
    k: int = 18,
    check: bool = False,
) -> _SceneRun: ...
def audit(
    frames: npt.ArrayLike,
    faces: npt.ArrayLike,
    obstacles: Optional[npt.ArrayLike] = None,
    obstacle_faces: Optional[npt.ArrayLike] = None,
    k: int = 18,
    threads: int = 0,
    keep: int = 16,
    min_distance: float = 0.0,
    near_rings: int = 2,
    near_first_frame: bool = True,
) -> _Audit: ...
