# SPDX-License-Identifier: MIT
"""Exact Minkowski sums, convex hulls, half-spaces and proximity of convex sets.

Every value is exact (GMP rationals): inputs are taken exactly (a float as the
binary number it is, "0.1" as 1/10), exact outputs are ``fractions.Fraction``
or ``int``; only ``ConvexSet.vertices`` and ``distance()`` round, to the
nearest double. See docs/python.md.

>>> import cvms
>>> box = cvms.hull([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 1)])
>>> (box + cvms.cube()).dimension
3
"""

from ._cvms import (
    ConvexSet,
    DistanceResult,
    Error,
    PenetrationResult,
    __version__,
    box,
    cube,
    distance,
    from_halfspaces,
    from_off,
    geodesic_sphere,
    hull,
    intersects,
    minkowski_difference,
    minkowski_sum,
    octahedron,
    penetration,
    pontryagin_difference,
    read,
    squared_distance,
    tetrahedron,
    write,
    zonotope,
)

Error.__module__ = "cvms"

__all__ = [
    "ConvexSet",
    "DistanceResult",
    "Error",
    "PenetrationResult",
    "__version__",
    "box",
    "cube",
    "distance",
    "from_halfspaces",
    "from_off",
    "geodesic_sphere",
    "hull",
    "intersects",
    "minkowski_difference",
    "minkowski_sum",
    "octahedron",
    "penetration",
    "pontryagin_difference",
    "read",
    "squared_distance",
    "tetrahedron",
    "write",
    "zonotope",
]
