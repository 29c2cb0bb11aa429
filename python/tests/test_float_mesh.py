# SPDX-License-Identifier: MIT
"""Sets in doubles: cvms.write(s, path, float='nearest' | 'outer') and
cvms.to_float_mesh. The oracle is exact arithmetic on the doubles (taken as
the binary numbers they are, through Fraction): the outer mesh contains
every exact vertex, and the file holds the mesh's doubles."""

from fractions import Fraction

import numpy as np
import pytest

import cvms

THIRDS = [(0, 0, 0), (Fraction(1, 3), 0, 0), (0, Fraction(2, 7), 0), (Fraction(1, 7), Fraction(1, 9), Fraction(5, 3))]


def cross(u, v):
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def inside(positions, triangles, p):
    exact = [tuple(Fraction(float(c)) for c in row) for row in positions]
    for i, j, k in triangles:
        a, b, c = exact[i], exact[j], exact[k]
        n = cross(tuple(b[t] - a[t] for t in range(3)), tuple(c[t] - a[t] for t in range(3)))
        if sum(n[t] * (p[t] - a[t]) for t in range(3)) > 0:
            return False
    return True


def test_outer_mesh_contains_the_exact_set():
    s = cvms.hull(THIRDS) + cvms.geodesic_sphere(1)
    positions, triangles = cvms.to_float_mesh(s, "outer")
    assert positions.dtype == np.float64 and positions.shape[1] == 3
    assert triangles.dtype == np.uint32 and triangles.shape[1] == 3
    assert all(inside(positions, triangles, v) for v in s.exact_vertices())


def test_nearest_mesh_is_what_the_file_holds(tmp_path):
    s = cvms.hull(THIRDS)
    positions, triangles = cvms.to_float_mesh(s)
    for mode in [True, "nearest"]:
        cvms.write(s, tmp_path / "n.off", float=mode)
        lines = (tmp_path / "n.off").read_text().split("\n")
        count = int(lines[1].split()[0])
        written = np.array([[float(t) for t in line.split()] for line in lines[2:2 + count]])
        assert np.array_equal(written, positions)
    assert len(triangles) == 4


def test_bad_modes_are_refused(tmp_path):
    s = cvms.hull(THIRDS)
    with pytest.raises(ValueError):
        cvms.to_float_mesh(s, "inner")
    with pytest.raises(ValueError):
        cvms.write(s, tmp_path / "x.off", float="inner")
    with pytest.raises(TypeError):
        cvms.write(s, tmp_path / "x.off", float=1.5)
    with pytest.raises(cvms.Error):
        cvms.write(s, tmp_path / "x.stl", float="outer")
