# Type stubs of the module fdhcert (pybind11, python/src; docs/python.md), a PEP 561 stub-only
# package: fdhcert is one extension module, which cannot hold a py.typed of its own.
# tests/package/test_stubs.py checks that every public name, parameter and default here is the
# module's, and the reverse.
from fractions import Fraction
from os import PathLike
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

_Path = Union[str, bytes, PathLike[str], PathLike[bytes]]
_Bools = npt.NDArray[np.bool_]
_Floats = npt.NDArray[np.float64]

class InputError(ValueError):
    """Bad input, with the message the fdhcert program prints ("FILE:LINE: message")."""

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
def contact_time(
    query: npt.ArrayLike, kind: str = "vertex-face"
) -> Dict[str, Union[bool, Optional[Fraction], Tuple[Fraction, Fraction]]]: ...
def kdop(points: npt.ArrayLike, k: int = 18) -> Tuple[_Floats, _Floats, npt.NDArray[np.int32]]: ...
def classify(
    files: Sequence[_Path],
    methods: Sequence[str] = [],
    kind: str = "",
    gate: int = 0,
    time: bool = False,
    rounds: int = 7,
) -> Dict[str, Any]: ...
def classify_arrays(
    queries: npt.ArrayLike,
    kind: str = "vertex-face",
    truth: Optional[npt.ArrayLike] = None,
    methods: Sequence[str] = [],
) -> Dict[str, Any]: ...
def simulate(
    scene: _Path,
    frames: Optional[int] = None,
    grid: int = 0,
    every: int = 1,
    narrow: str = "robust",
    k: int = 18,
    check: bool = False,
) -> Dict[str, Any]: ...
def audit(
    frames: npt.ArrayLike,
    faces: npt.ArrayLike,
    obstacles: Optional[npt.ArrayLike] = None,
    obstacle_faces: Optional[npt.ArrayLike] = None,
    k: int = 18,
    threads: int = 0,
    keep: int = 16,
) -> Dict[str, Any]: ...
