#!/usr/bin/env python3
"""Whole `cvms sum A B -o out.off` runs from file to file on the pairs of
cvms_solid_sum_bench (sums of solids that need not be convex, written as one
closed solid), following bench/end_to_end.py: the minimum wall time over
--rounds runs of each, the peak resident memory of that run and the sum's own
time inside it (`--stats`). The operands are the files the benchmark writes
(`--write_operands`), so the in-process rows and these sum the same solids.
The mesh pair is run with `--threads 1` and `--threads 2`, the others on one
thread. The reference row of each pair, `cvms sum A B --pieces -o pieces.obj`,
writes the pairwise sums of both decompositions instead of their union.

usage: bench/solid_sum_end_to_end.py [--filter REGEX] [--rounds 3] [--json docs/bench/solid_sum_end_to_end.json]
"""
import argparse
import json
import os
import re
import tempfile

import end_to_end
import solid_sum_pairs


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    solid_sum_pairs.add_arguments(parser)
    args = parser.parse_args()
    cvms, bench = os.path.abspath(args.cvms), os.path.abspath(args.bench)
    results = {}
    with tempfile.TemporaryDirectory() as scratch:
        solid_sum_pairs.write_operands(bench, scratch)
        for name, a, b in solid_sum_pairs.pairs(bench):
            if args.filter and not re.search(args.filter, name):
                continue
            runs = {f"{name}/{t}": ["--threads", str(t), "-o", "out.off"]
                    for t in ((1, 2) if name.startswith("spot+") else (1,))}
            runs[f"{name}/pieces"] = ["--pieces", "-o", "pieces.obj"]
            for row, options in runs.items():
                argv = [cvms, "sum", os.path.join(scratch, a + ".off"), os.path.join(scratch, b + ".off"), "--stats"]
                argv += [os.path.join(scratch, o) if o.endswith((".off", ".obj")) else o for o in options]
                try:
                    results[row] = end_to_end.measure(argv, args.rounds)
                except SystemExit as failed:  # the command failed: keep its message, go on
                    message = str(failed).split(" failed: ", 1)[-1].replace(scratch + os.sep, "")
                    results[row] = {"error": message[-300:]}
                print(f"{row}: " + (f"{results[row]['wall_ms']:.1f} ms" if "wall_ms" in results[row]
                                    else results[row]["error"]), flush=True)
    if args.json:
        with open(args.json, "w") as f:
            json.dump(results, f, indent=2)
            f.write("\n")


if __name__ == "__main__":
    main()
