# SPDX-License-Identifier: MIT
"""ConvexSet: construction from every kind of input, exact and float views,
faces, volume, membership, half-spaces, equality, reflection, translation."""

from decimal import Decimal
from fractions import Fraction

import numpy as np
import pytest

import cvms
from conftest import brute_force_facets, brute_force_vertices, cross, dot, sub

CUBE = [(x, y, z) for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]


def test_version_is_the_project_version():
    assert isinstance(cvms.__version__, str)
    assert cvms.__version__.count(".") == 2


def test_hull_of_a_cube_from_ints_floats_fractions_strings_and_arrays():
    expected = set(tuple(Fraction(c) for c in p) for p in CUBE)
    inputs = [
        CUBE,
        [tuple(float(c) for c in p) for p in CUBE],
        [tuple(Fraction(c) for c in p) for p in CUBE],
        [tuple(str(c) for c in p) for p in CUBE],
        [tuple(Decimal(c) for c in p) for p in CUBE],
        np.array(CUBE, dtype=np.int64),
        np.array(CUBE, dtype=np.int32),
        np.array(CUBE, dtype=np.float64),
        np.array(CUBE, dtype=np.float32),
        np.array(CUBE + [(0, 0, 0)], dtype=object),
    ]
    for points in inputs:
        s = cvms.hull(points)
        assert s.dimension == 3
        assert set(s.exact_vertices()) == expected
        assert s == cvms.cube()


def test_decimal_strings_are_exact_and_doubles_are_their_binary_value():
    s = cvms.hull([("0.1", 0, 0)])
    assert s.dimension == 0
    assert s.exact_vertices() == [(Fraction(1, 10), 0, 0)]
    d = cvms.hull(np.array([[0.1, 0, 0]]))
    assert d.exact_vertices() == [(Fraction(0.1), 0, 0)]
    assert Fraction(0.1) != Fraction(1, 10)
    assert d.vertices[0, 0] == 0.1
    huge = Fraction(1, 3**100)
    p = cvms.hull([(huge, -(2**200), "1/7")])
    assert p.exact_vertices() == [(huge, -(2**200), Fraction(1, 7))]


def test_dimensions_of_hulls():
    assert cvms.hull([]).dimension == -1
    assert cvms.hull([]).is_empty
    assert cvms.hull([(1, 2, 3), (1, 2, 3)]).dimension == 0
    seg = cvms.hull([(0, 0, 0), (2, 2, 2), (1, 1, 1)])
    assert seg.dimension == 1
    assert sorted(seg.exact_vertices()) == [(0, 0, 0), (2, 2, 2)]
    square = cvms.hull([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (Fraction(1, 2), Fraction(1, 2), 0)])
    assert square.dimension == 2
    assert square.num_vertices == 4


def test_vertices_are_the_nearest_doubles_in_one_float64_array():
    third = Fraction(1, 3)
    s = cvms.hull([(third, 0, 0), (0, third, 0), (0, 0, third), (0, 0, 0)])
    v = s.vertices
    assert v.dtype == np.float64 and v.shape == (4, 3)
    for row, exact in zip(v, s.exact_vertices()):
        for x, q in zip(row, exact):
            # the nearest double: no other double is closer
            assert abs(Fraction(float(x)) - q) <= abs(Fraction(np.nextafter(x, 1)) - q)
            assert abs(Fraction(float(x)) - q) <= abs(Fraction(np.nextafter(x, -1)) - q)
            assert x == float(q)  # Python's Fraction -> float is correctly rounded too


def test_faces_are_counter_clockwise_from_outside_and_triangles_cover_them():
    s = cvms.hull([(0, 0, 0), (3, 0, 0), (0, 3, 0), (0, 0, 3), (1, 1, 0)])
    vertices = s.exact_vertices()
    centroid = tuple(sum(v[i] for v in vertices) / len(vertices) for i in range(3))
    for face in s.faces:
        a, b, c = (vertices[i] for i in face[:3])
        normal = cross(sub(b, a), sub(c, a))
        assert dot(normal, sub(centroid, a)) < 0  # the centroid is behind every face
    tris = s.triangles()
    assert tris.dtype == np.int64 and tris.shape == (sum(len(f) - 2 for f in s.faces), 3)
    assert cvms.hull([(0, 0, 0), (1, 0, 0)]).faces == []
    assert cvms.hull([(0, 0, 0), (1, 0, 0)]).triangles().shape == (0, 3)


def test_volume_by_hand():
    assert cvms.cube().volume() == 8
    assert cvms.tetrahedron().volume() == Fraction(8, 3)
    assert cvms.octahedron().volume() == Fraction(4, 3)
    assert cvms.hull([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]).volume() == Fraction(1, 6)
    assert cvms.box((0, 0, 0), ("0.1", Fraction(1, 3), 7)).volume() == Fraction(7, 30)
    assert isinstance(cvms.cube().volume(), Fraction)
    assert cvms.hull([(0, 0, 0), (1, 0, 0), (0, 1, 0)]).volume() == 0


def test_contains_is_exact_on_the_boundary():
    cube = cvms.cube()
    assert cube.contains((1, 1, 1))
    assert cube.contains((0, "0.5", -1))
    assert not cube.contains((0, 0, Fraction(10**30 + 1, 10**30)))
    square = cvms.hull([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)])
    assert square.contains((Fraction(1, 2), 1, 0))
    assert not square.contains((Fraction(1, 2), Fraction(1, 2), Fraction(1, 10**40)))
    assert not cvms.ConvexSet().contains((0, 0, 0))
    assert cube.contains(np.array([0.5, 0.5, 0.5]))


def test_halfspaces_are_minimal_primitive_and_match_brute_force():
    points = [(0, 0, 0), (4, 0, 0), (0, 4, 0), (0, 0, 4), (4, 4, 4), (1, 1, 1), (2, 0, 0)]
    s = cvms.hull(points)
    a, b = s.halfspaces()
    rows = set(zip(map(tuple, a), b))
    assert rows == brute_force_facets(points)
    assert s.equalities() == ([], [])
    assert all(isinstance(x, int) for row in a for x in row)


def test_equalities_of_flat_sets():
    square = cvms.hull([(0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)])
    e, f = square.equalities()
    assert e == [[0, 0, 1]] and f == [1]
    a, b = square.halfspaces()
    assert len(a) == 4
    assert len(cvms.hull([(0, 0, 0), (1, 2, 3)]).equalities()[0]) == 2
    assert len(cvms.hull([(5, 6, 7)]).equalities()[0]) == 3


def test_from_halfspaces_inverts_halfspaces_and_takes_exact_inputs():
    for s in [cvms.cube(), cvms.tetrahedron(), cvms.hull([(0, 0, 0), (1, 0, 0), (1, 1, 0)]),
              cvms.hull([(1, 2, 3), (4, 5, 6)]), cvms.hull([(1, 2, 3)])]:
        a, b = s.halfspaces()
        e, f = s.equalities()
        assert cvms.from_halfspaces(a, b, e, f) == s
    # rows as numpy floats, strings and fractions; a redundant row
    a = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1], [1, 1, 1]], dtype=float)
    b = ["0.5", 0, Fraction(1, 3), 0, 2, 0, 100]
    s = cvms.from_halfspaces(a, b)
    assert s.volume() == Fraction(1, 2) * Fraction(1, 3) * 2
    assert cvms.from_halfspaces([[1, 0, 0], [-1, 0, 0]], [-1, 0]).is_empty  # x <= -1 and x >= 0


def test_from_halfspaces_reports_unboundedness_as_a_cvms_error():
    with pytest.raises(cvms.Error) as info:
        cvms.from_halfspaces([[1, 0, 0], [-1, 0, 0]], [1, 1])
    assert info.value.category == "invalid_argument"
    assert "unbounded" in info.value.message
    with pytest.raises(cvms.Error):
        cvms.from_halfspaces([[1, 0, 0]], [1, 2])  # 1 row, 2 right-hand sides


def test_reflection_translation_and_equality():
    s = cvms.hull([(0, 0, 0), (1, 0, 0), (0, 2, 0), (0, 0, 3)])
    assert set((-s).exact_vertices()) == {tuple(-c for c in v) for v in s.exact_vertices()}
    assert -s == s.reflected()
    assert -(-s) == s
    t = s.translated((Fraction(1, 3), "0.5", -2))
    assert set(t.exact_vertices()) == {(v[0] + Fraction(1, 3), v[1] + Fraction(1, 2), v[2] - 2)
                                       for v in s.exact_vertices()}
    assert t != s
    assert cvms.ConvexSet() == cvms.hull([])


def test_repr_names_the_kind():
    assert "polyhedron" in repr(cvms.cube())
    assert "empty" in repr(cvms.ConvexSet())


def test_brute_force_helpers_can_fail():
    # the oracle tells a tetrahedron's facets from a cube's
    assert brute_force_facets(CUBE) != brute_force_facets([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)])
    assert len(brute_force_vertices(CUBE + [(0, 0, 0)], brute_force_facets(CUBE))) == 8
