#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Writes the binary seed inputs of test/fuzz/corpus/ (the text seeds are
# plain files). The byte layouts are the decoders of
# test/support/fuzz_targets.cpp: keep the two in step.
import os
import random
import struct

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")


def coord(num, den=1):
    """One byte that decode_coordinate maps to num/den (num in -15..16)."""
    sel = {1: 0, 2: 5, 3: 6, 4: 7}[den]
    assert -15 <= num <= 16
    return (num + 15) | (sel << 5)


def cloud(points):
    return bytes(coord(*c) if isinstance(c, tuple) else coord(c) for p in points for c in p)


def write(target, name, data):
    with open(os.path.join(HERE, target, name), "wb") as f:
        f.write(data)


CUBE = [(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)]
TETRA = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
OCTA = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]


def binary_stl(triangles, header=b"binary seed"):
    out = header.ljust(80, b"\0") + struct.pack("<I", len(triangles))
    for t in triangles:
        out += struct.pack("<3f", 0, 0, 0)
        for p in t:
            out += struct.pack("<3f", *p)
        out += b"\0\0"
    return out


def binary_ply(order, points, faces, coordinate="d"):
    fmt = "binary_little_endian" if order == "<" else "binary_big_endian"
    kind = "double" if coordinate == "d" else "float"
    header = ("ply\nformat %s 1.0\nelement vertex %d\nproperty %s x\nproperty %s y\nproperty %s z\n"
              "element face %d\nproperty list uchar int vertex_indices\nend_header\n"
              % (fmt, len(points), kind, kind, kind, len(faces))).encode()
    body = b"".join(struct.pack(order + "3" + coordinate, *p) for p in points)
    body += b"".join(struct.pack(order + "B%di" % len(f), len(f), *f) for f in faces)
    return header + body


def main():
    rng = random.Random(6)
    # read_ply: binary tetrahedra in both byte orders, doubles and floats
    # (the ASCII seeds are plain files).
    tetra_faces = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
    write("read_ply", "tetra_le_double.ply", binary_ply("<", [(0.1, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1e-300)], tetra_faces))
    write("read_ply", "tetra_be_float.ply", binary_ply(">", TETRA, tetra_faces, "f"))
    # read_stl: a binary tetrahedron, a binary cube (12 triangles), a binary
    # file with a degenerate (repeated vertex) triangle and a tiny float.
    t = TETRA
    write("read_stl", "tetra_binary.stl",
          binary_stl([(t[0], t[2], t[1]), (t[0], t[1], t[3]), (t[0], t[3], t[2]), (t[1], t[2], t[3])]))
    quads = [((0, 0, 0), (0, 1, 0), (1, 1, 0), (1, 0, 0)), ((0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)),
             ((0, 0, 0), (1, 0, 0), (1, 0, 1), (0, 0, 1)), ((0, 1, 0), (0, 1, 1), (1, 1, 1), (1, 1, 0)),
             ((0, 0, 0), (0, 0, 1), (0, 1, 1), (0, 1, 0)), ((1, 0, 0), (1, 1, 0), (1, 1, 1), (1, 0, 1))]
    write("read_stl", "cube_binary.stl", binary_stl([tri for q in quads for tri in ((q[0], q[1], q[2]), (q[0], q[2], q[3]))]))
    write("read_stl", "degenerate_binary.stl",
          binary_stl([((0, 0, 0), (0, 0, 0), (1, 0, 0)), ((1e-45, 0, 0), (0.1, 0.2, 0.3), (-0.0, 3e38, 1))]))

    # from_soup, edited-hull mode (mode bit 0 = 1): count byte, points, flags, edits.
    write("from_soup", "hull_cube.bin", bytes([1, 4]) + cloud(CUBE) + bytes([0, 0]))
    # triangulated from varied corners, globally flipped, an edge split (op 3)
    # and a face centroid fan (op 4): all repairable.
    write("from_soup", "hull_cube_repairs.bin",
          bytes([1, 4]) + cloud(CUBE) + bytes([3, 0, 1, 2, 3, 0, 1, 2]) + bytes([3, 1, 2, 1, 4, 3, 0]))
    # a moved vertex (op 0) and a flipped face (op 1): rejected
    write("from_soup", "hull_octa_broken.bin",
          bytes([1, 2]) + cloud(OCTA) + bytes([0, 2, 0, 2, 1, 3, 4, 1, 1, 5, 0]))
    # grid coordinates (mode bit 1): 24 points of {-2..2}^3, many coplanar
    write("from_soup", "hull_grid.bin", bytes([3, 20]) + bytes(rng.randrange(256) for _ in range(72)) + bytes([1, 0]))
    # raw mode (mode bit 0 = 0): count byte, points, then faces (degree byte, indices)
    tetra_faces = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
    write("from_soup", "raw_tetra.bin",
          bytes([0, 3]) + cloud(TETRA) + b"".join(bytes([0, *f]) for f in tetra_faces))
    octa_faces = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 5, 3)]
    write("from_soup", "raw_octa_flipped_face.bin",
          bytes([0, 5]) + cloud(OCTA) + b"".join(bytes([0, *f]) for f in octa_faces))
    # a square pyramid with a quad base (degree byte 1 = 4 corners)
    pyr = [(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0), (1, 1, 2)]
    write("from_soup", "raw_pyramid_quad.bin",
          bytes([0, 4]) + cloud(pyr) + bytes([1, 0, 3, 2, 1]) +
          b"".join(bytes([0, a, b, 4]) for a, b in ((0, 1), (1, 2), (2, 3), (3, 0))))

    # hull mode with tiny moves (bit 2) and an extreme scale (bit 3): two
    # cube corners moved by 2^-50, then everything scaled by 2^(8 * -100).
    write("from_soup", "hull_cube_tiny_moves_tiny_scale.bin",
          bytes([13, 4]) + cloud(CUBE) + bytes([3, 30, 0, 0, 0, 0, 0, 0, 9, 30, 0]) + bytes([256 - 100]) + bytes([0, 0]))
    write("from_soup", "hull_octa_huge_scale.bin", bytes([9, 2]) + cloud(OCTA) + bytes([126]) + bytes([1, 0]))

    # minkowski, bit 3: tiny moves of both clouds, then an extreme scale.
    write("minkowski", "cube_tetra_huge.bin",
          bytes([8, 4]) + cloud(CUBE) + bytes([0]) + cloud(TETRA) + bytes(12) + bytes([127]))
    write("minkowski", "cube_minus_cube_nearly.bin",
          bytes([10, 4]) + cloud(CUBE) + bytes([1, 40, 0, 0, 3, 45, 0, 0, 5, 59] + [0] * 6) + bytes([256 - 128]))

    # minkowski: mode (bit 0 grid, bits 1-2: B independent / -A / scaled A / subset of A,
    # bit 3: tiny moves and an extreme scale)
    write("minkowski", "cube_tetra.bin", bytes([0, 4]) + cloud(CUBE) + bytes([0]) + cloud(TETRA))
    write("minkowski", "cube_minus_cube.bin", bytes([2, 4]) + cloud(CUBE))
    write("minkowski", "octa_scaled.bin", bytes([4, 2]) + cloud(OCTA) + bytes([1, 1]) + cloud([(3, -2, (1, 2))]))
    write("minkowski", "tetra_minus_tetra.bin", bytes([2, 0]) + cloud(TETRA))
    write("minkowski", "grid_subset.bin",
          bytes([7, 16]) + bytes(rng.randrange(256) for _ in range(60)) + bytes(rng.randrange(256) for _ in range(25)))
    write("minkowski", "random_wide.bin",
          bytes([0, 26]) + bytes(rng.randrange(256) for _ in range(90)) + bytes([26]) +
          bytes(rng.randrange(256) for _ in range(90)))
    pts = [(rng.randint(-3, 3), rng.randint(-3, 3), rng.choice([-1, 0, 1])) for _ in range(12)]
    write("minkowski", "flat_ish_prisms.bin", bytes([0, 8]) + cloud(pts) + bytes([8]) + cloud(pts[::-1]))
    sets_seeds()
    halfspace_seeds()


def grid(points):
    """Grid points (coordinates -2..2) as decode_point(grid=True) reads them."""
    return bytes(c + 2 for p in points for c in p)


def sets_seeds():
    """sets: two sets, each [mode, count - 1, points, flattening bytes]; mode
    bits 0-1: solid, plane z = (p x + q y) / 2 + r, line o + x d, point; bit 2:
    rational coordinates (coord) instead of the grid."""
    os.makedirs(os.path.join(HERE, "sets"), exist_ok=True)
    square = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
    tri = [(-2, 0, 0), (2, -1, 0), (0, 2, 0)]
    def solid(points): return bytes([0, len(points) - 1]) + grid(points)
    def plane(points, p, q, r): return bytes([1, len(points) - 1]) + grid(points) + bytes([p + 2, q + 2, coord(r)])
    def line(points, d): return bytes([2, len(points) - 1]) + grid(points) + grid([d])
    def point(p): return bytes([3, 0]) + grid([p])
    write("sets", "cube_square.bin", solid(CUBE) + plane(square, 0, 0, 0))
    write("sets", "cube_tilted_triangle.bin", solid(CUBE) + plane(tri, 1, -1, 1))
    write("sets", "square_parallel_square.bin", plane(square, 0, 0, 0) + plane(tri, 0, 0, 2))
    write("sets", "polygons_skew.bin", plane(square, 2, 0, 0) + plane(tri, 0, -2, 1))
    write("sets", "segment_cube.bin", line([(0, 0, 0), (2, 0, 0)], (1, 1, 0)) + solid(CUBE))
    write("sets", "segment_along_edge.bin", line([(0, 0, 0), (1, 0, 0)], (1, 0, 0)) + solid(CUBE))
    write("sets", "segments_skew.bin", line([(0, 0, 0), (1, 0, 0)], (1, 2, 0)) + line([(0, 0, 0), (1, 0, 0)], (0, 1, 2)))
    write("sets", "segment_in_polygon_plane.bin", line([(0, 0, 0), (2, 0, 0)], (1, -1, 0)) + plane(tri, 0, 0, 0))
    write("sets", "point_tetra.bin", point((1, -1, 2)) + solid(TETRA))
    write("sets", "octa_rational_plane.bin", solid(OCTA) + bytes([5, 3]) + cloud([(1, 0, 0), (0, (1, 3), 0), (-1, 0, 0), (0, -1, 0)]) +
          bytes([3, 1, coord(1, 2)]))


def halfspace_seeds():
    """read_halfspaces: a mode byte (0 cdd H, 1 plain, 2 cdd V) and the text.
    halfspaces: [mode, box radius byte if mode bit 0, row count, rows, scale
    byte if mode bit 3] then a set B as in sets_seeds. A row is [op, earlier
    row index (from the second row on)] and then: for a new row (op % 8 < 4,
    and always the first) its normal (grid or coord bytes by mode bit 1) and
    offset coord; op 4 (earlier scaled) two bytes; op 5 (opposite) a slack
    byte; op 6 (zero row) an offset coord; op 7 (tiny move) two bytes."""
    for target in ("read_halfspaces", "halfspaces"):
        os.makedirs(os.path.join(HERE, target), exist_ok=True)
    cube_ine = ("H-representation\nbegin\n6 4 integer\n1 -1 0 0\n1 1 0 0\n1 0 -1 0\n1 0 1 0\n"
                "1 0 0 -1\n1 0 0 1\nend\n")
    write("read_halfspaces", "cube.ine", b"\0" + cube_ine.encode())
    square_ine = "* a square in z = 0\nlinearity 1 1\nbegin\n5 4 rational\n0 0 0 1\n1 -1 0 0\n1 1 0 0\n1/2 0 -1 0\n1/2 0 1 0\nend\n"
    write("read_halfspaces", "square_linearity.ine", b"\0" + square_ine.encode())
    cross_ine = ("begin\n10 4 real\n" + "".join(f"1 {a} {b} {c}\n" for a in (-1, 1) for b in (-1, 1) for c in (-1, 1)) +
                 "2.5 -1 0 0\n1e1 0 0 1\nend\nmaximize\n0 1 1 1\n")
    write("read_halfspaces", "octahedron_redundant.ine", b"\0" + cross_ine.encode())
    write("read_halfspaces", "cube.txt", b"\1" + b"1 0 0 1\n-1 0 0 1\n0 1 0 1\n0 -1 0 1\n0 0 1 1\n0 0 -1 1  # top\n")
    write("read_halfspaces", "unbounded.txt", b"\1" + b"1 0 0 1\n0 1 0 1\n0 0 1 1\n")
    write("read_halfspaces", "empty.txt", b"\1" + b"1 0 0 -1\n-1 0 0 -1\n0 1 0 1\n0 -1 0 1\n0 0 1 1\n0 0 -1 1\n")
    write("read_halfspaces", "tetra.ext", b"\2" + b"V-representation\nbegin\n4 4 rational\n1 0 0 0\n1 1 0 0\n1 0 1 0\n1 0 0 1/3\nend\n")

    def row(normal, offset, first=False):  # a new row on the grid
        return bytes([0] + ([] if first else [0])) + grid([normal]) + bytes([coord(offset)])
    cube_b = bytes([0, len(CUBE) - 1]) + grid(CUBE)
    point_b = bytes([3, 0]) + grid([(1, 0, -1)])
    segment_b = bytes([2, 1]) + grid([(0, 0, 0), (1, 0, 0)]) + grid([(1, 1, 0)])
    square_b = bytes([1, 3]) + grid([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]) + bytes([2, 2, coord(0)])
    write("halfspaces", "box_point.bin", bytes([1, 1, 0]) + point_b)
    write("halfspaces", "box_cut_cube.bin", bytes([3, 2, 1]) + row((1, 1, 1), 1, True) + cube_b)
    # z <= 0 and its opposite (slack byte 2: slack 0): the square z = 0 of the box
    write("halfspaces", "implied_equality_segment.bin", bytes([3, 1, 2]) + row((0, 0, 1), 0, True) + bytes([5, 0, 2]) + segment_b)
    write("halfspaces", "unbounded_octant.bin",
          bytes([2, 3]) + row((1, 0, 0), 1, True) + row((0, 1, 0), 1) + row((0, 0, 1), 1) + point_b)
    write("halfspaces", "empty_box.bin", bytes([3, 0, 1]) + row((0, 0, 1), -5, True) + point_b)
    # a row, the same scaled, a zero row, a tiny move of the first, an extreme scale
    write("halfspaces", "scaled_zero_tiny_extreme.bin",
          bytes([11, 3, 4]) + row((1, 1, 0), 1, True) + bytes([4, 0, 2, 1, 6, 0, coord(2), 7, 0, 5, 30, 0x80 + 1]) + square_b)
    write("halfspaces", "equality_first.bin", bytes([5, 1, 1]) + bytes([0, coord(1), coord(0), coord(-1), coord(1)]) + square_b)


if __name__ == "__main__":
    main()
