#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes the tangent planes of a sphere as a cdd H-representation (.ine).

The sphere has centre (cx, 0, 0) and radius 1; with cx > 1 it does not
contain the origin, so `cvms hull --from-halfspaces` cannot take the origin
as its interior point and runs the max-slack LP. The normals are exact
rational points of the unit sphere (inverse stereographic projection of
grid points), so every row is exact: n.x <= n.c + 1.

--order sorted writes the rows sorted by their normals (x, then y, then
z), so the planes farthest from the origin (the most negative right-hand
sides) come first and neighbouring rows are neighbouring planes: a pivoting
rule that prefers low row indices then walks over the sphere one plane at
a time. --order shuffled writes the same rows in a
random order (--seed).
"""
import argparse
import math
import random
import sys
from fractions import Fraction


def normals(count):
    """About `count` distinct rational unit vectors spread over the sphere."""
    side = max(2, int(math.ceil(math.sqrt(count))))
    seen, out = set(), []
    for i in range(side):
        for j in range(side):
            # Grid points of the plane; the projection covers the sphere.
            a = Fraction(4 * i - 2 * side, side) + Fraction(1, 2 * side + 1)
            b = Fraction(4 * j - 2 * side, side) + Fraction(1, 3 * side + 1)
            s = 1 + a * a + b * b
            n = (2 * a / s, 2 * b / s, (1 - a * a - b * b) / s)
            if n not in seen:
                seen.add(n)
                out.append(n)
            if len(out) == count:
                return out
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--rows", type=int, default=5000, help="number of planes (default 5000)")
    parser.add_argument("--centre", type=int, default=3, help="x of the sphere's centre (default 3)")
    parser.add_argument("--order", choices=["sorted", "shuffled"], default="sorted")
    parser.add_argument("--seed", type=int, default=1, help="seed of --order shuffled")
    args = parser.parse_args()
    rows = normals(args.rows)
    if args.order == "sorted":
        rows.sort()
    else:
        random.Random(args.seed).shuffle(rows)
    out = sys.stdout
    out.write("H-representation\nbegin\n%d 4 rational\n" % len(rows))
    for n in rows:
        b = n[0] * args.centre + 1  # n.x <= n.c + 1, cdd: b - n.x >= 0
        out.write("%s %s %s %s\n" % (b, -n[0], -n[1], -n[2]))
    out.write("end\n")


if __name__ == "__main__":
    main()
