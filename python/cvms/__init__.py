# SPDX-License-Identifier: MIT
"""Exact Minkowski sums, convex hulls, half-spaces and proximity of convex sets.

Every value is exact (GMP rationals): inputs are taken exactly (a float as the
binary number it is, "0.1" as 1/10), exact outputs are ``fractions.Fraction``
or ``int``; only ``ConvexSet.vertices``, ``distance()`` and the ``depth`` and
``distance`` properties round, to the nearest double. See docs/python.md.

>>> import cvms
>>> corner = cvms.hull([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)])
>>> (corner + cvms.cube()).dimension
3

The functions are thin Python functions over the extension module
``cvms._cvms`` so that they pickle by name (dask and multiprocessing ship
them to workers); each one's docstring is the extension's.
"""

from . import _cvms
from ._cvms import ConvexSet, DistanceResult, Error, PenetrationResult, __version__

for _name in ("ConvexSet", "DistanceResult", "PenetrationResult", "Error"):
    globals()[_name].__module__ = "cvms"
del _name

__all__ = [
    "ConvexSet", "DistanceResult", "Error", "PenetrationResult", "__version__",
    "box", "cube", "distance", "from_halfspaces", "from_off", "geodesic_sphere", "hull",
    "intersects", "minkowski_difference", "minkowski_sum", "octahedron", "penetration",
    "pontryagin_difference", "read", "squared_distance", "tetrahedron", "to_float_mesh", "write",
    "zonotope",
]


def read(path):
    return _cvms.read(str(path))


def write(set, path, float=False):  # noqa: A002 (the names of the documented API)
    _cvms.write(set, str(path), float)


def to_float_mesh(set, mode="nearest"):  # noqa: A002 (the names of the documented API)
    return _cvms.to_float_mesh(set, mode)


def from_off(text):
    return _cvms.from_off(text)


def hull(points):
    return _cvms.hull(points)


def from_halfspaces(A, b, E=None, f=None):  # noqa: N803 (the usual names of A x <= b)
    return _cvms.from_halfspaces(A, b, E, f)


def minkowski_sum(a, b=None, *, threads=1, algorithm="cvms"):
    return _cvms.minkowski_sum(a, b, threads=threads, algorithm=algorithm)


def minkowski_difference(a, b):
    return _cvms.minkowski_difference(a, b)


def pontryagin_difference(a, b):
    return _cvms.pontryagin_difference(a, b)


def zonotope(center, generators):
    return _cvms.zonotope(center, generators)


def intersects(a, b):
    return _cvms.intersects(a, b)


def squared_distance(a, b):
    return _cvms.squared_distance(a, b)


def distance(a, b):
    return _cvms.distance(a, b)


def penetration(a, b):
    return _cvms.penetration(a, b)


def cube():
    return _cvms.cube()


def tetrahedron():
    return _cvms.tetrahedron()


def octahedron():
    return _cvms.octahedron()


def box(lo, hi):
    return _cvms.box(lo, hi)


def geodesic_sphere(k, rotated=False):
    return _cvms.geodesic_sphere(k, rotated)


def _document():
    for name in __all__:
        function = globals()[name]
        if callable(function) and getattr(function, "__module__", None) == __name__:
            # pybind11's docstring starts with the C++ signature line; keep the text.
            doc = getattr(_cvms, name).__doc__ or ""
            function.__doc__ = doc.split("\n", 1)[-1].strip() if doc.startswith(name + "(") else doc


_document()
del _document
