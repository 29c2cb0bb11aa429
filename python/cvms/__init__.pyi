# SPDX-License-Identifier: MIT
"""Type stubs of the cvms package (exact convex geometry on GMP rationals)."""

from decimal import Decimal
from fractions import Fraction
from os import PathLike
from typing import Iterable, Literal, Optional, Sequence, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str

#: An exact number: int, float (its exact binary value), Fraction, Decimal,
#: or a decimal / "p/q" string ("0.1" is exactly 1/10).
Number = Union[int, float, Fraction, Decimal, str, np.integer, np.floating]
#: Three exact numbers.
Point = Union[Sequence[Number], npt.NDArray[np.generic]]
#: An (n, 3) array (float: each double exactly; int) or a sequence of points.
Points = Union[npt.NDArray[np.generic], Sequence[Point]]
#: Exact coordinates: ints where the value is an integer may appear as Fraction(n, 1).
ExactTriple = tuple[Fraction, Fraction, Fraction]
IntTriple = tuple[int, int, int]
Path = Union[str, "PathLike[str]"]

class Error(ValueError):
    """Every failure of the library: a ValueError with the library's category and message."""

    category: Literal["parse", "topology", "not_convex", "degenerate", "limit", "io", "invalid_argument"]
    """The kind of failure."""
    message: str
    """The library's message without the "<category>: " prefix of str(e)."""

class ConvexSet:
    """An exact convex polytope in 3-D of any dimension (-1 empty .. 3 polyhedron). Immutable, picklable."""

    def __init__(self) -> None:
        """The empty set."""
    @property
    def dimension(self) -> int:
        """-1 for the empty set, 0 point, 1 segment, 2 polygon, 3 polyhedron."""
    @property
    def is_empty(self) -> bool:
        """True iff this is the empty set."""
    @property
    def num_vertices(self) -> int:
        """The number of vertices."""
    @property
    def vertices(self) -> npt.NDArray[np.float64]:
        """The vertices as an (n, 3) float64 array of nearest doubles."""
    def exact_vertices(self) -> list[ExactTriple]:
        """The exact vertices, as triples of Fraction, in the order of vertices."""
    @property
    def faces(self) -> list[list[int]]:
        """Vertex indices of each face, counter-clockwise from outside ([] below dimension 2)."""
    def triangles(self) -> npt.NDArray[np.int64]:
        """The faces fan-triangulated: an (m, 3) int64 array of vertex indices."""
    def volume(self) -> Fraction:
        """The exact volume (0 below dimension 3)."""
    def contains(self, point: Point) -> bool:
        """True iff the point lies in the set (exactly; the boundary counts)."""
    def translated(self, offset: Point) -> ConvexSet:
        """The set moved by offset."""
    def reflected(self) -> ConvexSet:
        """-S = {-x : x in S}."""
    def halfspaces(self) -> tuple[list[list[int]], list[int]]:
        """The minimal rows (A, b) of A x <= b, primitive integers."""
    def equalities(self) -> tuple[list[list[int]], list[int]]:
        """The rows (E, f) of E x = f of a flat set's affine hull (empty for a solid)."""
    def to_off(self) -> str:
        """The set as exact OFF text."""
    def __neg__(self) -> ConvexSet:
        """-S = {-x : x in S}."""
    def __add__(self, other: ConvexSet) -> ConvexSet:
        """The Minkowski sum."""
    def __eq__(self, other: object) -> bool:
        """Exact equality of the sets."""
    def __ne__(self, other: object) -> bool:
        """Exact inequality of the sets."""
    def __reduce__(self) -> tuple[object, tuple[str]]:
        """Pickling through the exact OFF text."""

class DistanceResult:
    """The exact distance of two sets and where it is reached."""

    @property
    def squared_distance(self) -> Fraction:
        """min |a - b|^2 over a in A, b in B; 0 iff they intersect."""
    @property
    def witness_a(self) -> ExactTriple:
        """A point of A closest to B."""
    @property
    def witness_b(self) -> ExactTriple:
        """A point of B closest to A."""
    @property
    def intersect(self) -> bool:
        """True iff they intersect (touching counts)."""
    @property
    def distance(self) -> float:
        """The correctly rounded distance."""

class PenetrationResult:
    """How far B must be translated to separate from A."""

    @property
    def intersect(self) -> bool:
        """True iff they intersect (touching counts)."""
    @property
    def squared_depth(self) -> Fraction:
        """The squared minimum translation distance; 0 when apart or touching."""
    @property
    def direction(self) -> IntTriple:
        """The primitive integer normal of the nearest facet of A + (-B); (0, 0, 0) when apart."""
    @property
    def offset(self) -> Fraction:
        """That facet's plane offset."""
    @property
    def translation(self) -> ExactTriple:
        """The minimum translation of B."""
    @property
    def witness_a(self) -> ExactTriple:
        """A point of A: witness_a - witness_b == translation when they intersect."""
    @property
    def witness_b(self) -> ExactTriple:
        """A point of B."""
    @property
    def depth(self) -> float:
        """The correctly rounded depth."""

def read(path: Path) -> ConvexSet:
    """Reads a convex set of any dimension (.off, .obj, .stl, .ply, or a list of points)."""
def write(set: ConvexSet, path: Path, float: Union[bool, Literal["nearest", "outer"]] = False) -> None:
    """Writes the set in the format of the path's extension, exactly unless float is True,
    'nearest' (a valid convex set in doubles) or 'outer' (doubles that contain the set)."""
def to_float_mesh(
    set: ConvexSet, mode: Literal["nearest", "outer"] = "nearest"
) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.uint32]]:
    """The set in doubles as (positions (n, 3) float64, triangles (m, 3) uint32), as write() writes it."""
def from_off(text: str) -> ConvexSet:
    """The convex set an OFF text describes."""
def hull(points: Points) -> ConvexSet:
    """The exact convex hull, in the dimension the points span."""
def from_halfspaces(A: Points, b: Sequence[Number], E: Optional[Points] = None,
                    f: Optional[Sequence[Number]] = None) -> ConvexSet:
    """The exact intersection of A x <= b (and E x = f); raises Error if unbounded."""
@overload
def minkowski_sum(a: ConvexSet, b: ConvexSet, *, threads: int = 1,
                  algorithm: Literal["cvms", "essdms", "chms"] = "cvms") -> ConvexSet: ...
@overload
def minkowski_sum(a: Iterable[ConvexSet], b: None = None, *, threads: int = 1,
                  algorithm: Literal["cvms", "essdms", "chms"] = "cvms") -> ConvexSet: ...
def minkowski_difference(a: ConvexSet, b: ConvexSet) -> ConvexSet:
    """a + (-b), the configuration-space obstacle."""
def pontryagin_difference(a: ConvexSet, b: ConvexSet) -> ConvexSet:
    """The erosion {x : x + b in a}."""
def zonotope(center: Point, generators: Points) -> ConvexSet:
    """center + the sum of the segments [-g, g]."""
def intersects(a: ConvexSet, b: ConvexSet) -> bool:
    """True iff a and b have a common point."""
def squared_distance(a: ConvexSet, b: ConvexSet) -> DistanceResult:
    """The exact squared distance with witnesses."""
def distance(a: ConvexSet, b: ConvexSet) -> float:
    """The correctly rounded distance."""
def penetration(a: ConvexSet, b: ConvexSet) -> PenetrationResult:
    """The exact penetration depth, direction and witnesses."""
def cube() -> ConvexSet:
    """The cube [-1, 1]^3."""
def tetrahedron() -> ConvexSet:
    """The regular tetrahedron (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1)."""
def octahedron() -> ConvexSet:
    """The octahedron |x|+|y|+|z| <= 1."""
def box(lo: Point, hi: Point) -> ConvexSet:
    """The axis-aligned box [lo, hi]."""
def geodesic_sphere(k: int, rotated: bool = False) -> ConvexSet:
    """The benchmark sphere Sphere_k (about 20 * 4^(k-1) facets)."""
