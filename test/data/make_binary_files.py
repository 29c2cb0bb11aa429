#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Regenerates the committed binary test inputs (binary STL and junk files).
# Deterministic: run it from test/data to reproduce the files byte for byte.
import random
import struct


def triangle(normal, a, b, c):
    return struct.pack("<12fH", *normal, *a, *b, *c, 0)


def stl(header, count, records):
    header = header.ljust(80, b"\0")[:80]
    return header + struct.pack("<I", count) + b"".join(records)


F32_MAX = 3.4028234663852886e38
DENORM_MIN = 2.0 ** -149
p0, p0_neg_zero = (0.1, 0.0, 0.0), (0.1, -0.0, -0.0)
p1, p2, p3 = (1.0, 0.0, 0.0), (DENORM_MIN, 1.5, 0.0), (0.0, 0.0, F32_MAX)
nan = float("nan")
tetra = [
    triangle((0, 0, -1), p0, p2, p1),
    triangle((nan, nan, nan), p0_neg_zero, p1, p3),
    triangle((-1, 0, 0), p0, p3, p2),
    triangle((1, 1, 1), p1, p2, p3),
]

files = {
    # good: a binary STL whose header starts with "solid", as many exporters write
    "tetra_binary_solid_header.stl": stl(b"solid this is binary nevertheless", 4, tetra),
    # bad: header says 10 triangles, holds 2
    "bad/binary_count_mismatch.stl": stl(b"exporter", 10, tetra[:2]),
    # bad: header says 1 triangle, holds 2
    "bad/binary_trailing_bytes.stl": stl(b"exporter", 1, tetra[:2]),
    # bad: a NaN coordinate in the second vertex of triangle 1
    "bad/binary_nan.stl": stl(b"exporter", 2, [tetra[0], triangle((0, 0, 1), p1, (0.0, nan, 0.0), p3)]),
    # bad: an infinite coordinate
    "bad/binary_inf.stl": stl(b"exporter", 1, [triangle((0, 0, 1), (float("inf"), 0.0, 0.0), p1, p2)]),
    # bad: 4 billion triangles declared in a 134-byte file
    "bad/binary_lying_count.stl": stl(b"exporter", 0xFFFFFFFF, tetra[:1]),
    # bad: shorter than a binary header and not ASCII
    "bad/short_binary.stl": bytes(range(1, 41)),
    # bad: "solid" header, binary content, count does not match the size
    "bad/solid_header_count_mismatch.stl": stl(b"solid but binary", 7, tetra),
}



def ply_le(points, faces):
    header = (b"ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
              b"property float z\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n"
              % (len(points), len(faces)))
    body = b"".join(struct.pack("<3f", *p) for p in points)
    body += b"".join(struct.pack("<B%di" % len(f), len(f), *f) for f in faces)
    return header + body


ply_tetra_points = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)]
ply_tetra_faces = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
ply_tetra = ply_le(ply_tetra_points, ply_tetra_faces)
ply_header_size = ply_tetra.index(b"end_header\n") + len(b"end_header\n")
# bad: cut in the middle of the z coordinate of vertex 2
files["bad/ply_binary_truncated.ply"] = ply_tetra[:ply_header_size + 2 * 12 + 10]
# bad: a NaN x coordinate in vertex 1
files["bad/ply_binary_nan.ply"] = ply_le([ply_tetra_points[0], (nan, 0.0, 0.0)] + ply_tetra_points[2:], ply_tetra_faces)

rng = random.Random(20240611)
junk = bytes(rng.randrange(256) for _ in range(1000))
for ext in ("off", "obj", "stl"):
    files["bad/binary_junk." + ext] = junk

for name, data in files.items():
    with open(name, "wb") as f:
        f.write(data)
