#!/usr/bin/env python3
"""Where a sum's time goes, from a sampling profile: reads `perf script`
output of a benchmark run recorded with call graphs, keeps the samples whose
stack holds cvms::minkowski_sum (the setup of the operands is left out),
and writes each phase's share of them (a phase is every sample with one of
its functions on the stack, so the phases nest) and the share of the samples
whose innermost frame is in GMP, in malloc/free or in the kernel.

Each row of docs/bench/decimal_profile.json comes from

    perf record -F 400 --call-graph dwarf,32768 -o form<f>.data \\
        build/release/bench/cvms_decimal_sum_bench --benchmark_filter='Written_SphereRot/6/<f>$' \\
        --benchmark_min_time=3
    perf script -i form<f>.data | bench/perf_phases.py --row <name> --json docs/bench/decimal_profile.json

(form 0: exact dyadic operands; 1: shortest round-trip decimals; 2: 6 digits). The JSON
is updated in place, one row per --row; bench/performance_page.py reads it.

usage: perf script -i perf.data | bench/perf_phases.py --row NAME [--json FILE]
"""
import argparse
import json
import os
import re
import sys

# (phase, the functions that put a sample in it), outermost first; a
# function matches when its name, without arguments and template arguments,
# ends with the given text.
PHASES = (
    ("search: contributing vertices and edge-facet trace", ("cvms::detail::cvms_facets_reported",)),
    ("output build", ("cvms::detail::SumFacetBuilder::build",)),
    ("output build: facet normals", ("cvms::detail::SumFacetBuilder::write_normals",)),
    ("output build: edge directions as rationals", ("EdgeDirections::general",)),
    ("output build: vertices and mesh", ("cvms::detail::SumFacetBuilder::mesh_with_points",)),
    ("output build: vertices as rationals", ("cvms::detail::SumFacetBuilder::soup",)),
)
GROUPS = (("GMP", re.compile(r"libgmp")), ("malloc/free", re.compile(r"libc[.-]")),
          ("kernel", re.compile(r"kernel")))

FRAME = re.compile(r"^\s+[0-9a-f]+\s+(.*?)(\+0x[0-9a-f]+)?\s+\((.*)\)$")


def plain(symbol):
    """The symbol without (anonymous namespace), template arguments and arguments."""
    symbol = symbol.replace("(anonymous namespace)::", "")
    previous = None
    while previous != symbol:
        previous, symbol = symbol, re.sub(r"<[^<>]*>", "", symbol)
    return re.sub(r"\(.*\)( const)?$", "", symbol)


def samples(stream):
    """Yields each sample's frames, innermost first, as (function, object file)."""
    frames = []
    for line in stream:
        if not line.strip():
            if frames:
                yield frames
            frames = []
            continue
        m = FRAME.match(line)
        if m:
            frames.append((plain(m.group(1)), m.group(3)))
    if frames:
        yield frames


def shares(stream):
    inside = 0
    phase = {name: 0 for name, _ in PHASES}
    group = {name: 0 for name, _ in GROUPS}
    for frames in samples(stream):
        names = [f for f, _ in frames]
        if not any(n.endswith("cvms::minkowski_sum") for n in names):
            continue
        inside += 1
        for name, functions in PHASES:
            if any(n.endswith(f) for n in names for f in functions):
                phase[name] += 1
        for name, pattern in GROUPS:
            if pattern.search(frames[0][1]):
                group[name] += 1
                break
    if inside == 0:
        raise SystemExit("no sample inside cvms::minkowski_sum: was the run recorded with --call-graph?")
    return {"samples": inside, "phases": {k: v / inside for k, v in phase.items()},
            "innermost": {k: v / inside for k, v in group.items()}}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--row", required=True, help="the row's name in the JSON (e.g. dyadic, shortest)")
    parser.add_argument("--json", help="the file to update (printed to stdout without it)")
    args = parser.parse_args()
    row = shares(sys.stdin)
    if not args.json:
        json.dump(row, sys.stdout, indent=2)
        return
    data = {}
    if os.path.exists(args.json):
        with open(args.json) as f:
            data = json.load(f)
    data.setdefault("rows", {})[args.row] = row
    with open(args.json, "w") as f:
        json.dump(data, f, indent=2)
        f.write("\n")


if __name__ == "__main__":
    main()
