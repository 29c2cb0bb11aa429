#!/usr/bin/env python3
"""Manifold's floating-point Minkowski sum (npm package manifold-3d under
node, bench/manifold_peer.mjs) on the pairs of cvms_solid_sum_bench, side by
side with its exact rows, written as Google Benchmark JSON (rows
`Manifold/<pair>/1`, wall and CPU time in ms, each the minimum of --rounds
sums in one node process) so that bench/performance_page.py reads it like the others.

Each result is also checked exactly: Manifold's output, its float32
coordinates written exactly, is validated by `cvms check` (a closed, oriented,
non-self-intersecting solid, no two vertices at one point, no degenerate
face). Counters: peer_vertices, peer_triangles, peer_genus (Manifold's own),
exact_valid (1 when `cvms check` accepts the result) and, when it does not,
exact_check (its message).

Off by default: the package is installed only with --install, by npm, into
--cache (default ~/.cache/cvms-bench/manifold, outside the source tree).

usage: bench/manifold_peer.py [--install] [--filter REGEX] [--rounds 3] [--json docs/bench/solid_sum_manifold.json]
"""
import argparse
import json
import os
import platform
import re
import subprocess
import sys
import tempfile
import time

import solid_sum_pairs

HERE = os.path.dirname(os.path.abspath(__file__))
PACKAGE = "manifold-3d"


def install(cache):
    os.makedirs(cache, exist_ok=True)
    if not os.path.exists(os.path.join(cache, "package.json")):
        subprocess.run(["npm", "init", "-y"], cwd=cache, check=True, capture_output=True)
    subprocess.run(["npm", "install", "--no-audit", "--no-fund", PACKAGE], cwd=cache, check=True)


def package_version(cache):
    path = os.path.join(cache, "node_modules", PACKAGE, "package.json")
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return json.load(f)["version"]


def exact_check(cvms, path):
    """(1, "") when `cvms check` accepts the file, else (0, its message)."""
    done = subprocess.run([cvms, "check", path], capture_output=True, text=True)
    if done.returncode == 0:
        return 1, ""
    message = (done.stderr.strip() or done.stdout.strip()).splitlines()[0]
    return 0, message.replace(path, os.path.basename(path))[:300]


def run_pair(args, scratch, name, a, b):
    out = os.path.join(scratch, f"manifold_{name}.off")
    argv = ["node", os.path.join(HERE, "manifold_peer.mjs"), args.cache, os.path.join(scratch, a + ".off"),
            os.path.join(scratch, b + ".off"), str(args.rounds), out]
    row = {"name": f"Manifold/{name}/1", "run_name": f"Manifold/{name}/1", "run_type": "iteration",
           "repetitions": args.rounds, "iterations": 1, "threads": 1, "time_unit": "ms"}
    try:
        done = subprocess.run(argv, capture_output=True, text=True, timeout=args.timeout)
    except subprocess.TimeoutExpired:
        return {**row, "error_occurred": True, "error_message": f"timed out after {args.timeout} s"}
    if done.returncode != 0:
        return {**row, "error_occurred": True, "error_message": done.stderr.strip()[-300:]}
    r = json.loads(done.stdout)
    valid, message = exact_check(args.cvms, out)
    row.update({"real_time": r["ms"], "cpu_time": r["cpu_ms"], "peer_vertices": r["vertices"],
                "peer_triangles": r["triangles"], "peer_genus": r["genus"], "peer_volume": r["volume"],
                "peer_status": r["status"], "exact_valid": valid})
    if message:
        row["exact_check"] = message
    return row


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    solid_sum_pairs.add_arguments(parser)
    parser.add_argument("--cache", default=os.path.expanduser("~/.cache/cvms-bench/manifold"),
                        help="where npm installs manifold-3d (outside the source tree)")
    parser.add_argument("--install", action="store_true", help="install manifold-3d with npm into --cache first")
    parser.add_argument("--timeout", type=float, default=1800, help="seconds allowed for one pair")
    args = parser.parse_args()
    args.cache = os.path.abspath(args.cache)
    args.cvms = os.path.abspath(args.cvms)
    if args.install:
        install(args.cache)
    version = package_version(args.cache)
    if version is None:
        sys.exit(f"{PACKAGE} is not installed in {args.cache}: run with --install (npm, off by default)")
    node = subprocess.run(["node", "--version"], capture_output=True, text=True, check=True).stdout.strip()
    context = {"date": time.strftime("%Y-%m-%dT%H:%M:%S%z"), "host_name": platform.node(),
               "num_cpus": os.cpu_count(), "load_avg": list(os.getloadavg()),
               "peer": f"{PACKAGE} {version} under node {node}"}
    rows = []
    with tempfile.TemporaryDirectory() as scratch:
        solid_sum_pairs.write_operands(os.path.abspath(args.bench), scratch)
        for name, a, b in solid_sum_pairs.pairs(os.path.abspath(args.bench)):
            if args.filter and not re.search(args.filter, name):
                continue
            row = run_pair(args, scratch, name, a, b)
            rows.append(row)
            state = row.get("error_message") or (f"{row['real_time']:.1f} ms, exact check "
                                                 + ("passed" if row["exact_valid"] else "failed: " + row["exact_check"]))
            print(f"{name}: {state}", flush=True)
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"context": context, "benchmarks": rows}, f, indent=2)
            f.write("\n")


if __name__ == "__main__":
    main()
