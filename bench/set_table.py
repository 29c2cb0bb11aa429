#!/usr/bin/env python3
"""Prints the tables of cvms_set_bench's JSON output: the polygon and segment
sums with Sphere6 next to qhull's hull of their pairwise vertex sums (rows of
one run), and the zonotope rows with their output size, the exact hull fold
next to them, and the least-squares log-log slope of time against output
facets (2 would be quadratic in the output).
"""
import argparse
import math
import re

import bench_json


def sums_table(rows):
    """The sums with a flat operand, as markdown lines; rows = {name: (ms, entry)}."""
    lines = ["| sum | output F | cvms (ms) | qhull on the pairwise sums (ms) | qhull / cvms |",
             "|---|---:|---:|---:|---:|"]
    for label, ours, peer in [
        ("100-gon + Sphere6", "BM_PolygonPlusSphere6/100", "BM_QhullPolygonPlusSphere6/100"),
        ("1,000-gon + Sphere6", "BM_PolygonPlusSphere6/1000", None),
        ("segment + Sphere6", "BM_SegmentPlusSphere6", "BM_QhullSegmentPlusSphere6"),
    ]:
        if ours not in rows:
            continue
        o, entry = rows[ours]
        p = rows[peer][0] if peer in rows else None
        peer_text = f"{p:.1f}" if p else "—"
        ratio = f"{p / o:.1f}×" if p else "—"
        lines.append(f"| {label} | {int(entry['F']):,} | {o:.1f} | {peer_text} | {ratio} |")
    return lines


def zonotope_slope(rows):
    """Least-squares log-log slope of zonotope time against output facets, or None."""
    points = [(math.log(b["F"]), math.log(ms)) for name, (ms, b) in rows.items()
              if re.fullmatch(r"BM_Zonotope/\d+", name)]
    if len(points) < 2:
        return None
    mx = sum(x for x, _ in points) / len(points)
    my = sum(y for _, y in points) / len(points)
    return sum((x - mx) * (y - my) for x, y in points) / sum((x - mx) ** 2 for x, _ in points)


def zonotope_table(rows):
    """The zonotope rows against the fold by exact hulls, as markdown lines."""
    lines = ["| n | V | F | cvms zonotope (ms) | exact hull fold (ms) | fold / cvms |",
             "|---:|---:|---:|---:|---:|---:|"]
    names = sorted((n for n in rows if re.fullmatch(r"BM_Zonotope/\d+", n)), key=lambda n: int(n.split("/")[1]))
    for name in names:
        n = name.split("/")[1]
        z, entry = rows[name]
        fold = rows.get(f"BM_ZonotopeHullFold/{n}")
        fold_text = f"{fold[0]:.1f}" if fold else "—"
        ratio = f"{fold[0] / z:.1f}×" if fold else "—"
        lines.append(f"| {n} | {int(entry['V']):,} | {int(entry['F']):,} | {z:.2f} | {fold_text} | {ratio} |")
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("results", help="cvms_set_bench JSON output")
    bench_json.add_time_options(parser)
    args = parser.parse_args()
    rows = bench_json.rows(args.results, *bench_json.time_options(args))
    print("\n".join(sums_table(rows)))
    print()
    print("\n".join(zonotope_table(rows)))
    slope = zonotope_slope(rows)
    if slope is not None:
        print(f"\nlog-log slope of zonotope time against output facets (least squares): {slope:.2f}")
    if "BM_SumOfTenRandomHulls" in rows:
        ms, b = rows["BM_SumOfTenRandomHulls"]
        print(f"\nsum of 10 random 30-point hulls ({int(b['F']):,} facets): {ms:.1f} ms")


if __name__ == "__main__":
    main()
