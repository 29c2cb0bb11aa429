#!/usr/bin/env python3
"""Our exact quickhull against qhull on the same point sets, from
cvms_quickhull_bench JSON (built with -DCVMS_BENCH_PEERS=ON): per cloud and
size, hull_soup/<cloud>/<n> against qhull/<cloud>/<n>, and the pairwise sums
of Cube + Sphere6 (hull_soup_peer/... against qhull/...).

usage: bench/qhull_ratios.py [--cpu] quickhull.json > ratios.md
"""
import json
import sys


def main(args):
    field = "real_time"
    if "--cpu" in args:
        field = "cpu_time"
        args = [a for a in args if a != "--cpu"]
    if len(args) != 1:
        sys.exit(__doc__)
    ms = {}
    for b in json.load(open(args[0]))["benchmarks"]:
        if b.get("error_occurred") or (b.get("run_type") == "aggregate" and b.get("aggregate_name") != "median"):
            continue
        ms[b["name"]] = b[field] * {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[b["time_unit"]]
    pairs = []
    for name in ms:
        if name.startswith("qhull/"):
            case = name[len("qhull/"):]
            ours = "hull_soup/" + case if "hull_soup/" + case in ms else "hull_soup_peer/" + case
            if ours in ms:
                pairs.append((case, ms[ours], ms[name]))
    print("| points | quickhull, exact (ms) | qhull, double (ms) | quickhull/qhull |")
    print("|---|---|---|---|")
    for case, ours, theirs in pairs:
        print("| %s | %.3f | %.3f | %.2f |" % (case, ours, theirs, ours / theirs))


if __name__ == "__main__":
    main(sys.argv[1:])
