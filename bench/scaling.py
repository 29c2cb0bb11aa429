#!/usr/bin/env python3
"""Prints the scaling tables of cvms_minkowski_bench's JSON output: for the
families Sphere_k + rotated Sphere_k (SphereRot) and Cube + Sphere_k
(CubeSphere), per k the output facet count, each algorithm's time and time
per output facet, the ratios CVMS / limit (the output-mesh build alone) and
peer / CVMS, and per algorithm the log-log slope of time against output
facets, from k = 3 to the largest k present for that algorithm (endpoint
slope) and the least-squares slope over all k.

Output facets are those of the exact sum (from our rows); the peers' rows
are matched to them by family and k.
"""
import argparse
import math

import bench_json

FAMILIES = {"SphereRot": "Sphere_k + rotated Sphere_k", "CubeSphere": "Cube + Sphere_k"}
# Benchmark name prefix (before "_<family>/k") -> column.
ALGORITHMS = [
    ("BM_CVMS", "CVMS"), ("BM_CVMS_2threads", "CVMS_2threads"), ("BM_CVMS_paper", "CVMS_paper"), ("BM_Limit_Mesh", "limit mesh"),
    ("BM_Limit_Build", "limit build"), ("BM_Qhull", "qhull"), ("BM_CGAL", "CGAL"),
]
LIMITS = ["limit mesh", "limit build"]
PEERS = ["qhull", "CGAL"]


def load(path, time_field="real_time", statistic="median"):
    """times[family][algorithm][k] = ms; out[family][k] = (input, output facets); peaks likewise."""
    names = {f"{prefix}_{family}": (family, column) for family in FAMILIES for prefix, column in ALGORITHMS}
    times = {f: {} for f in FAMILIES}
    peaks = {f: {} for f in FAMILIES}
    facets = {f: {} for f in FAMILIES}
    for prefix, k, ms, b in bench_json.runs(path, time_field, statistic):
        if prefix not in names:
            continue
        family, column = names[prefix]
        times[family].setdefault(column, {})[k] = ms
        if "peak_heap_bytes" in b:
            peaks[family].setdefault(column, {})[k] = b["peak_heap_bytes"]
        if "output_facets" in b:
            facets[family][k] = (int(b.get("input_facets", 0)), int(b["output_facets"]))
    return times, peaks, facets


def slopes(series, facets):
    """(endpoint slope from k = 3 to the largest k, least-squares slope, largest k) of log time vs log facets."""
    ks = sorted(k for k in series if k in facets and k >= 3)
    if len(ks) < 2 or ks[0] != 3:
        return None
    xs = [math.log(facets[k][1]) for k in ks]
    ys = [math.log(series[k]) for k in ks]
    endpoint = (ys[-1] - ys[0]) / (xs[-1] - xs[0])
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    fit = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
    return endpoint, fit, ks[-1]


def family_table(times, peaks, facets):
    """One family's times, times per output facet and ratios as markdown lines."""
    lines = []
    columns = [c for _, c in ALGORITHMS if c in times]
    if not columns:
        return lines
    ks = sorted(set(k for c in columns for k in times[c]))
    header = ["k", "facets in", "facets out"]
    header += [f"{c} (ms)" for c in columns] + [f"{c} (us/out facet)" for c in columns]
    header += [f"CVMS/{c}" for c in LIMITS if c in columns and "CVMS" in columns]
    header += [f"{c}/CVMS" for c in PEERS if c in columns and "CVMS" in columns]
    if "CVMS" in peaks:
        header += ["CVMS peak heap (MiB)"]
    lines.append("| " + " | ".join(header) + " |")
    lines.append("|" + "---|" * len(header))
    for k in ks:
        fin, fout = facets.get(k, (0, 0))
        cells = [str(k), str(fin), str(fout)]
        cells += ["%.3f" % times[c][k] if k in times[c] else "-" for c in columns]
        cells += ["%.3f" % (1e3 * times[c][k] / fout) if k in times[c] and fout else "-" for c in columns]
        for c in LIMITS:
            if c in columns and "CVMS" in columns:
                ok = k in times[c] and k in times["CVMS"]
                cells.append("%.2f" % (times["CVMS"][k] / times[c][k]) if ok else "-")
        for c in PEERS:
            if c in columns and "CVMS" in columns:
                ok = k in times[c] and k in times["CVMS"]
                cells.append("%.1f" % (times[c][k] / times["CVMS"][k]) if ok else "-")
        if "CVMS" in peaks:
            cells.append("%.1f" % (peaks["CVMS"][k] / 2**20) if k in peaks["CVMS"] else "-")
        lines.append("| " + " | ".join(cells) + " |")
    return lines


def slope_table(times, facets):
    """Per algorithm, the log-log slopes of time against output facets, as markdown lines."""
    lines = ["| algorithm | log-log slope k=3..K (endpoints) | least-squares slope | K |", "|---|---|---|---|"]
    for c in [c for _, c in ALGORITHMS if c in times]:
        s = slopes(times[c], facets)
        if s:
            lines.append("| %s | %.3f | %.3f | %d |" % (c, s[0], s[1], s[2]))
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("results", help="cvms_minkowski_bench JSON output")
    bench_json.add_time_options(parser)
    args = parser.parse_args()
    times, peaks, facets = load(args.results, *bench_json.time_options(args))
    for family, title in FAMILIES.items():
        if not times[family]:
            continue
        print(f"### {title} ({family})\n")
        print("\n".join(family_table(times[family], peaks[family], facets[family])))
        print()
        print("\n".join(slope_table(times[family], facets[family])))
        print()


if __name__ == "__main__":
    main()
