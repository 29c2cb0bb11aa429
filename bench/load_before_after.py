#!/usr/bin/env python3
"""Loading in two release build trees (e.g. before and after a change), run
alternately on the same machine state: the in-process rows of
cvms_load_bench (load, parse and validate of Sphere6 and of the 35,000-point
decimal hull; minimum CPU time over all repetitions of all rounds) and whole
`cvms check sphere6.off` runs under `perf stat -e page-faults,task-clock`
(minimum wall and task-clock, median page faults). The machine is shared, so
single runs are noisy: the minimum of alternating runs is what compares.

With --checks 0 no `cvms check` runs, and the trees need only the bench.

usage: bench/load_before_after.py --before /tmp/main/build/release --after build/release
                                  [--rounds 4] [--checks 3] [--json out.json]
"""
import argparse
import json
import os
import re
import statistics
import subprocess
import tempfile


def load_rows(build):
    out = subprocess.run([os.path.join(build, "bench", "cvms_load_bench"),
                          "--benchmark_filter=BM_(load|parse|validate|parse_numbers)/", "--benchmark_min_time=0.3",
                          "--benchmark_repetitions=3", "--benchmark_format=json"],
                         check=True, capture_output=True, text=True).stdout
    rows = {}
    for b in json.loads(out)["benchmarks"]:
        if b.get("run_type") == "iteration":
            rows.setdefault(b["name"].split("/repeats")[0], []).append(b["cpu_time"])
    return rows


def check_run(build, shape):
    """(wall ms, task-clock ms, page faults) of one `cvms check`."""
    err = subprocess.run(["perf", "stat", "-e", "page-faults,task-clock", os.path.join(build, "tools", "cvms"),
                          "check", shape], check=True, capture_output=True, text=True).stderr
    faults = float(re.search(r"([0-9,]+)\s+page-faults", err).group(1).replace(",", ""))
    task = float(re.search(r"([0-9.,]+)\s+msec task-clock", err).group(1).replace(",", ""))
    wall = 1000 * float(re.search(r"([0-9.]+) seconds time elapsed", err).group(1))
    return wall, task, faults


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--before", required=True)
    parser.add_argument("--after", required=True)
    parser.add_argument("--rounds", type=int, default=4)
    parser.add_argument("--checks", type=int, default=3)
    parser.add_argument("--json")
    args = parser.parse_args()
    builds = {"before": args.before, "after": args.after}
    with tempfile.TemporaryDirectory() as scratch:
        shape = os.path.join(scratch, "sphere6.off")
        if args.checks > 0:
            subprocess.run([os.path.join(args.after, "tools", "cvms"), "gen", "sphere", "--subdivisions", "6", "-o",
                            shape], check=True)
        load = {k: {} for k in builds}
        checks = {k: [] for k in builds}
        for _ in range(args.rounds):
            for key, build in builds.items():
                for name, times in load_rows(build).items():
                    load[key].setdefault(name, []).extend(times)
                checks[key].extend(check_run(build, shape) for _ in range(args.checks))
    result = {"load_ms_cpu_min": {k: {n: min(t) for n, t in v.items()} for k, v in load.items()},
              "check": {k: {"wall_ms_min": min(c[0] for c in v), "task_clock_ms_min": min(c[1] for c in v),
                            "page_faults_median": statistics.median(c[2] for c in v)}
                        for k, v in checks.items() if v}}
    for name in sorted(result["load_ms_cpu_min"]["before"]):
        base_ms, new_ms = result["load_ms_cpu_min"]["before"][name], result["load_ms_cpu_min"]["after"][name]
        ratio = base_ms / new_ms
        print(f"{name:24s} before {base_ms:8.2f} ms  after {new_ms:8.2f} ms  {ratio:5.2f}x")
    for key in result["check"]:
        c = result["check"][key]
        print(f"cvms check sphere6.off {key:6s} wall {c['wall_ms_min']:7.1f} ms  task-clock "
              f"{c['task_clock_ms_min']:7.1f} ms  page faults {c['page_faults_median']:.0f}")
    if args.json:
        with open(args.json, "w") as f:
            json.dump(result, f, indent=1)


if __name__ == "__main__":
    main()
