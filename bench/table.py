#!/usr/bin/env python3
"""Turns Google Benchmark JSON from cvms_minkowski_bench into the
Table 1 reproduction of docs/performance.md: per row, our times per algorithm, our CHMS/x ratios
next to the paper's (Barki et al., Table 1, seconds on a 2.2 GHz Core 2 Duo),
the peers (qhull, CGAL: hull of the pairwise vertex sums, built with
-DCVMS_BENCH_PEERS=ON) with peer/CVMS ratios, and CVMS's peak heap.
With --memory, a second table gives every algorithm's peak heap.

The column "exact fallback" is the share of CVMS's predicates that the
floating-point filters could not decide and the exact arithmetic did.
"""
import argparse

import bench_json

ROWS = ["Tetra", "Hedra", "TruncatedCube", "Sphere1", "Sphere2", "Sphere3", "Sphere4", "Sphere5", "Sphere6"]
# Paper's Table 1: (CHMS, ESSDMS, CVMS) seconds.
PAPER = {
    "Tetra": (0.016, 0.015, 0.015), "Hedra": (0.015, 0.015, 0.015), "TruncatedCube": (0.046, 0.015, 0.015),
    "Sphere1": (0.046, 0.046, 0.015), "Sphere2": (0.125, 0.093, 0.031), "Sphere3": (0.546, 0.250, 0.078),
    "Sphere4": (2.438, 0.735, 0.266), "Sphere5": (11.407, 2.719, 1.375), "Sphere6": (77.422, 16.828, 12.234),
}
# Benchmark name (before the "/row") -> column. Our CVMS_paper is the
# paper-faithful search; CVMS is the output-sensitive default.
BENCHMARKS = {
    "BM_CHMS": "CHMS", "BM_ESSDMS": "ESSDMS", "BM_CVMS_paper": "CVMS_paper", "BM_CVMS": "CVMS",
    "BM_CVMS_2threads": "CVMS_2threads", "BM_Qhull_PairwiseSums": "qhull", "BM_CGAL_PairwiseSums": "CGAL",
}
OURS = ["CHMS", "ESSDMS", "CVMS_paper", "CVMS", "CVMS_2threads"]
PEERS = ["qhull", "CGAL"]
# The paper's ratios shown: CHMS over its ESSDMS and over its CVMS (column
# indices into PAPER); every CVMS mode of ours compares with the latter.
PAPER_RATIOS = {"ESSDMS": 1, "CVMS": 2}


def load(path, time_field="real_time", statistic="median"):
    """(times, peaks, facets, fallback): times[(algorithm, row)] in ms, peaks in bytes,
    facets[row] = (input, output) from our rows (the peers do not report the
    output facet count: qhull merges in floating point, CGAL triangulates);
    fallback[row] = CVMS's exact-fallback rate."""
    times, peaks, facets, fallback = {}, {}, {}, {}
    for prefix, arg, ms, b in bench_json.runs(path, time_field, statistic):
        if prefix not in BENCHMARKS:
            continue
        algorithm = BENCHMARKS[prefix]
        row = ROWS[arg]
        times[(algorithm, row)] = ms
        if "peak_heap_bytes" in b:
            peaks[(algorithm, row)] = b["peak_heap_bytes"]
        if "output_facets" in b:
            facets[row] = (int(b.get("input_facets", 0)), int(b["output_facets"]))
        if algorithm == "CVMS" and "exact_fallback_rate" in b:
            fallback[row] = b["exact_fallback_rate"]
    return times, peaks, facets, fallback


def kib(n):
    return "%.0f" % (n / 1024.0)


def ratio(times, num, den, row):
    if (num, row) in times and (den, row) in times:
        return "%.1f" % (times[(num, row)] / times[(den, row)])
    return "-"


def table1(times, peaks, facets, fallback):
    """Table 1 as markdown lines."""
    lines = []
    ours = [a for a in OURS if any((a, r) in times for r in ROWS)]
    peers = [a for a in PEERS if any((a, r) in times for r in ROWS)]
    present = ours + peers
    header = ["Cube +", "facets in/out"] + [f"{a} (ms)" for a in present]
    header += [f"CHMS/{a}" for a in ours if a != "CHMS"]
    header += [f"{p}/CVMS" for p in peers if "CVMS" in ours]
    header += [f"paper CHMS/{a}" for a in PAPER_RATIOS]
    if "CVMS" in ours:
        header += ["CVMS peak heap (KiB)"]
    if fallback:
        header += ["CVMS exact fallback"]
    lines.append("| " + " | ".join(header) + " |")
    lines.append("|" + "---|" * len(header))
    for row in ROWS:
        if not any((a, row) in times for a in present):
            continue
        cells = [row, "%d / %d" % facets.get(row, (0, 0))]
        cells += ["%.3f" % times[(a, row)] if (a, row) in times else "-" for a in present]
        cells += [ratio(times, "CHMS", a, row) for a in ours if a != "CHMS"]
        if "CVMS" in ours:
            cells += [ratio(times, p, "CVMS", row) for p in peers]
        cells += ["%.1f" % (PAPER[row][0] / PAPER[row][c]) for c in PAPER_RATIOS.values()]
        if "CVMS" in ours:
            cells.append(kib(peaks[("CVMS", row)]) if ("CVMS", row) in peaks else "-")
        if fallback:
            cells.append("%.1f %%" % (100 * fallback[row]) if row in fallback else "-")
        lines.append("| " + " | ".join(cells) + " |")
    return lines


def memory_table(peaks):
    """Every algorithm's peak heap as markdown lines."""
    lines = []
    present = [a for a in OURS + PEERS if any((a, r) in peaks for r in ROWS)]
    header = ["Cube +"] + [f"{a} peak heap (KiB)" for a in present]
    lines.append("| " + " | ".join(header) + " |")
    lines.append("|" + "---|" * len(header))
    for row in ROWS:
        if not any((a, row) in peaks for a in present):
            continue
        cells = [row] + [kib(peaks[(a, row)]) if (a, row) in peaks else "-" for a in present]
        lines.append("| " + " | ".join(cells) + " |")
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("results", help="cvms_minkowski_bench JSON output")
    parser.add_argument("--memory", action="store_true", help="also print every algorithm's peak heap")
    bench_json.add_time_options(parser)
    args = parser.parse_args()
    times, peaks, facets, fallback = load(args.results, *bench_json.time_options(args))
    print("\n".join(table1(times, peaks, facets, fallback)))
    if args.memory:
        print()
        print("\n".join(memory_table(peaks)))


if __name__ == "__main__":
    main()
