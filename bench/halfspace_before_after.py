#!/usr/bin/env python3
"""from_halfspaces, pontryagin_difference and qhull's qhalf before and after a
change, from two release build trees with the peers on, run
alternately on the same machine state, under glibc's default malloc policy and
with freed memory kept (MALLOC_TRIM_THRESHOLD_, MALLOC_MMAP_THRESHOLD_ and
MALLOC_TOP_PAD_ set high): on this virtual machine a page fault costs about
13 µs, and whether glibc returns a call's memory to the kernel (so that the next
call faults it in again) depends on the sizes of the blocks freed before, not on
the algorithm. Prints, per policy and row, the minimum CPU time over all rounds
(ms) before and after, and the ratios to the minimum qhull time of both builds
(qhull's code is the same in both).

usage: bench/halfspace_before_after.py --before /tmp/main/build/release --after build/release
                                       [--rounds 3] [--json out.json]
"""
import argparse
import json
import os
import subprocess

KEPT = {"MALLOC_TRIM_THRESHOLD_": "4000000000", "MALLOC_MMAP_THRESHOLD_": "268435456",
        "MALLOC_TOP_PAD_": "67108864"}


def run(build, kept):
    env = dict(os.environ)
    for k in KEPT:
        env.pop(k, None)
    if kept:
        env.update(KEPT)
    out = subprocess.run([os.path.join(build, "bench", "cvms_halfspace_bench"),
                          "--benchmark_filter=FromHalfspaces|Qhalf|Pontryagin", "--benchmark_min_time=0.3",
                          "--benchmark_format=json"], check=True, capture_output=True, text=True, env=env).stdout
    return {b["name"]: b["cpu_time"] for b in json.loads(out)["benchmarks"] if b["time_unit"] == "ms"}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--before", required=True)
    parser.add_argument("--after", required=True)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--json")
    args = parser.parse_args()
    best = {}
    for _ in range(args.rounds):
        for policy in ("default", "kept"):
            for label, build in (("before", args.before), ("after", args.after)):
                for name, t in run(build, policy == "kept").items():
                    key = (policy, label, name)
                    best[key] = min(best.get(key, float("inf")), t)
    table = {}
    for policy in ("default", "kept"):
        print(f"== {policy}")
        names = sorted({n for (p, _, n) in best if p == policy and not n.startswith("BM_Qhalf")})
        for name in names:
            before, after = best[(policy, "before", name)], best[(policy, "after", name)]
            qhull = float("inf")
            if name.startswith("BM_FromHalfspaces"):
                peer = name.replace("FromHalfspaces", "Qhalf")
                qhull = min(best.get((policy, "before", peer), qhull), best.get((policy, "after", peer), qhull))
            row = {"before_ms": before, "after_ms": after, "after/before": after / before}
            line = f"{name:40s} before {before:8.2f}  after {after:8.2f}  after/before {after / before:5.2f}"
            if qhull != float("inf"):
                row.update({"qhull_ms": qhull, "after/qhull": after / qhull, "before/qhull": before / qhull})
                line += f"  qhull {qhull:8.2f}  after/qhull {after / qhull:5.2f}  before/qhull {before / qhull:5.2f}"
            table[f"{policy} {name}"] = row
            print(line)
    if args.json:
        with open(args.json, "w") as f:
            json.dump(table, f, indent=1)


if __name__ == "__main__":
    main()
