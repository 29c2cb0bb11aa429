#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The cost of calling a sum from Python: cvms.minkowski_sum against the same
sum in C++ (the time `cvms sum --stats` reports for the sum alone), on the
same input files, the best of several runs each.

    cmake -S . -B build/python -DCVMS_BUILD_TOOLS=ON   # after scripts/python.sh
    cmake --build build/python --target _cvms cvms_cli
    PYTHONPATH=build/python/python /usr/bin/python3 python/bench/sum_overhead.py --cvms build/python/tools/cvms

The module and the tool should come from one build tree, so that both link
the same library objects.
"""

import argparse
import json
import pathlib
import re
import subprocess
import tempfile
import time

import cvms

PAIRS = [("Cube", ["cube"], "Sphere6", ["sphere", "--subdivisions", "6"]),
         ("Sphere6", ["sphere", "--subdivisions", "6"], "rotated Sphere6", ["rotated-sphere", "--subdivisions", "6"])]


def cpp_ms(tool, a, b):
    out = subprocess.run([tool, "sum", str(a), str(b), "-o", "/dev/null", "--stats"], check=True,
                         capture_output=True, text=True).stdout
    return float(re.search(r"^time: ([0-9.]+) ms", out, re.M).group(1))


def python_ms(a, b):
    start = time.perf_counter()
    cvms.minkowski_sum(a, b)
    return (time.perf_counter() - start) * 1e3


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cvms", required=True, help="the cvms command-line tool")
    parser.add_argument("--runs", type=int, default=7, help="runs of each, the best counts (default 7)")
    parser.add_argument("--json", help="also write the minima here (docs/bench/python_overhead.json)")
    args = parser.parse_args()
    results = {}
    print("| sum | C++ (ms) | Python (ms) | ratio |")
    print("|---|---:|---:|---:|")
    with tempfile.TemporaryDirectory() as tmp:
        for name_a, gen_a, name_b, gen_b in PAIRS:
            files = []
            for name, gen in ((name_a, gen_a), (name_b, gen_b)):
                path = pathlib.Path(tmp) / (name.replace(" ", "_") + ".off")
                subprocess.run([args.cvms, "gen", *gen, "-o", str(path)], check=True)
                files.append(path)
            a, b = cvms.read(files[0]), cvms.read(files[1])
            cpp, py = [], []
            for _ in range(args.runs):  # interleaved, so that load on the machine hits both alike
                cpp.append(cpp_ms(args.cvms, *files))
                py.append(python_ms(a, b))
            print(f"| {name_a} + {name_b} | {min(cpp):.1f} | {min(py):.1f} | {min(py) / min(cpp):.2f} |")
            results[f"{name_a} + {name_b}"] = {"cpp_ms": min(cpp), "python_ms": min(py), "runs": args.runs}
    if args.json:
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump(results, f, indent=2)
            f.write("\n")


if __name__ == "__main__":
    main()
