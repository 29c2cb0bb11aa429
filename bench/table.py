#!/usr/bin/env python3
"""Turns Google Benchmark JSON from cvms_minkowski_bench into the README's
Table 1 reproduction: per row, our times per algorithm, our CHMS/x ratios
next to the paper's (Barki et al., Table 1, seconds on a 2.2 GHz Core 2 Duo).

usage: bench/table.py results.json > table.md
"""
import json
import sys

ROWS = ["Tetra", "Hedra", "TruncatedCube", "Sphere1", "Sphere2", "Sphere3", "Sphere4", "Sphere5", "Sphere6"]
# Paper's Table 1: (CHMS, ESSDMS, CVMS) seconds.
PAPER = {
    "Tetra": (0.016, 0.015, 0.015), "Hedra": (0.015, 0.015, 0.015), "TruncatedCube": (0.046, 0.015, 0.015),
    "Sphere1": (0.046, 0.046, 0.015), "Sphere2": (0.125, 0.093, 0.031), "Sphere3": (0.546, 0.250, 0.078),
    "Sphere4": (2.438, 0.735, 0.266), "Sphere5": (11.407, 2.719, 1.375), "Sphere6": (77.422, 16.828, 12.234),
}
ALGORITHMS = ["CHMS", "ESSDMS", "CVMS_paper", "CVMS"]
# Which paper column each of ours compares with (our CVMS_paper is the
# paper-faithful search; CVMS is the output-sensitive default).
PAPER_COLUMN = {"CHMS": 0, "ESSDMS": 1, "CVMS_paper": 2, "CVMS": 2}


def main(path):
    data = json.load(open(path))
    times = {}  # (algorithm, row) -> ms
    facets = {}
    for b in data["benchmarks"]:
        if b.get("run_type") == "aggregate" and b.get("aggregate_name") != "median":
            continue
        if b.get("error_occurred") or "_" in b["name"].split("/")[0].replace("BM_", "").replace("CVMS_paper", ""):
            continue
        name = b["name"].split("/")
        algorithm = name[0].replace("BM_", "")
        row = ROWS[int(name[1])]
        scale = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[b["time_unit"]]
        times[(algorithm, row)] = b["real_time"] * scale
        facets[row] = (int(b.get("input_facets", 0)), int(b.get("output_facets", 0)))
    present = [a for a in ALGORITHMS if any((a, r) in times for r in ROWS)]
    header = ["Cube +", "facets in/out"] + [f"{a} (ms)" for a in present]
    header += [f"CHMS/{a}" for a in present if a != "CHMS"] + [f"paper CHMS/{a}" for a in present if a != "CHMS"]
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    for row in ROWS:
        if not any((a, row) in times for a in present):
            continue
        cells = [row, "%d / %d" % facets.get(row, (0, 0))]
        cells += ["%.3f" % times[(a, row)] if (a, row) in times else "-" for a in present]
        for a in present:
            if a == "CHMS":
                continue
            if ("CHMS", row) in times and (a, row) in times:
                cells.append("%.1f" % (times[("CHMS", row)] / times[(a, row)]))
            else:
                cells.append("-")
        for a in present:
            if a == "CHMS":
                continue
            p = PAPER[row]
            cells.append("%.1f" % (p[0] / p[PAPER_COLUMN[a]]))
        print("| " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main(sys.argv[1])
