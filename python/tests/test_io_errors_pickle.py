# SPDX-License-Identifier: MIT
"""Files, the C++ command-line tool on the same files, errors, pickling."""

import pickle
import subprocess
from fractions import Fraction

import pytest

import cvms

SKEW = [(0, 0, 0), (1, 2, 0), (-1, 1, 1), (0, -1, 2), (Fraction(1, 3), 0, -1)]


def test_write_and_read_back_exactly(tmp_path):
    s = cvms.hull(SKEW)
    for name in ["s.off", "s.obj"]:
        cvms.write(s, str(tmp_path / name))
        assert cvms.read(str(tmp_path / name)) == s
    cvms.write(s, str(tmp_path / "f.off"), float=True)
    rounded = cvms.read(str(tmp_path / "f.off"))
    assert rounded != s  # 1/3 became the decimal of its nearest double
    assert all(Fraction(str(float(Fraction(1, 3)))) in v or Fraction(1, 3) not in w
               for v, w in zip(sorted(rounded.exact_vertices()), sorted(s.exact_vertices())))
    for flat in [cvms.hull([(0, 0, 0), (1, 0, 0)]), cvms.hull([(0, 0, 0), (1, 0, 0), (0, 1, 0)]),
                 cvms.hull([(1, 2, 3)])]:
        cvms.write(flat, str(tmp_path / "flat.off"))
        assert cvms.read(str(tmp_path / "flat.off")) == flat
    (tmp_path / "points.xyz").write_text("0 0 0\n1 0 0\n0 1 0\n0 0 0.5\n")
    assert cvms.read(str(tmp_path / "points.xyz")).volume() == Fraction(1, 12)


def test_ply_is_exact_decimals_or_binary_doubles(tmp_path):
    third = cvms.hull([(0, 0, 0), (Fraction(1, 3), 0, 0), (0, 1, 0), (0, 0, 1)])
    with pytest.raises(cvms.Error) as info:  # 1/3 has no decimal, and PLY no p/q
        cvms.write(third, str(tmp_path / "third.ply"))
    assert info.value.category == "invalid_argument"
    cvms.write(third, str(tmp_path / "third.ply"), float=True)  # binary doubles, read back as such
    assert sorted(cvms.read(str(tmp_path / "third.ply")).exact_vertices()) == sorted(
        tuple(Fraction(float(c)) for c in v) for v in third.exact_vertices())
    decimal = cvms.hull([(0, 0, 0), (Fraction(1, 10), 0, 0), (0, 2, 0), (0, 0, Fraction(-5, 4))])
    cvms.write(decimal, str(tmp_path / "decimal.ply"))
    assert cvms.read(str(tmp_path / "decimal.ply")) == decimal


def test_errors_carry_category_and_message(tmp_path):
    with pytest.raises(cvms.Error) as info:
        cvms.read(str(tmp_path / "missing.off"))
    assert info.value.category == "io"
    assert "missing.off" in info.value.message
    assert str(info.value).startswith("io: ")
    assert isinstance(info.value, ValueError)
    (tmp_path / "bad.off").write_text("OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\nx 0 0\n3 0 1 2\n")
    with pytest.raises(cvms.Error) as info:
        cvms.read(str(tmp_path / "bad.off"))
    assert info.value.category == "parse"
    # a polygon with a reflex corner at (1, 1)
    with pytest.raises(cvms.Error) as info:
        cvms.from_off("OFF\n4 1 0\n0 0 0\n2 0 0\n1 1 0\n1 3 0\n4 0 1 2 3\n")
    assert info.value.category == "not_convex"
    with pytest.raises(cvms.Error) as info:
        cvms.hull([("0.1x", 0, 0)])
    assert info.value.category == "parse"
    with pytest.raises(cvms.Error) as info:
        cvms.hull([(float("nan"), 0, 0)])
    assert info.value.category == "invalid_argument"
    with pytest.raises(cvms.Error):
        cvms.hull([(1, 2)])
    with pytest.raises(cvms.Error):
        cvms.write(cvms.hull([(0, 0, 0)]), str(tmp_path / "p.stl"))
    with pytest.raises(TypeError):
        cvms.hull([(object(), 0, 0)])
    with pytest.raises(TypeError):
        cvms.minkowski_sum(cvms.cube(), "not a set")
    with pytest.raises(cvms.Error):
        cvms.minkowski_sum(cvms.cube(), cvms.cube(), algorithm="fast")


def test_pickle_is_exact():
    sets = [cvms.hull(SKEW), cvms.hull([(Fraction(1, 3**80), 0, 0), (0, 2**100, 0)]), cvms.ConvexSet(),
            cvms.hull([(0, 0, 0), (1, 0, 0), (1, 1, 1)]), cvms.hull([("0.1", "0.2", "0.3")])]
    for s in sets:
        for protocol in range(pickle.HIGHEST_PROTOCOL + 1):
            back = pickle.loads(pickle.dumps(s, protocol))
            assert back == s
            assert back.exact_vertices() == s.exact_vertices()
    assert cvms.from_off(sets[0].to_off()) == sets[0]


def parse_cli(text):
    out = {}
    for line in text.splitlines():
        key, _, value = line.partition(" ")
        out[key] = value.split()
    return out


def test_the_command_line_tool_agrees(cli, tmp_path):
    a, b = cvms.hull(SKEW), cvms.tetrahedron().translated((3, Fraction(1, 7), 0))
    cvms.write(a, str(tmp_path / "a.off"))
    cvms.write(b, str(tmp_path / "b.off"))
    subprocess.run([cli, "sum", str(tmp_path / "a.off"), str(tmp_path / "b.off"), "-o", str(tmp_path / "s.off")],
                   check=True)
    assert cvms.read(str(tmp_path / "s.off")) == a + b
    out = parse_cli(subprocess.run([cli, "distance", str(tmp_path / "a.off"), str(tmp_path / "b.off")],
                                   check=True, capture_output=True, text=True).stdout)
    r = cvms.squared_distance(a, b)
    assert Fraction(out["squared_distance"][0]) == r.squared_distance
    assert float(out["distance"][0]) == cvms.distance(a, b)
    c = b.translated((-2, 0, 0))
    cvms.write(c, str(tmp_path / "c.off"))
    out = parse_cli(subprocess.run([cli, "penetration", str(tmp_path / "a.off"), str(tmp_path / "c.off")],
                                   check=True, capture_output=True, text=True).stdout)
    p = cvms.penetration(a, c)
    assert p.intersect and out["intersect"] == ["yes"]
    assert Fraction(out["squared_depth"][0]) == p.squared_depth
    assert tuple(int(x) for x in out["direction"]) == p.direction
    subprocess.run([cli, "gen", "sphere", "--subdivisions", "2", "-o", str(tmp_path / "s2.off")], check=True)
    assert cvms.read(str(tmp_path / "s2.off")) == cvms.geodesic_sphere(2)
