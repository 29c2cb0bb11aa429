# SPDX-License-Identifier: MIT
"""Shared helpers of the Python tests: brute-force exact geometry in pure
Python (fractions only), independent of the library, and the CLI's path."""

import itertools
import math
import os
import shutil
from fractions import Fraction

import pytest


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def primitive(normal, offset):
    """The row (normal, offset) scaled by a positive rational to integers with gcd 1."""
    values = [Fraction(v) for v in (*normal, offset)]
    lcm = 1
    for v in values:
        lcm = lcm * v.denominator // math.gcd(lcm, v.denominator)
    ints = [int(v * lcm) for v in values]
    g = 0
    for v in ints:
        g = math.gcd(g, v)
    return tuple(v // g for v in ints[:3]), ints[3] // g


def brute_force_facets(points):
    """The facet planes of the hull of solid points, as primitive rows (a, b) with
    a.x <= b: every plane through three of the points with all points on one side."""
    points = sorted(set(tuple(Fraction(c) for c in p) for p in points))
    planes = set()
    for p, q, r in itertools.combinations(points, 3):
        n = cross(sub(q, p), sub(r, p))
        if n == (0, 0, 0):
            continue
        d = dot(n, p)
        sides = {(dot(n, x) > d) - (dot(n, x) < d) for x in points}
        if 1 in sides and -1 in sides:
            continue
        if 1 in sides:
            n, d = tuple(-c for c in n), -d
        planes.add(primitive(n, d))
    return planes


def brute_force_vertices(points, planes):
    """The points of the set that lie on three facet planes with independent normals."""
    vertices = set()
    for p in set(tuple(Fraction(c) for c in x) for x in points):
        on = [a for a, b in planes if dot(a, p) == b]
        if any(dot(cross(a, b), c) != 0 for a, b, c in itertools.combinations(on, 3)):
            vertices.add(p)
    return vertices


def pairwise_sums(a_points, b_points):
    return [tuple(x + y for x, y in zip(p, q)) for p in a_points for q in b_points]


@pytest.fixture
def cli():
    """The cvms command-line tool of the same build (CVMS_CLI), or skip."""
    path = os.environ.get("CVMS_CLI") or shutil.which("cvms")
    if not path or not os.path.exists(path):
        pytest.skip("the cvms command-line tool is not built (CVMS_CLI)")
    return path
