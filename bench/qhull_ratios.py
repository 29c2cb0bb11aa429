#!/usr/bin/env python3
"""Our exact quickhull against qhull on the same point sets, from
cvms_quickhull_bench JSON (built with -DCVMS_BENCH_PEERS=ON): per cloud and
size, hull_soup/<cloud>/<n> (exact input) and from_doubles/<cloud>/<n>
(double input, as qhull's) against qhull/<cloud>/<n>, and the pairwise sums of
Cube + Sphere6 (hull_soup_peer/... against qhull/...). With
--benchmark_repetitions, the medians are read.

usage: bench/qhull_ratios.py [--cpu] quickhull.json > ratios.md
"""
import json
import sys


def times(path, field):
    runs = json.load(open(path))["benchmarks"]
    medians = any(b.get("aggregate_name") == "median" for b in runs)
    ms = {}
    for b in runs:
        if b.get("error_occurred"):
            continue
        if medians != (b.get("aggregate_name") == "median"):
            continue
        name = b.get("run_name", b["name"]) if medians else b["name"]
        ms[name] = b[field] * {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[b["time_unit"]]
    return ms


def main(args):
    field = "real_time"
    if "--cpu" in args:
        field = "cpu_time"
        args = [a for a in args if a != "--cpu"]
    if len(args) != 1:
        sys.exit(__doc__)
    ms = times(args[0], field)
    print("| points | quickhull, exact input (ms) | quickhull, double input (ms) | qhull, double (ms) "
          "| exact/qhull | double/qhull |")
    print("|---|---:|---:|---:|---:|---:|")
    for name in ms:
        if not name.startswith("qhull/"):
            continue
        case = name[len("qhull/"):]
        ours = ms.get("hull_soup/" + case, ms.get("hull_soup_peer/" + case))
        doubles = ms.get("from_doubles/" + case)
        if ours is None:
            continue
        theirs = ms[name]
        d = "—" if doubles is None else "%.3f" % doubles
        dr = "—" if doubles is None else "%.2f" % (doubles / theirs)
        print("| %s | %.3f | %s | %.3f | %.2f | %s |" % (case, ours, d, theirs, ours / theirs, dr))


if __name__ == "__main__":
    main(sys.argv[1:])
