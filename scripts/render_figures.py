#!/usr/bin/env python3
"""Renders the README's pictures from the cvms tool's own output files.

The tool computes everything (hulls, sums); this script only prepares exact
operands from the tool's output (a scale by a power of two, a reflection
x -> -x: exact rational arithmetic on the OFF text, with fractions) and draws
the OFF files the tool wrote, with matplotlib:

  docs/images/hull-ball.png  the convex hull of a real mesh (Keenan Crane's
                             "Spot", public domain; its path is an argument,
                             the mesh is not in the repository) summed with a
                             small ball (`cvms gen sphere`, scaled by 1/8),
                             beside the two operands;
  docs/images/cspace.png     a configuration-space obstacle A + (-B): an
                             obstacle A (`cvms gen random`) and a robot B (a
                             triangular prism from `cvms gen prism`, scaled and
                             moved off its reference point); the CLI sums, so
                             -B is B's OFF with every vertex negated (exact).

usage: scripts/render_figures.py --cvms build/release/tools/cvms --mesh /path/to/spot.obj
"""
import argparse
import os
import subprocess
import tempfile
from fractions import Fraction

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LIGHT = (0.35, -0.55, 0.76)


def read_off(path):
    """(vertices as Fractions, faces as index lists) of an OFF file the tool wrote."""
    with open(path) as f:
        tokens = [line.split("#")[0].split() for line in f]
    tokens = [t for t in tokens if t]
    if tokens[0][0] != "OFF":
        raise SystemExit(f"{path}: not an OFF file")
    nv, nf = int(tokens[1][0]), int(tokens[1][1])
    vertices = [tuple(Fraction(c) for c in t[:3]) for t in tokens[2:2 + nv]]
    faces = [[int(i) for i in t[1:1 + int(t[0])]] for t in tokens[2 + nv:2 + nv + nf]]
    return vertices, faces


def write_off(path, vertices, faces):
    def text(c):
        return str(c.numerator) if c.denominator == 1 else f"{c.numerator}/{c.denominator}"

    with open(path, "w") as f:
        f.write(f"OFF\n{len(vertices)} {len(faces)} 0\n")
        for v in vertices:
            f.write(" ".join(text(c) for c in v) + "\n")
        for face in faces:
            f.write(f"{len(face)} " + " ".join(map(str, face)) + "\n")


def transformed(src, dst, scale=Fraction(1), shift=(0, 0, 0), reflect=False):
    """Writes dst = (reflect ? -1 : 1) * (scale * src + shift), exactly."""
    vertices, faces = read_off(src)
    sign = -1 if reflect else 1
    moved = [tuple(sign * (scale * c + Fraction(s)) for c, s in zip(v, shift)) for v in vertices]
    # A reflection turns the faces' orientation around; the tool fixes it on reading.
    write_off(dst, moved, faces)


def cvms(tool, *args):
    subprocess.run([tool, *args], check=True, stdout=subprocess.DEVNULL)


def draw(ax, path, colour, alpha=1.0, edge="#1f1f1f", view=lambda p: p, linewidth=0.35):
    """Draws the polyhedron of an OFF file: faces shaded by a fixed light, their edges drawn."""
    vertices, faces = read_off(path)
    points = [view(tuple(float(c) for c in v)) for v in vertices]
    centre = [sum(p[i] for p in points) / len(points) for i in range(3)]
    polygons, colours = [], []
    base = matplotlib.colors.to_rgb(colour)
    for face in faces:
        poly = [points[i] for i in face]
        a, b, c = poly[0], poly[1], poly[2]
        u = [b[i] - a[i] for i in range(3)]
        w = [c[i] - a[i] for i in range(3)]
        n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
        length = sum(x * x for x in n) ** 0.5 or 1.0
        n = [x / length for x in n]
        # Outward for a convex polyhedron: away from its centre.
        if sum(n[i] * (a[i] - centre[i]) for i in range(3)) < 0:
            n = [-x for x in n]
        light = max(0.0, sum(n[i] * LIGHT[i] for i in range(3)))
        shade = 0.38 + 0.62 * light
        colours.append((*[min(1.0, x * shade + 0.08) for x in base], alpha))
        polygons.append(poly)
    ax.add_collection3d(Poly3DCollection(polygons, facecolors=colours, edgecolors=edge, linewidths=linewidth))
    return points


def frame(ax, points, title, azim=-60, elev=18):
    lo = [min(p[i] for p in points) for i in range(3)]
    hi = [max(p[i] for p in points) for i in range(3)]
    mid = [(a + b) / 2 for a, b in zip(lo, hi)]
    half = max(b - a for a, b in zip(lo, hi)) / 2 * 1.02
    ax.set_xlim(mid[0] - half, mid[0] + half)
    ax.set_ylim(mid[1] - half, mid[1] + half)
    ax.set_zlim(mid[2] - half, mid[2] + half)
    ax.set_box_aspect((1, 1, 1), zoom=1.3)
    ax.set_axis_off()
    ax.set_title(title, fontsize=10, pad=0)
    ax.view_init(elev=elev, azim=azim)


def hull_ball(tool, mesh, scratch, output):
    hull, sphere, ball, total = (os.path.join(scratch, n) for n in ("hull.off", "sphere.off", "ball.off", "sum.off"))
    cvms(tool, "hull", mesh, "-o", hull)
    cvms(tool, "gen", "sphere", "--subdivisions", "3", "-o", sphere)
    transformed(sphere, ball, scale=Fraction(1, 8))
    cvms(tool, "sum", hull, ball, "-o", total)

    def upright(p):  # the mesh's y axis is its up
        return (p[0], -p[2], p[1])

    fig = plt.figure(figsize=(8, 4), dpi=100)
    sum_axes = fig.add_subplot(1, 3, 3, projection="3d")
    extent = draw(sum_axes, total, "#d9822b", view=upright, linewidth=0.15)
    for index, (path, colour, title, width) in enumerate(
            ((hull, "#4a7ab5", "A: convex hull of a mesh", 0.2), (ball, "#5aa469", "B: a ball of radius 1/8", 0.3))):
        ax = fig.add_subplot(1, 3, index + 1, projection="3d")
        draw(ax, path, colour, view=upright, linewidth=width)
        frame(ax, extent, title, azim=-25, elev=12)  # one scale for all three
    frame(sum_axes, extent, "A ⊕ B (exact)", azim=-25, elev=12)
    fig.suptitle("Minkowski sum of the convex hull of Spot and a ball", fontsize=12)
    fig.subplots_adjust(left=0, right=1, bottom=0, top=0.88, wspace=0)
    fig.savefig(output, dpi=100)
    plt.close(fig)


def cspace(tool, scratch, output):
    obstacle, prism, robot, reflected, total = (
        os.path.join(scratch, n) for n in ("obstacle.off", "prism.off", "robot.off", "minus_robot.off", "cspace.off"))
    cvms(tool, "gen", "random", "--points", "40", "--seed", "7", "-o", obstacle)
    cvms(tool, "gen", "prism", "--points", "3", "-o", prism)
    # The robot; its reference point, the origin, is inside it but off its centre, so -B is not B.
    transformed(prism, robot, scale=Fraction(256), shift=(100, 0, 0))
    transformed(prism, reflected, scale=Fraction(256), shift=(100, 0, 0), reflect=True)
    cvms(tool, "sum", obstacle, reflected, "-o", total)

    fig = plt.figure(figsize=(8, 4), dpi=100)
    left = fig.add_subplot(1, 2, 1, projection="3d")
    points = draw(left, obstacle, "#4a7ab5", linewidth=0.4)
    aside = 2200  # B is drawn moved aside, its reference point with it

    def moved(p):
        return (p[0] + aside, p[1], p[2])

    points += draw(left, robot, "#5aa469", linewidth=0.6, view=moved)
    left.computed_zorder = False
    left.scatter([aside], [0], [1.05 * 256], color="black", s=14, depthshade=False, zorder=5)
    frame(left, points, "obstacle A and robot B (• its reference point)")
    right = fig.add_subplot(1, 2, 2, projection="3d")
    # A drawn first and the translucent sum over it, whatever their depths.
    right.computed_zorder = False
    draw(right, obstacle, "#4a7ab5", linewidth=0.3)
    extent = draw(right, total, "#d9822b", alpha=0.45, edge="#5a3a10", linewidth=0.3)
    frame(right, extent, "C-space obstacle A ⊕ (−B)")
    fig.suptitle("B's reference point collides with A exactly when it is inside A ⊕ (−B)", fontsize=11)
    fig.subplots_adjust(left=0, right=1, bottom=0, top=0.88, wspace=0)
    fig.savefig(output, dpi=100)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--cvms", default=os.path.join(ROOT, "build", "release", "tools", "cvms"),
                        help="the release tool (default: %(default)s)")
    parser.add_argument("--mesh", required=True,
                        help="the mesh whose hull is summed with a ball (the README's picture uses Spot's OBJ)")
    parser.add_argument("--out-dir", default=os.path.join(ROOT, "docs", "images"),
                        help="where the PNGs go (default: %(default)s)")
    args = parser.parse_args()
    matplotlib.rcParams["font.family"] = "DejaVu Sans"
    os.makedirs(args.out_dir, exist_ok=True)
    with tempfile.TemporaryDirectory() as scratch:
        hull_ball(args.cvms, args.mesh, scratch, os.path.join(args.out_dir, "hull-ball.png"))
        cspace(args.cvms, scratch, os.path.join(args.out_dir, "cspace.png"))


if __name__ == "__main__":
    main()
