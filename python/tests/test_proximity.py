# SPDX-License-Identifier: MIT
"""intersects, squared_distance, distance and penetration against answers
worked out by hand."""

import math
from fractions import Fraction

import pytest

import cvms


def box(lo, hi):
    return cvms.box(lo, hi)


def test_intersects_touching_counts():
    a = cvms.cube()
    assert cvms.intersects(a, a.translated((2, 0, 0)))  # touching faces
    assert not cvms.intersects(a, a.translated((Fraction(2) + Fraction(1, 10**30), 0, 0)))
    assert cvms.intersects(a, cvms.hull([(0, 0, 0)]))
    with pytest.raises(cvms.Error):
        cvms.intersects(a, cvms.ConvexSet())


def test_squared_distance_of_boxes_by_hand():
    a = cvms.cube()
    b = box((2, 3, -5), (4, 5, 5))  # gap 1 in x, 2 in y, overlap in z
    r = cvms.squared_distance(a, b)
    assert r.squared_distance == 5 and isinstance(r.squared_distance, Fraction)
    assert not r.intersect
    wa, wb = r.witness_a, r.witness_b
    assert a.contains(wa) and b.contains(wb)
    assert sum((x - y) ** 2 for x, y in zip(wa, wb)) == 5
    assert wa[0] == 1 and wa[1] == 1 and wb[0] == 2 and wb[1] == 3
    # IEEE square root of an exactly representable value is correctly rounded
    assert cvms.distance(a, b) == math.sqrt(5)
    assert r.distance == math.sqrt(5)


def test_distance_of_flat_sets_and_rationals():
    seg = cvms.hull([(0, 0, 3), (1, 0, 3)])
    square = cvms.hull([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)])
    assert cvms.squared_distance(seg, square).squared_distance == 9
    p = cvms.hull([(Fraction(1, 3), Fraction(1, 3), Fraction(1, 3))])
    q = cvms.hull([(0, 0, 0), (1, 0, 0), (0, 1, 0)])  # the triangle's plane z = 0
    assert cvms.squared_distance(p, q).squared_distance == Fraction(1, 9)
    assert cvms.distance(p, q) == float(Fraction(1, 3))
    inside = cvms.squared_distance(cvms.cube(), cvms.hull([(0, 0, 0)]))
    assert inside.intersect and inside.squared_distance == 0 and inside.witness_a == inside.witness_b


def test_penetration_by_hand():
    a = cvms.cube()
    b = a.translated((Fraction(1, 2), Fraction(1, 4), 0))
    r = cvms.penetration(a, b)
    assert r.intersect
    assert r.squared_depth == Fraction(9, 4)  # overlap 3/2 in x, 7/4 in y, 2 in z
    assert r.direction == (1, 0, 0) and all(isinstance(c, int) for c in r.direction)
    assert r.translation == (Fraction(3, 2), 0, 0)
    assert tuple(x - y for x, y in zip(r.witness_a, r.witness_b)) == r.translation
    assert r.depth == 1.5
    moved = b.translated(r.translation)
    assert cvms.intersects(a, moved)
    assert cvms.squared_distance(a, moved.translated((Fraction(1, 10**9), 0, 0))).squared_distance > 0


def test_penetration_of_separate_sets_is_zero():
    a = cvms.cube()
    r = cvms.penetration(a, a.translated((5, 0, 0)))
    assert not r.intersect
    assert r.squared_depth == 0 and r.direction == (0, 0, 0)
    assert sum((x - y) ** 2 for x, y in zip(r.witness_a, r.witness_b)) == 9
