#!/usr/bin/env python3
"""Our exact quickhull against qhull on the same point sets, from
cvms_quickhull_bench JSON (built with -DCVMS_BENCH_PEERS=ON): per cloud and
size, hull_soup/<cloud>/<n> (exact input) and from_doubles/<cloud>/<n>
(double input, as qhull's) against qhull/<cloud>/<n>, and the pairwise sums of
Cube + Sphere6 (hull_soup_peer/... against qhull/...).
"""
import argparse

import bench_json


def ratio_rows(rows):
    """[(case, exact ms, double ms or None, qhull ms)] for every qhull row with an exact counterpart."""
    out = []
    for name, (theirs, _) in rows.items():
        if not name.startswith("qhull/"):
            continue
        case = name[len("qhull/"):]
        ours = rows.get("hull_soup/" + case, rows.get("hull_soup_peer/" + case))
        if ours is None:
            continue
        doubles = rows.get("from_doubles/" + case)
        out.append((case, ours[0], doubles[0] if doubles else None, theirs))
    return out


def table(rows):
    """The ratios as markdown lines."""
    lines = ["| points | quickhull, exact input (ms) | quickhull, double input (ms) | qhull, double (ms) "
             "| exact/qhull | double/qhull |", "|---|---:|---:|---:|---:|---:|"]
    for case, ours, doubles, theirs in ratio_rows(rows):
        d = "—" if doubles is None else "%.3f" % doubles
        dr = "—" if doubles is None else "%.2f" % (doubles / theirs)
        lines.append("| %s | %.3f | %s | %.3f | %.2f | %s |" % (case, ours, d, theirs, ours / theirs, dr))
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("results", help="cvms_quickhull_bench JSON output")
    bench_json.add_time_options(parser)
    args = parser.parse_args()
    print("\n".join(table(bench_json.rows(args.results, *bench_json.time_options(args)))))


if __name__ == "__main__":
    main()
