# SPDX-License-Identifier: MIT
"""Sums, differences and zonotopes against the brute-force hull of all
pairwise vertex sums, computed with fractions in pure Python."""

import itertools
from fractions import Fraction

import pytest

import cvms
from conftest import brute_force_facets, brute_force_vertices, pairwise_sums

TETRA = [(0, 0, 0), (2, 0, 0), (0, 3, 0), (1, 1, 4)]
SKEW = [(0, 0, 0), (1, 2, 0), (-1, 1, 1), (0, -1, 2), (Fraction(1, 2), 0, -1)]


def check_against_brute_force(result, a_points, b_points):
    sums = pairwise_sums(a_points, b_points)
    planes = brute_force_facets(sums)
    a, b = result.halfspaces()
    assert set(zip(map(tuple, a), b)) == planes
    assert set(result.exact_vertices()) == brute_force_vertices(sums, planes)


@pytest.mark.parametrize("algorithm", ["cvms", "essdms", "chms"])
def test_sum_of_two_polyhedra_is_the_hull_of_pairwise_sums(algorithm):
    a, b = cvms.hull(TETRA), cvms.hull(SKEW)
    s = cvms.minkowski_sum(a, b, algorithm=algorithm)
    check_against_brute_force(s, a.exact_vertices(), b.exact_vertices())


def test_operator_list_and_threads_agree():
    a, b, c = cvms.hull(TETRA), cvms.hull(SKEW), cvms.cube()
    assert a + b == cvms.minkowski_sum(a, b) == cvms.minkowski_sum(a, b, threads=2)
    three = cvms.minkowski_sum([a, b, c])
    assert three == (a + b) + c == a + (c + b)
    # brute force on a small triple: a tetrahedron, a segment, a triangle
    small = [cvms.hull(TETRA), cvms.hull([(0, 0, 0), (1, 1, 1)]), cvms.hull([(0, 0, 0), (2, 0, 1), (0, 1, 2)])]
    ab = pairwise_sums(small[0].exact_vertices(), small[1].exact_vertices())
    check_against_brute_force(cvms.minkowski_sum(small), ab, small[2].exact_vertices())
    assert cvms.minkowski_sum([]) == cvms.hull([(0, 0, 0)])
    assert cvms.minkowski_sum(a) == a


def test_flat_sums_have_their_own_dimension():
    seg_x = cvms.hull([(0, 0, 0), (1, 0, 0)])
    seg_y = cvms.hull([(0, 0, 0), (0, 1, 0)])
    seg_z = cvms.hull([(0, 0, 0), (0, 0, 1)])
    square = seg_x + seg_y
    assert square.dimension == 2
    assert set(square.exact_vertices()) == {(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)}
    box = square + seg_z
    assert box.dimension == 3 and box.volume() == 1
    assert (seg_x + seg_x).dimension == 1
    assert (seg_x + cvms.ConvexSet()).is_empty


def test_minkowski_difference_is_a_plus_minus_b():
    a, b = cvms.hull(TETRA), cvms.hull(SKEW)
    d = cvms.minkowski_difference(a, b)
    assert d == a + (-b)
    check_against_brute_force(d, a.exact_vertices(), [tuple(-c for c in p) for p in b.exact_vertices()])


def test_pontryagin_difference_by_hand():
    cube = cvms.cube()
    half = cvms.box((Fraction(-1, 2),) * 3, (Fraction(1, 2),) * 3)
    assert cvms.pontryagin_difference(cube, half) == half
    assert cvms.pontryagin_difference(cube, cube) == cvms.hull([(0, 0, 0)])
    assert cvms.pontryagin_difference(half, cube).is_empty
    # the erosion undoes the sum for a polytope summand
    a, b = cvms.hull(TETRA), cvms.hull(SKEW)
    assert cvms.pontryagin_difference(a + b, b) == a
    with pytest.raises(cvms.Error) as info:
        cvms.pontryagin_difference(cube, cvms.ConvexSet())
    assert info.value.category == "invalid_argument"


def test_zonotope_counts_and_shape():
    assert cvms.zonotope((0, 0, 0), [(1, 0, 0), (0, 1, 0), (0, 0, 1)]) == cvms.cube()
    gens = [(1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 1), (1, -2, 3)]
    z = cvms.zonotope(("0.5", 0, 0), gens)
    n = len(gens)
    assert z.num_vertices == n * n - n + 2
    assert len(z.faces) == n * (n - 1)
    segments = [cvms.hull([tuple(-c for c in g), g]) for g in gens]
    assert z == cvms.minkowski_sum(segments).translated((Fraction(1, 2), 0, 0))
    # brute force: all 2^n sign choices
    corners = [tuple(Fraction(1, 2) * (i == 0) + sum(s * g[i] for s, g in zip(signs, gens)) for i in range(3))
               for signs in itertools.product((-1, 1), repeat=n)]
    assert set(z.exact_vertices()) == brute_force_vertices(corners, brute_force_facets(corners))
    assert cvms.zonotope((1, 2, 3), []).exact_vertices() == [(1, 2, 3)]


def test_sum_limits_raise_a_limit_error():
    with pytest.raises(cvms.Error) as info:
        cvms.zonotope((0, 0, 0), [(1, i, i * i) for i in range(1, 100001)])
    assert info.value.category == "limit"
