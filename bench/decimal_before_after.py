#!/usr/bin/env python3
"""Sums and loads of operands written three ways (exact dyadic expansions,
shortest round-trip decimals, 6 digits) in two release build trees (e.g.
before and after a change), run alternately on the same machine state: the
rows BM_Written_* of cvms_decimal_sum_bench (Sphere6 + rotated Sphere6 and
Cube + Sphere6) and the Sphere6 rows of cvms_load_bench (load, validate with
the facet planes, the numbers parsed alone). Each round runs both trees, in
turn; a row's figure is its minimum CPU time over all repetitions of all
rounds (the machine is shared: noise only adds time).

usage: bench/decimal_before_after.py --before /tmp/main/build/release --after build/release
                                     [--rounds 3] [--json docs/bench/decimal_before_after.json]
"""
import argparse
import json
import os
import subprocess

RUNS = (("cvms_decimal_sum_bench", "BM_Written_", "1"),
        ("cvms_load_bench", "BM_(load|validate_and_planes|parse_numbers)/(0|4|5)$", "0.3"))


def rows(build):
    """{row: [cpu ms, ...]} of one round in one tree."""
    out = {}
    for program, pattern, min_time in RUNS:
        text = subprocess.run([os.path.join(build, "bench", program), f"--benchmark_filter={pattern}",
                               f"--benchmark_min_time={min_time}", "--benchmark_repetitions=2",
                               "--benchmark_format=json"], check=True, capture_output=True, text=True).stdout
        for b in json.loads(text)["benchmarks"]:
            if b.get("run_type") != "iteration":
                continue
            scale = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[b["time_unit"]]
            out.setdefault(b["run_name"], []).append(b["cpu_time"] * scale)
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--before", required=True, help="a release build tree (its bench/ binaries are run)")
    parser.add_argument("--after", required=True, help="the other release build tree")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--json")
    args = parser.parse_args()
    times = {"before": {}, "after": {}}
    for r in range(args.rounds):
        for side in ("before", "after") if r % 2 == 0 else ("after", "before"):
            for name, values in rows(getattr(args, side)).items():
                times[side].setdefault(name, []).extend(values)
    result = {"rounds": args.rounds, "cpu_ms_min": {side: {name: min(v) for name, v in t.items()}
                                                      for side, t in times.items()}}
    print("| row | before (ms) | after (ms) | after / before |")
    print("|---|---:|---:|---:|")
    for name, before in result["cpu_ms_min"]["before"].items():
        after = result["cpu_ms_min"]["after"].get(name)
        if after:
            print(f"| {name} | {before:.2f} | {after:.2f} | {after / before:.2f} |")
    if args.json:
        with open(args.json, "w") as f:
            json.dump(result, f, indent=2)
            f.write("\n")


if __name__ == "__main__":
    main()
