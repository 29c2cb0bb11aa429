#!/usr/bin/env python3
"""Prints the tables of cvms_set_bench's JSON output (issue 15): the polygon
and segment sums with Sphere6 next to qhull's hull of their pairwise vertex
sums (rows of one run), and the zonotope rows with their output size, the
exact hull fold next to them, and the least-squares log-log slope of time
against output facets (2 would be quadratic in the output).

usage: bench/set_table.py results.json > sets.md
"""
import math
import re
import sys

import bench_json


def rows_by_name(path):
    return {b["name"]: b for b in bench_json.load(path)}


def ms(b):
    return bench_json.milliseconds(b, "real_time")


def sums_table(rows):
    print("| sum | output F | cvms (ms) | qhull on the pairwise sums (ms) | qhull / cvms |")
    print("|---|---:|---:|---:|---:|")
    for label, ours, peer in [
        ("100-gon + Sphere6", "BM_PolygonPlusSphere6/100", "BM_QhullPolygonPlusSphere6/100"),
        ("1,000-gon + Sphere6", "BM_PolygonPlusSphere6/1000", None),
        ("segment + Sphere6", "BM_SegmentPlusSphere6", "BM_QhullSegmentPlusSphere6"),
    ]:
        if ours not in rows:
            continue
        o = rows[ours]
        p = rows.get(peer) if peer else None
        peer_text = f"{ms(p):.1f}" if p else "—"
        ratio = f"{ms(p) / ms(o):.1f}×" if p else "—"
        print(f"| {label} | {int(o['F'])} | {ms(o):.1f} | {peer_text} | {ratio} |")


def zonotope_table(rows):
    print("| n | V | F | cvms zonotope (ms) | exact hull fold (ms) | fold / cvms |")
    print("|---:|---:|---:|---:|---:|---:|")
    points = []
    for name in sorted((n for n in rows if re.fullmatch(r"BM_Zonotope/\d+", n)), key=lambda n: int(n.split("/")[1])):
        n = name.split("/")[1]
        z = rows[name]
        fold = rows.get(f"BM_ZonotopeHullFold/{n}")
        fold_text = f"{ms(fold):.1f}" if fold else "—"
        ratio = f"{ms(fold) / ms(z):.1f}×" if fold else "—"
        print(f"| {n} | {int(z['V'])} | {int(z['F'])} | {ms(z):.2f} | {fold_text} | {ratio} |")
        points.append((math.log(z["F"]), math.log(ms(z))))
    if len(points) >= 2:
        mx = sum(x for x, _ in points) / len(points)
        my = sum(y for _, y in points) / len(points)
        slope = sum((x - mx) * (y - my) for x, y in points) / sum((x - mx) ** 2 for x, _ in points)
        print(f"\nlog-log slope of zonotope time against output facets (least squares): {slope:.2f}")


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    rows = rows_by_name(sys.argv[1])
    sums_table(rows)
    print()
    zonotope_table(rows)
    if "BM_SumOfTenRandomHulls" in rows:
        print(f"\nsum of 10 random 30-point hulls: {ms(rows['BM_SumOfTenRandomHulls']):.1f} ms")


if __name__ == "__main__":
    main()
