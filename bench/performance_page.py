#!/usr/bin/env python3
"""Writes docs/performance.md, the whole page, from the benchmark JSON in
docs/bench/: every table and every figure quoted in its text is computed here
from those files, so the page says what the committed runs measured and
nothing else. With --check it writes nothing and fails (printing a diff) when
the committed page differs from what the JSON gives (the ctest
bench_performance_page runs that).
"""
import argparse
import difflib
import json
import math
import os
import sys

import bench_json
import qhull_ratios
import scaling
import set_table
import solid_sum_table
import table

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def path_in(bench_dir, name):
    return os.path.join(bench_dir, name)


def run_line(path, time_field, statistic, extra=""):
    """One line saying how a table's file was read and on what machine state it was run."""
    c = bench_json.context(path)
    what = "real (wall) time" if time_field == "real_time" else "CPU time"
    stat = {"min": "the minimum of each row's repetitions (a row run once: that run)",
            "median": "the median of each row's repetitions"}[statistic]
    load = c.get("load_avg")
    machine = f"{c.get('num_cpus', '?')} CPUs"
    if load:
        machine += f", load average {load[0]:.1f} when the run started"
    return (f"*`docs/bench/{os.path.basename(path)}`: {what}, {stat}; {machine}.{extra}*")


fmt_ms = bench_json.fmt_ms


def ratio(a, b, digits=1):
    return f"{a / b:.{digits}f}×"


class Page:
    def __init__(self):
        self.lines = []

    def add(self, *lines):
        self.lines.extend(lines)

    def para(self, text):
        self.lines.extend([text, ""])

    def block(self, lines):
        self.lines.extend(list(lines) + [""])

    def text(self):
        out = "\n".join(self.lines).rstrip("\n") + "\n"
        while "\n\n\n" in out:
            out = out.replace("\n\n\n", "\n\n")
        return out


PIECES_COMMAND = r"""build/release/bench/cvms_pieces_bench --benchmark_min_time=0.05 --benchmark_repetitions=3 \
    --benchmark_enable_random_interleaving=true --benchmark_out=docs/bench/pieces.json --benchmark_out_format=json"""

REPRODUCE = r"""```sh
# configure once: release preset, the peers (qhull, CGAL) on; they are optional and bench only
cmake --preset release -DCVMS_BENCH_PEERS=ON
cmake --build build/release -j2 --target cvms_minkowski_bench cvms_quickhull_bench cvms_set_bench \
    cvms_halfspace_bench cvms_load_bench cvms_decimal_sum_bench cvms_pieces_bench cvms_cli

# Table 1, scaling families, limits and peers (docs/bench/minkowski.json): five repetitions of
# every row, interleaved at random over the whole run (about 4 minutes)
build/release/bench/cvms_minkowski_bench --benchmark_min_time=0.2 --benchmark_repetitions=5 \
    --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true \
    --benchmark_out=docs/bench/minkowski.json --benchmark_out_format=json
bench/plot.py --min docs/bench/minkowski.json -o docs/fig12.svg   # Fig. 12 (matplotlib)

# exact quickhull against qhull, under glibc's default malloc policy and with freed memory kept
F='^(hull_soup|from_doubles|qhull|hull_soup_peer)/'
build/release/bench/cvms_quickhull_bench --benchmark_filter="$F" --benchmark_min_time=0.2 \
    --benchmark_repetitions=3 --benchmark_out=docs/bench/quickhull.json --benchmark_out_format=json
MALLOC_TRIM_THRESHOLD_=4000000000 MALLOC_MMAP_THRESHOLD_=268435456 MALLOC_TOP_PAD_=67108864 \
    build/release/bench/cvms_quickhull_bench --benchmark_filter="$F" --benchmark_min_time=0.2 \
    --benchmark_repetitions=3 --benchmark_out=docs/bench/quickhull_memory_kept.json --benchmark_out_format=json

# non-convex solids: decompositions, sums as unions of pieces, qhull on every piece pair
PIECES_RUN

# non-convex sums as one closed solid, CGAL Nef on the small pairs (CVMS_BENCH_NEF=all: spot too,
# minutes), Manifold under node, whole `cvms sum` runs
CVMS_BENCH_NEF=small SOLID_SUM_RUN

# sums of convex sets, half-spaces, decimal coordinates, loading and writing
build/release/bench/cvms_set_bench --benchmark_min_time=0.2 \
    --benchmark_out=docs/bench/sets.json --benchmark_out_format=json
build/release/bench/cvms_halfspace_bench --benchmark_min_time=0.2 \
    --benchmark_out=docs/bench/halfspace.json --benchmark_out_format=json
build/release/bench/cvms_halfspace_bench --benchmark_min_time=0.2 \
    --benchmark_out=docs/bench/halfspace_cgal.json --benchmark_out_format=json
build/release/bench/cvms_decimal_sum_bench --benchmark_min_time=1 --benchmark_repetitions=3 \
    --benchmark_enable_random_interleaving=true \
    --benchmark_out=docs/bench/decimal_sum.json --benchmark_out_format=json
build/release/bench/cvms_load_bench --benchmark_min_time=0.3 --benchmark_repetitions=3 \
    --benchmark_out=docs/bench/load.json --benchmark_out_format=json
# where a decimal sum's time goes (commands in bench/perf_phases.py), and two trees alternately
bench/decimal_before_after.py --before /tmp/main/build/release --after build/release \
    --rounds 3 --json docs/bench/decimal_before_after.json
bench/load_before_after.py --before /tmp/main/build/release --after build/release \
    --rounds 3 --checks 0 --json docs/bench/load_before_after.json

# whole `cvms` runs from file to file (minimum of 5 rounds)
bench/end_to_end.py --cvms build/release/tools/cvms --json docs/bench/end_to_end.json

# a sum called from Python against the same sum in C++ (the module and the tool of one tree)
scripts/python.sh && cmake -S . -B build/python -DCVMS_BUILD_TOOLS=ON && cmake --build build/python --target cvms_cli
PYTHONPATH=build/python/python /usr/bin/python3 python/bench/sum_overhead.py --cvms build/python/tools/cvms \
    --runs 9 --json docs/bench/python_overhead.json

# then this page
bench/performance_page.py
```"""

SOLID_SUM_COMMAND = r"""build/release/bench/cvms_solid_sum_bench --benchmark_min_time=0.05 --benchmark_repetitions=3 \
    --benchmark_enable_random_interleaving=true --benchmark_out=docs/bench/solid_sum.json --benchmark_out_format=json
CVMS_BENCH_NEF=all build/release/bench/cvms_solid_sum_bench --benchmark_filter='^BM_CgalNef/spot' \
    --benchmark_out=docs/bench/solid_sum_nef_spot.json --benchmark_out_format=json
bench/manifold_peer.py --install --json docs/bench/solid_sum_manifold.json   # npm, into ~/.cache/cvms-bench
bench/solid_sum_end_to_end.py --json docs/bench/solid_sum_end_to_end.json"""

REPRODUCE = REPRODUCE.replace("PIECES_RUN", PIECES_COMMAND).replace("SOLID_SUM_RUN", SOLID_SUM_COMMAND)

NOISY_MACHINE = """\
**How to read these numbers on a noisy machine.** The runs come from a 2-core virtual machine
whose host is shared. Over a few seconds it repeats a row within 1–2 %, but its speed moves in
spells, and from one spell to the next the same row moves by up to 40 %. Noise only ever adds
time, so a row's fastest repetition is the closest to what the code costs: the Minkowski binary
runs every row five times, the repetitions interleaved at random over the whole run, and the
tables read each row's **minimum**, its time in the run's fastest spell, so that all rows are
compared under the same conditions. Rows run in order would each fall into whatever spell they
met. Even so, absolute times move between runs; what to compare are the **ratios of rows
measured side by side in one run of one binary** (every ratio on this page is one), not times
across tables or files. Files without repetitions give each row's one run; where a run shared
the machine with other jobs (a load average above 2 on 2 CPUs), its single-threaded tables read
CPU time, which such sharing inflates far less than wall time."""


def minkowski_sections(page, path):
    times, peaks, facets, fallback = table.load(path, "real_time", "min")
    stimes, speaks, sfacets = scaling.load(path, "real_time", "min")

    page.add("## Table 1 of the paper: Cube + {Tetra ... Sphere6}", "")
    page.para(run_line(path, "real_time", "min"))
    page.para("Times in ms. The paper's times are CGAL with a lazy exact kernel on a 2.2 GHz Core 2 Duo; "
              "\"paper CHMS/x\" is its ratio. The peers hull the pairwise vertex sums a + b "
              "(formed before the timed loop), timing the hull only: qhull in floating point, CGAL's "
              "`convex_hull_3` with the exact-constructions kernel (Epeck). \"CVMS exact fallback\" is the "
              "share of CVMS's predicates that the floating-point filters could not decide, so that exact "
              "arithmetic did.")
    page.block(table.table1(times, peaks, facets, fallback))
    page.add(
        "- `CHMS`: the exact hull of the pairwise vertex sums (the convex-hull method), on our exact quickhull.",
        "- `ESSDMS`: the paper's edge-set/Gaussian-map method, decided exactly.",
        "- `CVMS_paper`: the paper-faithful search: a linear contributing-vertex scan and the Eq. 4/5 "
        "edge-facet search, decided exactly.",
        "- `CVMS`: the default, output-sensitive mode: contributing vertices by hill-climbing, edge facets "
        "by tracing Gaussian arcs.",
        "- `CVMS_2threads`: the same with `Options::threads = 2`; sums with fewer than 512 output facets "
        "stay on one thread, since starting a thread costs more than they take.",
        "",
        "All CVMS modes give the identical polyhedron, numbering and `Stats` included.", "")

    page.add("## Peak heap", "")
    page.para("`peak_heap_bytes`: the peak of live heap bytes during the timed loop, above what was live "
              "before it (the inputs are excluded), in KiB. Every C++ allocation and every GMP limb is "
              "counted (`bench/heap_counter.cpp`); qhull allocates with `malloc`, so its rows add qhull's "
              "own peak. The 2-thread rows are not measured (the counters are per thread).")
    page.block(table.memory_table(peaks))

    page.add("## Scaling and log-log slopes", "")
    page.para(run_line(path, "real_time", "min"))
    page.para("Two families: Sphere_k + Sphere_k rotated (the second sphere from a rotated icosahedron, "
              "rounded to double, so the two Gaussian maps are in general position) and Cube + Sphere_k. "
              "Times in ms and µs per output facet. Two limits are timed on the final facet vertex-pair "
              "lists, on one thread: `limit mesh`, the half-edge mesh and its exact (packed) vertex "
              "coordinates as CVMS makes them, which every representation of the output needs; and "
              "`limit build`, the whole output polyhedron, i.e. everything CVMS does after its search. "
              "Peers run while their time stays under about 10 s and their memory under 4 GB.")
    for family, title in scaling.FAMILIES.items():
        if not stimes[family]:
            continue
        page.add(f"### {title}", "")
        page.block(scaling.family_table(stimes[family], speaks[family], sfacets[family]))
        page.para("Log-log slope of time against output facets, from k = 3 to the largest k measured (K): "
                  "between the end points and by least squares.")
        page.block(scaling.slope_table(stimes[family], sfacets[family]))
    page.para("![Runtime against facet count for every algorithm, after the paper's Fig. 12](fig12.svg)")
    return stimes, speaks, sfacets


def quickhull_section(page, default_path, kept_path):
    page.add("## Exact quickhull against qhull on the same points", "")
    page.para(run_line(default_path, "real_time", "min",
                       " The memory-kept file is a second run of the same binary."))
    page.para("The CHMS oracle and `cvms hull` use this quickhull. \"Exact input\" hulls exact rational "
              "points (`hull_soup`), \"double input\" the same points given as doubles, as qhull gets them "
              "(`convex_hull`, which also builds the polyhedron). Each is run under glibc's default malloc "
              "policy and with freed memory kept (`MALLOC_TRIM_THRESHOLD_=4000000000 "
              "MALLOC_MMAP_THRESHOLD_=268435456 MALLOC_TOP_PAD_=67108864`); the section on memory below "
              "says why both.")
    lines = ["| points | malloc policy | exact input (ms) | double input (ms) | qhull (ms) | exact / qhull "
             "| double / qhull |", "|---|---|---:|---:|---:|---:|---:|"]
    for label, path in (("default", default_path), ("memory kept", kept_path)):
        for case, ours, doubles, theirs in qhull_ratios.ratio_rows(bench_json.rows(path, "real_time", "min")):
            d = "—" if doubles is None else fmt_ms(doubles)
            dr = "—" if doubles is None else f"{doubles / theirs:.2f}"
            lines.append(f"| {case} | {label} | {fmt_ms(ours)} | {d} | {fmt_ms(theirs)} | {ours / theirs:.2f} | {dr} |")
    page.block(lines)


def sets_section(page, path):
    rows = bench_json.rows(path, "cpu_time", "min")
    page.add("## Sums of convex sets: flat operands and zonotopes", "")
    page.para(run_line(path, "cpu_time", "min"))
    page.para("The peer for a flat operand is what one does without a set sum: qhull's floating-point hull "
              "of all pairwise vertex sums, timed from the sums already in doubles (the 1,000-gon's 10^7 "
              "sums are beyond a benchmark's budget). Zonotopes of n generators have n² − n + 2 vertices; "
              "the fold by exact hulls of pairwise vertex sums runs up to n = 50.")
    page.block(set_table.sums_table(rows))
    page.block(set_table.zonotope_table(rows))
    slope = set_table.zonotope_slope(rows)
    text = []
    if slope is not None:
        text.append(f"Zonotope time against output facets has a least-squares log-log slope of {slope:.2f} "
                    "(n = 10 … 200), where the fold by exact hulls grows about as the cube of n.")
    if "BM_SumOfTenRandomHulls" in rows:
        ms, b = rows["BM_SumOfTenRandomHulls"]
        text.append(f"The n-ary sum of ten random 30-point hulls ({int(b['F']):,} facets) takes {fmt_ms(ms)} ms.")
    page.para(" ".join(text))


def halfspace_section(page, qhull_path, cgal_path):
    page.add("## Half-spaces and the Pontryagin difference", "")
    page.para("Exact `from_halfspaces` against qhull's half-space intersection (`qhull H<x,y,z>`, i.e. "
              "`qhalf` with the interior point given, in floating point, on the rows rounded to doubles) "
              "and CGAL's `halfspace_intersection_3` with Epeck (the same rows converted exactly, the same "
              "interior point given). The exact rows find their own interior point (a max-slack LP) inside "
              "the timed loop. Sphere rows: the facet planes of Sphere_k, none redundant; redundant rows: "
              "the facet planes of the hull of n seeded ball points plus as many loosened copies. CGAL's "
              "`V` counts the triangles of its triangulated dual hull, more than the intersection's "
              "vertices wherever more than three planes meet.")
    labels = {"Sphere/4": "Sphere4 facet planes", "Sphere/5": "Sphere5 facet planes",
              "Sphere/6": "Sphere6 facet planes", "Redundant/10000": "hull of 10^4 points + redundant rows",
              "Redundant/100000": "hull of 10^5 points + redundant rows"}

    def three_way(path, time_field, with_cgal):
        rows = bench_json.rows(path, time_field, "min")
        header = "| rows | count | vertices | exact (ms) | qhull (ms) | exact / qhull |"
        rule = "|---|---:|---:|---:|---:|---:|"
        if with_cgal:
            header += " CGAL (ms) | CGAL / exact |"
            rule += "---:|---:|"
        lines = [header, rule]
        for key, label in labels.items():
            ours = rows.get("BM_FromHalfspaces_" + key)
            if ours is None:
                continue
            ms, b = ours
            q = rows.get("BM_Qhalf_" + key)
            cells = [label, f"{int(b['rows']):,}", f"{int(b['V']):,}", fmt_ms(ms),
                     fmt_ms(q[0]) if q else "—", f"{ms / q[0]:.2f}" if q else "—"]
            if with_cgal:
                c = rows.get("BM_CgalHalfspaces_" + key)
                cells += [fmt_ms(c[0]) if c else "—", ratio(c[0], ms, 0) if c else "—"]
            lines.append("| " + " | ".join(cells) + " |")
        return lines

    page.para(run_line(qhull_path, "real_time", "min"))
    page.block(three_way(qhull_path, "real_time", False))
    page.para(run_line(cgal_path, "cpu_time", "min",
                       " A second run with CGAL's rows as well; the exact / qhull ratios of the two runs "
                       "differ by more than the code could: read each run's ratios within it."))
    page.block(three_way(cgal_path, "cpu_time", True))

    rows = bench_json.rows(qhull_path, "real_time", "min")
    lines = ["| difference | rows of A | output V / F | exact (ms) |", "|---|---:|---:|---:|"]
    for name, label in [("BM_Pontryagin_SphereCube/4", "Sphere4 ⊖ [−1/10, 1/10]³"),
                        ("BM_Pontryagin_SphereCube/5", "Sphere5 ⊖ [−1/10, 1/10]³"),
                        ("BM_Pontryagin_SphereCube/6", "Sphere6 ⊖ [−1/10, 1/10]³"),
                        ("BM_Pontryagin_RandomHulls", "10^5-point ball hull ⊖ a 10^3-point one shrunk 10×")]:
        if name in rows:
            ms, b = rows[name]
            lines.append(f"| {label} | {int(b['rows']):,} | {int(b['V']):,} / {int(b['F']):,} | {fmt_ms(ms)} |")
    page.para("`pontryagin_difference` (same run as the first table):")
    page.block(lines)


SOLID_LABELS = {
    "spot": "spot.obj (scanned-style mesh, 6-digit decimals)",
    "l_block": "L-block",
    "star_prism": "star prism",
    "box_with_hole": "box with a square hole (genus 1)",
    "cavity_cube": "cube with a cubic cavity",
    "nested_shells": "cube, cavity, cube inside it",
    "two_cubes": "two disjoint cubes",
}

PAIR_LABELS = {
    "spot+icosphere": "spot ⊕ icosphere (Sphere2 scaled 1/20)",
    "spot+l_block_small": "spot ⊕ L-block scaled 1/10",
    "star_prism+box_with_hole": "star prism ⊕ box with a hole",
}


def pieces_rows(path):
    """{kind: {name: {threads: (ms, entry)}}} from the rows "BM_<kind>/<name>[/<threads>]": the one-thread
    rows in CPU time (steadier on a shared machine), the two-thread rows in wall time (their CPU time is
    the calling thread's alone)."""
    out = {}
    timed = dict(bench_json.rows(path, "real_time", "min"))
    timed.update(bench_json.rows(path, "cpu_time", "min"))
    for key, value in timed.items():
        parts = key.split("/")
        threads = int(parts[2]) if len(parts) == 3 else 1
        out.setdefault(parts[0], {}).setdefault(parts[1], {})[threads] = value
    return out


def pieces_section(page, path):
    if not os.path.exists(path):
        return
    rows = pieces_rows(path)
    decompositions = rows.get("BM_Decompose", {})
    sums, peers = rows.get("BM_SumPieces", {}), rows.get("BM_QhullPairs", {})
    page.add("## Non-convex solids", "")
    page.para(run_line(path, "cpu_time", "min", " The two-thread columns are wall time (their CPU time counts "
                       "the calling thread only)."))
    page.para("`cvms_pieces_bench`, reproduced by the command below. `convex_decomposition` cuts the solid by "
              "its own facet planes (planes of facets on reflex edges first) into convex cells and merges "
              "neighbouring cells whose union is convex; the piece count drives every later step. The solids "
              "are the files of `test/data/solids`: spot.obj (CC0, the real mesh) and the small non-convex "
              "fixtures.")
    page.block(["```sh", PIECES_COMMAND, "```"])
    lines = ["| solid | vertices | facets | reflex edges | pieces | facets of the pieces | decomposition (ms) |",
             "|---|---:|---:|---:|---:|---:|---:|"]
    for name, label in SOLID_LABELS.items():
        if name not in decompositions:
            continue
        ms, b = decompositions[name][1]
        lines.append(f"| {label} | {int(b['vertices']):,} | {int(b['facets']):,} | {int(b['reflex_edges']):,} "
                     f"| {int(b['pieces']):,} | {int(b['piece_facets']):,} | {fmt_ms(ms)} |")
    page.block(lines)
    page.para("A sum of two solids is the union of the pairwise CVMS sums of their pieces "
              "(`minkowski_sum(ConvexUnion, ConvexUnion, Options)`, `Options::threads` spreading the pairs). "
              "The rows time that pairwise step alone, from the decompositions above. The peer is the "
              "floating-point hull-of-pairs sum: qhull's hull of the pairwise vertex sums of every piece pair, "
              "from the same pieces, the sums formed exactly and rounded to doubles before the timed loop "
              "(which favours qhull), on as many threads as the exact rows (the pairs shared through an atomic "
              "counter). qhull merges facets in floating point; the exact facet count is ours. Times in ms.")
    lines = ["| pair | pieces | output pieces | output facets (exact / qhull) | exact, 1 thread | qhull, 1 thread "
             "| exact / qhull | exact, 2 threads | qhull, 2 threads | exact / qhull |",
             "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for name, label in PAIR_LABELS.items():
        if 1 not in sums.get(name, {}):
            continue
        ms, b = sums[name][1]
        cells = [label, f"{int(b['pieces_A']):,} × {int(b['pieces_B']):,}", f"{int(b['out_pieces']):,}"]
        peer = peers.get(name, {}).get(1)
        cells.append(f"{int(b['out_facets']):,} / " + (f"{int(peer[1]['peer_facets']):,}" if peer else "—"))
        for threads in (1, 2):
            ours, theirs = sums[name].get(threads), peers.get(name, {}).get(threads)
            cells += [fmt_ms(ours[0]) if ours else "—", fmt_ms(theirs[0]) if theirs else "—",
                      f"{ours[0] / theirs[0]:.2f}" if ours and theirs else "—"]
        lines.append("| " + " | ".join(cells) + " |")
    page.block(lines)
    load = bench_json.context(path).get("load_avg")
    if load and load[0] > 2:
        page.para(f"This run shared the machine with other jobs (load average {load[0]:.1f} on 2 CPUs when it "
                  "started): the one-thread columns are CPU time, which such sharing inflates far less, but the "
                  "two-thread columns are wall time, and with both cores busy elsewhere they measure the sharing "
                  "more than the threads. Compare the exact and qhull columns of one thread count, not the two "
                  "thread counts.")
    spot = decompositions.get("spot", {}).get(1)
    ball = sums.get("spot+icosphere", {}).get(1)
    if spot and ball:
        page.para(f"On spot the decomposition dominates the whole sum: {fmt_ms(spot[0])} ms to decompose "
                  f"against {fmt_ms(ball[0])} ms for the {int(ball[1]['out_pieces']):,} pairwise sums with the "
                  "icosphere (both on one thread); a solid decomposed once can be summed with many operands. "
                  "Its time is spread over the auto-partition (choosing each splitting plane, cutting cells and "
                  "boundary fragments) and the merge (exact hulls and volumes of candidate unions): exact "
                  "rational arithmetic with its gcd normalisation, the conversions of rational coordinates to "
                  "the predicates' floating-point filters, and the allocations of exact numbers.")


def failed_rows(path, prefix):
    """The distinct error messages of the rows named "<prefix>/..." that failed in the run."""
    with open(path) as f:
        entries = json.load(f)["benchmarks"]
    return sorted({b.get("error_message", "?") for b in entries
                   if b.get("error_occurred") and b["name"].startswith(prefix + "/")})


def solid_sum_section(page, bench_dir):
    path = path_in(bench_dir, "solid_sum.json")
    manifold_path = path_in(bench_dir, "solid_sum_manifold.json")
    end_to_end_path = path_in(bench_dir, "solid_sum_end_to_end.json")
    if not (os.path.exists(path) or os.path.exists(manifold_path)):
        return
    nef_spot_path = path_in(bench_dir, "solid_sum_nef_spot.json")
    rows, manifold = solid_sum_table.load(path, nef_spot_path), solid_sum_table.load(manifold_path)
    page.add("## Non-convex sums as one closed solid", "")
    if os.path.exists(path):
        page.para(run_line(path, "cpu_time", "min", " The two-thread rows are wall time (their CPU time counts "
                           "the calling thread only); the CGAL Nef rows ran once each."))
    if os.path.exists(nef_spot_path):
        page.para(run_line(nef_spot_path, "cpu_time", "min", " CGAL Nef on spot ⊕ icosphere, run on its own "
                           "(minutes)."))
    if os.path.exists(manifold_path):
        c = bench_json.context(manifold_path)
        page.para(f"*`docs/bench/{os.path.basename(manifold_path)}` (`bench/manifold_peer.py`): "
                  f"{c.get('peer', 'Manifold')}, CPU time, the minimum of each pair's runs in one node process; "
                  f"{c.get('num_cpus', '?')} CPUs, load average {c.get('load_avg', [0])[0]:.1f} when the run "
                  "started.*")
    page.para("`minkowski_sum(Solid, Solid)` returns the exact boundary of A ⊕ B as one closed solid. The pairs: "
              "four small non-convex solids (the L-block, the frame (a box with a square hole), the star prism "
              "of `test/data/solids`, the coarse torus of `bench/data/solids`), each ⊕ the cube [−1/4, 1/4]³ "
              "(one operand convex: nothing is decomposed) and ⊕ each other (both decomposed); spot.obj ⊕ "
              "Sphere2 scaled by 1/20 (42 vertices, radius 2 % of spot's bounding-box diagonal); and the "
              "output-sensitive family, combs of k teeth ⊕ the cube. The peers sum the same solids: CGAL's "
              "exact Nef `minkowski_sum_3` in the same binary and run (the conversion of both surface meshes "
              "to Nef polyhedra included), and Manifold's floating-point `minkowskiSum` (WebAssembly under "
              "node, single precision coordinates) on the triangle files the benchmark writes. Each of "
              "Manifold's results is then checked exactly by `cvms check` (its float32 coordinates read "
              "exactly): a closed, oriented, non-self-intersecting solid with no two vertices at one point "
              "and no degenerate face. Reproduced by:")
    page.block(["```sh", "CVMS_BENCH_NEF=small " + SOLID_SUM_COMMAND, "```"])
    failed = failed_rows(path, "BM_SolidSum") if os.path.exists(path) else []
    if failed:
        page.para("cvms's own rows failed in this run (" + "; ".join(f"`{m}`" for m in failed) + "): the tables "
                  "below show the peers alone.")
    page.para("In process. \"pieces stage\" is the convex pieces alone, before any union: "
              "`minkowski_sum_pieces` (both decompositions and the pairwise sums) when both operands are "
              "non-convex, the convex sums of A's boundary triangles with the convex B otherwise; \"writing\" "
              "is the result's exact OFF text (to memory). The last column is the other road where one "
              "operand is convex: the union of the pieces of both decompositions. Times in ms.")
    page.block(solid_sum_table.in_process_table(rows))
    page.para("Side by side: cvms, CGAL Nef and Manifold on the same solids (the ratios are the peer's time "
              "over cvms's).")
    page.block(solid_sum_table.peers_table(rows, manifold))
    bad, checked = solid_sum_table.manifold_failures(manifold)
    if checked:
        page.para(f"Manifold's result failed the exact check on {bad} of the {checked} pairs.")
    summary = solid_sum_table.summary(rows, manifold)
    if summary:
        page.para(summary)
    page.para("Output-sensitive scaling: a comb of k teeth (the prism over a comb polygon, 4k vertices a cap) "
              "⊕ the cube; the output grows linearly in k.")
    page.block(solid_sum_table.scaling_table(rows, manifold))
    slopes = solid_sum_table.comb_slopes(rows, manifold)
    if slopes:
        page.para("Least-squares log-log slopes of time on the combs (1 is linear): "
                  + ", ".join(f"{label} {s:.2f}" for label, s in slopes.items()) + ".")
    if os.path.exists(end_to_end_path):
        with open(end_to_end_path) as f:
            results = json.load(f)
        page.para(f"End to end (`docs/bench/{os.path.basename(end_to_end_path)}`, "
                  "`bench/solid_sum_end_to_end.py`): whole `cvms sum` runs from file to file on the same "
                  "operand files, the minimum wall time over the rounds, with the sum's own time inside the run "
                  "(`--stats`) and the peak resident memory.")
        page.block(solid_sum_table.end_to_end_table(results))


def decimal_section(page, path):
    rows = bench_json.rows(path, "cpu_time", "min")
    general = rows.get("BM_DecimalSum_general/20000")
    self_sum = rows.get("BM_DecimalSum_self/20000")
    if not (general and self_sum):
        return
    page.add("## Decimal coordinates and exact ties", "")
    page.para(run_line(path, "cpu_time", "min"))
    page.para("Scanned meshes come with short decimal coordinates, none of them a double, so nothing is "
              "dyadic. Two hulls of 20,000-point clouds in a thin shell, coordinates rounded to 6 decimals: "
              "two independent clouds (general position), and one hull plus itself (A + A: every facet has a "
              "parallel twin, so every contributing-vertex choice is an exact tie that no floating-point "
              "filter can prove).")
    lines = ["| pair | vertices | output facets | time (ms) | µs per output facet |", "|---|---:|---:|---:|---:|"]
    per = {}
    for label, (ms, b) in (("two independent decimal hulls", general), ("the same hull twice (A + A)", self_sum)):
        per[label] = 1e3 * ms / b["out_facets"]
        lines.append(f"| {label} | {int(b['vertices_A']):,} + {int(b['vertices_B']):,} | {int(b['out_facets']):,} "
                     f"| {fmt_ms(ms)} | {per[label]:.2f} |")
    page.block(lines)
    a, g = per["the same hull twice (A + A)"], per["two independent decimal hulls"]
    page.para(f"A + A costs {a / g:.2f}× the time per output facet of the general pair: the planar sums of "
              "its parallel facet pairs scale both polygons to 64-bit integers over the common denominator "
              "of their coordinates (it divides 10^6 here) and merge them in 64/128-bit arithmetic, with no "
              "filter, no GMP and no gcd (`lib/planar/small_points.cpp`).")
    written_section(page, path)


WRITTEN_FAMILIES = (("SphereRot", "Sphere6 + rotated Sphere6"), ("CubeSphere", "Cube + Sphere6"))
WRITTEN_FORMS = ("exact dyadic expansions", "shortest round-trip decimals", "6-digit decimals")


def written_section(page, path):
    """The scaling families at k = 6 with both operands written three ways (BM_Written_*/6/<form>)."""
    rows = bench_json.rows(path, "cpu_time", "min")
    table = {}
    for key, label in WRITTEN_FAMILIES:
        forms = [rows.get(f"BM_Written_{key}/6/{form}") for form in range(3)]
        if all(forms):
            table[label] = forms
    if not table:
        return
    page.add("### The same sums, operands written three ways", "")
    page.para("The scaling families at k = 6 (every coordinate a double), both operands written as text three "
              "ways and read back exactly (`read_off` from a string stream, then `from_soup`, with their facet "
              "planes, outside the timing): the exact binary expansions of the doubles (dyadic rationals); the "
              "shortest decimals that read back to the same doubles (`std::to_chars`, as Python, numpy and "
              "most exporters write them; read exactly, `0.1` is 1/10, so these are other numbers than the "
              "doubles, with denominators up to about 10^17); 6 decimals (denominators 10^6). Same run as the "
              "table above; the cube's coordinates are integers in every form.")
    lines = ["| sum | operands written as | output facets | time (ms) | µs per output facet | / dyadic |",
             "|---|---|---:|---:|---:|---:|"]
    for label, forms in table.items():
        dyadic = forms[0][0]
        for form, (ms, b) in zip(WRITTEN_FORMS, forms):
            lines.append(f"| {label} | {form} | {int(b['out_facets']):,} | {fmt_ms(ms)} "
                         f"| {1e3 * ms / b['out_facets']:.2f} | {ratio(ms, dyadic, 2)} |")
    page.block(lines)
    profile_section(page, os.path.join(os.path.dirname(path), "decimal_profile.json"), table)
    before_after_section(page, os.path.join(os.path.dirname(path), "decimal_before_after.json"))


def before_after_section(page, path):
    """The rows of bench/decimal_before_after.py: two release trees run alternately."""
    if not os.path.exists(path):
        return
    with open(path) as f:
        data = json.load(f)
    before, after = data["cpu_ms_min"]["before"], data["cpu_ms_min"]["after"]
    page.para(f"*`docs/bench/{os.path.basename(path)}` (`bench/decimal_before_after.py`): two release trees "
              f"run alternately, {data['rounds']} rounds; CPU time, the minimum over all repetitions of all "
              "rounds. `--before` carries an operand as machine integers over its common denominator only "
              "when that denominator is below 2^63 (scaled coordinates below 2^61) and makes the vertices "
              "of other non-dyadic operands as GMP rationals; `--after`, the code on this page, also carries "
              "operands whose common denominator is below 2^124 as 128-bit integers "
              "(`lib/numeric/two_word_scaled.cpp`): their sum's vertices are 128-bit integers over the lcm "
              "of the two denominators, their edge directions differences of those integers.*")
    forms = dict(zip(("0", "4", "5"), WRITTEN_FORMS))
    labels = {f"BM_Written_{key}/6/{i}": f"{label}, {WRITTEN_FORMS[i]}" for key, label in WRITTEN_FAMILIES
              for i in range(3)}
    for step, name in (("load", "BM_load"), ("validate with the facet planes", "BM_validate_and_planes"),
                       ("coordinates parsed exactly", "BM_parse_numbers")):
        labels.update({f"{name}/{i}": f"Sphere6 {step}, {form}" for i, form in forms.items()})
    lines = ["| row | `--before` (ms) | `--after` (ms) | after / before |", "|---|---:|---:|---:|"]
    for name, label in labels.items():
        if name in before and name in after:
            lines.append(f"| {label} | {fmt_ms(before[name])} | {fmt_ms(after[name])} "
                         f"| {after[name] / before[name]:.2f} |")
    page.block(lines)


PROFILE_FORMS = (("dyadic", 0), ("shortest", 1), ("six_digits", 2))


def profile_section(page, path, table):
    """Where Sphere6 + rotated Sphere6's time goes in each written form: the phase shares of
    docs/bench/decimal_profile.json (bench/perf_phases.py) times the row's time in the table above."""
    forms = table.get("Sphere6 + rotated Sphere6")
    if not forms or not os.path.exists(path):
        return
    with open(path) as f:
        rows = json.load(f)["rows"]
    if not all(name in rows for name, _ in PROFILE_FORMS):
        return
    page.para("Where the time of Sphere6 + rotated Sphere6 goes (`docs/bench/decimal_profile.json`: "
              "`perf record --call-graph dwarf` of each row, the samples inside `minkowski_sum` split by the "
              "functions on their stack by `bench/perf_phases.py`, whose header gives the commands; the "
              "shares times each row's time above, in ms; phases nest, so indented rows are parts of the row "
              "above them):")
    names = list(rows["dyadic"]["phases"])
    lines = ["| phase | " + " | ".join(f"{label} (ms)" for label in WRITTEN_FORMS) + " |",
             "|---|" + "---:|" * len(WRITTEN_FORMS)]
    ms = {}
    for name in names:
        cells = []
        for form, i in PROFILE_FORMS:
            ms[(name, form)] = rows[form]["phases"][name] * forms[i][0]
            cells.append(fmt_ms(ms[(name, form)]))
        label = name.replace("output build: ", "&nbsp;&nbsp;") if name.startswith("output build: ") else name
        lines.append(f"| {label} | " + " | ".join(cells) + " |")
    for group in rows["dyadic"]["innermost"]:
        cells = [fmt_ms(rows[form]["innermost"][group] * forms[i][0]) for form, i in PROFILE_FORMS]
        lines.append(f"| innermost frame in {group} | " + " | ".join(cells) + " |")
    page.block(lines)
    search = "search: contributing vertices and edge-facet trace"
    build, normals = "output build", "output build: facet normals"
    vertices, sums = "output build: vertices and mesh", "output build: vertices as rationals"

    def more(phase):
        return fmt_ms(ms[(phase, "shortest")] - ms[(phase, "dyadic")])

    page.para(
        f"With shortest decimals the sum takes {fmt_ms(forms[1][0] - forms[0][0])} ms more than with the "
        f"dyadic operands. The search, {more(search)} ms more, decides its predicates on the floating-point "
        "filters in every form (the rows' `exact_share` counter is the same for the three forms); its "
        "operands' approximations are read off 128-bit integers over a decimal denominator instead of a "
        f"double's bits. The output build takes {more(build)} ms more: the vertices and the mesh "
        f"{more(vertices)} ms (128-bit vertex integers over a denominator of 10^19 or more, whose "
        "approximations need a 128-bit division where a dyadic vertex is a packed 16-byte value made from "
        f"machine words), the facet normals {more(normals)} ms (cross products of the edge directions made "
        "primitive in GMP where a double's direction is a few shifts of its bits). No vertex is made as a "
        "GMP rational and no edge direction takes the general rational path in any form (the zero rows). "
        f"GMP's own code is {100 * rows['shortest']['innermost']['GMP']:.0f} % of the shortest-decimal sum's "
        f"samples, against {100 * rows['dyadic']['innermost']['GMP']:.0f} % with dyadic operands.")
    page.para(
        "6-digit decimals share one denominator, 10^6: each operand is scaled once, on first use, to machine "
        "integers over it (`lib/numeric/word_scaled.cpp`, whenever the common denominator is below 2^63 and the "
        "scaled coordinates below 2^61), the sum's vertices are 128-bit integers over the product or common "
        "denominator (`ScaledPoints`, `lib/numeric/scaled_points.cpp`, with `Approx::of`'s doubles read off the "
        "integers; the canonical rationals are made only when read) and the edge directions differences of the "
        f"operands' integers: {forms[2][0] / forms[0][0]:.2f}× the dyadic sum, the output build "
        f"{fmt_ms(ms[(build, 'six_digits')])} ms against {fmt_ms(ms[(build, 'dyadic')])} ms. Shortest "
        "round-trip decimals do not fit one word: a coordinate below 0.01 in magnitude keeps 17 significant "
        "digits, so its denominator is 10^19 or more, beyond 2^63, and the operand's common denominator "
        "with it. Below 2^124 such an operand is carried as 128-bit integers over its denominator "
        "(`lib/numeric/two_word_scaled.cpp`): the sum's vertices are 128-bit integers over the lcm of the "
        "two denominators, the edge directions differences of the integers with their common powers of 2 "
        "and 5 divided out.")


def load_forms_section(page, path):
    """Sphere6 loaded in each written form (BM_load/BM_parse/... of inputs 0, 4, 5) against parsing its numbers."""
    rows = bench_json.rows(path, "cpu_time", "min")
    inputs = (("exact dyadic expansions", 0), ("shortest round-trip decimals", 4), ("6-digit decimals", 5))
    steps = (("load: parse + validate", "BM_load"), ("load, then the facet planes", None),
             ("parse alone (`read_off`)", "BM_parse"), ("validate alone (`from_soup`)", "BM_validate"),
             ("validate and make the facet planes", "BM_validate_and_planes"),
             ("its coordinates parsed exactly (`try_parse_rational`)", "BM_parse_numbers"),
             ("its coordinates parsed to doubles (`std::from_chars`)", "BM_parse_numbers_double"))
    if not all(rows.get(f"BM_parse_numbers/{i}") for _, i in inputs):
        return
    numbers = int(rows["BM_parse_numbers/0"][1]["numbers"])
    page.para(f"Sphere6 (20,480 facets, {numbers:,} coordinates, all doubles) written three ways, as in the "
              "sums above. \"Load, then the facet planes\" is the load plus the planes' share of validating with "
              "planes (`validate and make the facet planes` − `validate alone`): a loaded polyhedron makes its "
              "planes on first use, and the first sum with it pays for them.")
    lines = ["| step | " + " | ".join(f"{label} (ms)" for label, _ in inputs) + " |",
             "|---|" + "---:|" * len(inputs)]
    value = {}
    for label, name in steps:
        cells = []
        for _, i in inputs:
            if name is None:
                ms = rows[f"BM_load/{i}"][0] + rows[f"BM_validate_and_planes/{i}"][0] - rows[f"BM_validate/{i}"][0]
            else:
                ms = rows[f"{name}/{i}"][0]
            value[(label, i)] = ms
            cells.append(fmt_ms(ms))
        lines.append(f"| {label} | " + " | ".join(cells) + " |")
    page.block(lines)
    load, numbers = "load: parse + validate", "its coordinates parsed exactly (`try_parse_rational`)"
    planes = "load, then the facet planes"
    page.para("Load over the exact parse of the numbers alone: " +
              ", ".join(f"{label} {value[(load, i)] / value[(numbers, i)]:.1f}× "
                        f"({value[(planes, i)] / value[(numbers, i)]:.1f}× with the planes)"
                        for label, i in inputs) + ".")


def load_before_after_section(page, timings_path):
    """The load rows of two trees run alternately (bench/load_before_after.py), and where the rest goes."""
    with open(timings_path) as f:
        timings = json.load(f)["load_ms_cpu_min"]
    before, after = timings.get("before", {}), timings.get("after", {})
    inputs = (("Sphere6, exact dyadic expansions", 0), ("Sphere6, shortest round-trip decimals", 4),
              ("Sphere6, 6-digit decimals", 5), ("hull of 35,000 points, 6-digit decimals", 1),
              ("box of 19,200 triangles", 2), ("box of 9,600 quads", 3))
    steps = (("load", "BM_load"), ("parse alone", "BM_parse"), ("validate alone", "BM_validate"),
             ("coordinates parsed exactly", "BM_parse_numbers"))
    page.para("*`docs/bench/load_before_after.json`: `bench/load_before_after.py --rounds 3 --checks 0`, two "
              "release trees run alternately; CPU time, the minimum over all repetitions of all rounds, on a "
              "machine shared with other jobs. `--after` reads face indices in one pass over their digits, counts "
              "the bits of parsed numbers from their top limbs, approximates one-limb fractions by one machine "
              "division in `Approx::of` and sorts the duplicate-point check on a key of the coordinates' limbs; "
              "`--before` does not.*")
    lines = ["| row | `--before` (ms) | `--after` (ms) | after / before |", "|---|---:|---:|---:|"]
    for label, i in inputs:
        for step, name in steps:
            b, a = before.get(f"{name}/{i}"), after.get(f"{name}/{i}")
            if b and a:
                lines.append(f"| {label}: {step} | {fmt_ms(b)} | {fmt_ms(a)} | {a / b:.2f} |")
    page.block(lines)
    ratios = []
    for label, i in inputs[:3]:
        keys = (f"BM_load/{i}", f"BM_parse_numbers/{i}")
        if all(k in before and k in after for k in keys):
            ratios.append(f"{label.split(', ')[1]} {before[keys[0]] / before[keys[1]]:.2f}× (`--before`) and "
                          f"{after[keys[0]] / after[keys[1]]:.2f}× (`--after`)")
    if ratios:
        page.para("Load over the exact parse of the numbers alone in that run (the target is 3×): " +
                  ", ".join(ratios) + ". Where the rest of a load of Sphere6 from its shortest decimals goes "
                  "(`perf record` on `cvms_load_bench --benchmark_filter='BM_load/4$'`, the `--after` tree, "
                  "shares of the samples): the convexity proof of `ConvexPolyhedron::from_soup` about a third "
                  "(the filtered orientations of every face and edge, the merge of coplanar faces, the sphere "
                  "topology), the half-edge build of `Mesh::from_soup` with its duplicate check about a seventh, "
                  "`malloc` and `free` about an eighth (GMP allocates a numerator and a denominator per "
                  "coordinate while parsing and frees them with the polyhedron: the public `Vec3` holds "
                  "`mpq_class` values), the number parser a tenth and the line and token scanning a tenth. No "
                  "one of them alone brings the load to 3× the parse, and the allocations go only with "
                  "coordinates held outside `mpq_class`.")


def load_section(page, load_path, timings_path):
    page.add("## Loading and writing", "")
    page.para("In process (`cvms_load_bench`): loading a polyhedron is parsing the exact OFF text "
              "(`read_off`) and validating it (`from_soup`: convexity, merging of coplanar faces, facet "
              "normals), as `read_polyhedron` does; writing is the exact OFF text.")
    if os.path.exists(timings_path):
        load_before_after_section(page, timings_path)
    page.para(run_line(load_path, "cpu_time", "min"))
    load_forms_section(page, load_path)
    rows = bench_json.rows(load_path, "cpu_time", "min")
    write = rows.get("BM_write/1")
    total = rows.get("BM_sum")
    if write and total:
        w, b = write
        w0 = rows.get("BM_write/0")
        text = (f"Writing the exact OFF of Sphere6 + rotated Sphere6 ({int(b['facets']):,} facets, "
                f"{b['bytes'] / 1e6:.1f} MB) takes {fmt_ms(w)} ms against {fmt_ms(total[0])} ms for the sum in "
                f"the same run: {100 * w / total[0]:.0f} % of computing it.")
        if w0:
            text += f" Sphere6's own OFF ({int(w0[1]['facets']):,} facets) takes {fmt_ms(w0[0])} ms."
        decimal = [(label, rows.get(f"BM_write/{i}")) for label, i in
                   (("Sphere6 read from its shortest round-trip decimals", 2),
                    ("Sphere6 read from its 6-digit decimals", 3),
                    ("the sum of Sphere6 and rotated Sphere6 both read from their shortest decimals", 4))]
        if all(r for _, r in decimal):
            text += (" Decimal coordinates are integers over a power of ten, printed from machine words: "
                     + "; ".join(f"{label} ({int(r[1]['facets']):,} facets, {r[1]['bytes'] / 1e6:.1f} MB) "
                                 f"{fmt_ms(r[0])} ms" for label, r in decimal) + ".")
        page.para(text)


def end_to_end_section(page, path):
    with open(path) as f:
        results = json.load(f)
    page.add("## End to end: the command-line tool", "")
    page.para(f"*`docs/bench/{os.path.basename(path)}` (`bench/end_to_end.py`): the minimum wall time over "
              "the rounds of each whole `cvms` run, from file to file, with the peak resident memory of that "
              "process and the sum's own time inside it (`cvms sum --stats`); the CPU time (user + system) is "
              "the least over the rounds, the figure to trust on a shared machine.*")
    page.para("The sums also report (`--stats`) their read time (parsing and validating both operands, with "
              "their facet planes, in parentheses, made before the sum starts) and write time (the exact "
              "output, replaced atomically: written to a temporary file, synchronised to disk, renamed; the "
              "wait for the disk in parentheses), wall times inside the run like the sum's: \"work\" is "
              "read + sum + write, and what the wall time holds beyond it is the process's start and exit "
              "(`cvms check cube.off` is little else). The row into /dev/null writes without the temporary "
              "file and its synchronisation.")
    lines = ["| command | wall (ms) | CPU (ms) | sum in process (ms) | read (planes) (ms) | write (sync) (ms) "
             "| wall / sum | CPU / sum | wall / work | peak RSS (MiB) |",
             "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]

    def with_part(total, part):
        if total is None:
            return "—"
        return fmt_ms(total) + (f" ({fmt_ms(part)})" if part is not None else "")

    for name, r in results.items():
        s, read, write = r.get("sum_ms"), r.get("read_ms"), r.get("write_ms")
        work = s + read + write if s and read is not None and write is not None else None
        cpu = r.get("cpu_ms")
        lines.append(f"| `cvms {name}` | {fmt_ms(r['wall_ms'])} | {fmt_ms(cpu) if cpu else '—'} "
                     f"| {fmt_ms(s) if s else '—'} | {with_part(read, r.get('planes_ms')) if work else '—'} "
                     f"| {with_part(write, r.get('sync_ms')) if work else '—'} "
                     f"| {ratio(r['wall_ms'], s) if s else '—'} | {ratio(cpu, s) if s and cpu else '—'} "
                     f"| {ratio(r['wall_ms'], work) if work else '—'} | {r['peak_rss_bytes'] / 2**20:.1f} |")
    page.block(lines)


def python_section(page, path):
    if not os.path.exists(path):
        return
    with open(path) as f:
        results = json.load(f)
    page.add("## From Python", "")
    page.para(f"*`docs/bench/{os.path.basename(path)}` (`python/bench/sum_overhead.py`): the same sum called "
              "from Python (`cvms.minkowski_sum`) and in C++ (the time `cvms sum --stats` reports for the sum "
              "alone), on the same files, the module and the tool from one release build tree; the minimum of "
              "interleaved runs of each.*")
    lines = ["| sum | C++ (ms) | Python (ms) | Python / C++ |", "|---|---:|---:|---:|"]
    for name, r in results.items():
        lines.append(f"| {name} | {fmt_ms(r['cpp_ms'])} | {fmt_ms(r['python_ms'])} "
                     f"| {r['python_ms'] / r['cpp_ms']:.2f} |")
    page.block(lines)


def explanations(page, stimes, speaks, sfacets):
    """What the numbers mean: lasting explanations, with their figures taken from the JSON."""
    page.add("## What the numbers mean", "")

    rot, cube = stimes.get("SphereRot", {}), stimes.get("CubeSphere", {})

    def at(series, name, k):
        return series.get(name, {}).get(k)

    page.add("### Where a sum's time goes", "")
    text = ("A sum is a search (the contributing-vertex walks and climbs, the Gaussian-arc trace of the edge "
            "facets) and the build of its exact output (the half-edge mesh, the exact vertex coordinates "
            "and the facet normals). The two limits bound the build: `limit build` is all of it, "
            "`limit mesh` the mesh with its packed exact vertices alone, so their difference is the normals.")
    k6 = [at(rot, n, 6) for n in ("CVMS", "limit build", "limit mesh")]
    if all(k6):
        cvms6, build6, mesh6 = k6
        text += (f" On Sphere6 + rotated Sphere6 CVMS takes {fmt_ms(cvms6)} ms, of which the output build is "
                 f"{fmt_ms(build6)} ms ({100 * build6 / cvms6:.0f} %), and the normals are "
                 f"{100 * (1 - mesh6 / build6):.0f} % of the build.")
    c6 = [at(cube, n, 6) for n in ("CVMS", "limit build", "limit mesh")]
    if all(c6):
        text += (f" On Cube + Sphere6 the build is {100 * c6[1] / c6[0]:.0f} % of the sum and the normals "
                 f"{100 * (1 - c6[2] / c6[1]):.0f} % of the build: nearly every facet there is a facet of the "
                 "sphere, translated, whose normal (primitive, of about 100 bits) the build copies.")
    page.para(text)
    page.para("Every output coordinate of a sum of operands read from doubles is dyadic, and the build "
              "writes it as a 16-byte packed value straight from machine words, with no GMP call and no heap "
              "block per number; the `Vec3`s a caller asks for are made on first use. What remains of the "
              "build is the mesh (its corner sort and topology checks), the primitive normals of the edge "
              "facets (cross products of integer edge directions and their 128-bit gcds) and the loads of "
              "the operands' coordinates, which the search meets out of memory order.")

    page.add("### Why a sum's facet normals are built with it", "")
    text = ("A sum's plane offsets are made on first use, but its facet normals are made by the build. "
            "The step that most often follows a sum reads every normal: a configuration-space obstacle "
            "A ⊕ (−B) is summed to be queried (containment, distance, penetration) or summed again, and "
            "the next sum's search reads both operands' normals. The build copies most normals from the "
            "operand facet they are parallel to (only the edge facets take a cross product and a gcd); "
            "made later from the output's own vertices, every normal would cost a cross product and a gcd. "
            "So the sum keeps its normals: a benchmark of the sum alone would gain what its users lose.")
    page.para(text)

    page.add("### Two threads on a 2-core host", "")
    pairs = []
    for family, label in (("SphereRot", "Sphere_k + rotated Sphere_k"), ("CubeSphere", "Cube + Sphere_k")):
        s = stimes.get(family, {})
        for k in sorted(s.get("CVMS", {})):
            if k >= 6 and k in s.get("CVMS_2threads", {}):
                pairs.append(f"{label.replace('_k', str(k))} {s['CVMS'][k] / s['CVMS_2threads'][k]:.2f}×")
    text = ("`Options::threads = 2` shares the contributing-vertex walk over A's facets (cut into pieces by "
            "size alone), then a worker traces the edge facets while the caller finds the corner facets; "
            "for the output, the worker computes facet normals while the caller numbers the vertices and "
            "builds the mesh's topology, and both then take the rest of the normals and the vertices' "
            "exact coordinates in chunks.")
    if pairs:
        text += " One thread's time over two's in this run: " + ", ".join(pairs) + "."
    text += (" Two threads stay near 1.5×, short of 2×, because part of every sum is serial: numbering the "
             "output vertices, the mesh's connectivity and freeing the result run on one thread. On a 2-core "
             "host the second thread also shares its core with everything else the machine runs, and the "
             "largest sums (k = 7, working sets far beyond the caches) are bound by memory bandwidth, which "
             "the two threads share. A scheme that gives all threads chunks of every phase is slower here: "
             "its workers allocate the output in their own malloc arenas, which glibc hands back to the "
             "kernel when the result is freed, and the next sum faults them in again.")
    page.para(text)

    page.add("### Slopes above 1", "")
    slope_text = ("The log-log slopes of the one-thread CVMS rows are a little above 1 on Sphere_k + rotated "
                  "Sphere_k. That comes from the memory hierarchy, not the algorithm: `limit mesh`, which is "
                  "linear work, has a slope as steep, and its time per facet grows as the working set leaves "
                  "the caches.")
    cv, lm = rot.get("CVMS"), rot.get("limit mesh")
    if cv and lm:
        s1, s2 = scaling.slopes(cv, sfacets["SphereRot"]), scaling.slopes(lm, sfacets["SphereRot"])
        if s1 and s2:
            slope_text += f" In this run: CVMS {s1[1]:.2f}, `limit mesh` {s2[1]:.2f} (least squares)."
    page.para(slope_text + " The paper-faithful search's quadratic terms show where both operands are large "
              "(its slope on the same family), and the peers hull a number of pairwise sums that grows "
              "as the product of the operands' vertex counts.")

    page.add("### Memory: bytes per output facet", "")
    measured = ""
    peak6 = speaks.get("SphereRot", {}).get("CVMS", {}).get(6)
    if peak6 and 6 in sfacets.get("SphereRot", {}):
        measured = (f" In this run the peak heap of Sphere6 + rotated Sphere6 is {peak6 / 2**20:.1f} MiB, "
                    f"{peak6 / sfacets['SphereRot'][6][1]:.0f} bytes per output facet.")
    page.para("A sum's result keeps, per output facet, its share of the half-edge mesh (four 4-byte arrays "
              "per halfedge, one per vertex and face), the double approximations of vertices and normals "
              "with their error bounds (the filters read them), and the packed exact values (16 bytes a "
              "coordinate, plus the limbs of normal coordinates longer than 64 bits): about 240 bytes per "
              "facet on Sphere6 + rotated Sphere6. The peak heap adds the search's and the builder's arrays "
              "while the result is built." + measured)

    page.add("### Page faults and glibc's malloc policy", "")
    page.para("On this virtual machine a page fault costs about 13 µs. Under glibc's default policy, memory "
              "that a call frees may be returned to the kernel (the heap's top is trimmed past a threshold "
              "that depends on the largest block freed so far), and the next call faults it in again; "
              "whether that happens depends on the sizes of the blocks freed before, not on the algorithm. "
              "So the quickhull comparison is run twice, under the default policy and with freed memory kept. "
              "A sum carves its result's arrays from two blocks sized in advance and mapped on huge pages, "
              "so it faults a few times per sum either way; the `cvms` tool keeps freed memory and puts its "
              "heap on transparent huge pages (`tools/cvms/heap_pages.cpp`), and a program that sums in a "
              "loop can do the same with `mallopt` or a caching allocator.")

    page.add("### End to end", "")
    page.para("A whole `cvms sum` run is mostly not the sum: it starts the process, reads and validates both "
              "operands exactly (parsing, convexity, the facet normals with their gcds), and writes the "
              "result's exact text atomically (a temporary file, `fsync`, rename). `cvms check` is the load "
              "without the sum, plus the process start. A tool that validates and keeps its input exact "
              "pays for that on every run; a program that loads once and sums many times does not.")
    page.para("The run's own overheads are small: read, sum and write account for the whole wall time "
              "(wall / work 1.0), and starting and ending the process, heap and huge-page set-up included, "
              "is the `cvms check cube.off` row. Each operand is read with one `read()` of the size `fstat` "
              "gives and parsed from memory; the text goes to the file in the writer's blocks, straight "
              "from its buffer. What remains is the library's work, at the cost it has in process (the "
              "\"Loading and writing\" rows), and the atomic replace's `fsync`, shown apart. Within 2x of "
              "the sum means read + write no longer than the sum itself. That cannot hold for Cube + Sphere6 "
              "in either form: loading Sphere6 alone (parse and validate, then its facet planes, which the "
              "sum reads) costs more than the sum, and the 2 MB of exact text cost about as much again. Nor "
              "for the dyadic Sphere6 + rotated Sphere6: two loads with their planes and 8.7 MB of exact "
              "text take longer than the sum's 30-40 ms. With shortest decimals the sum is twice as long "
              "and its output text less than half the size, so there the floor in process (two loads with "
              "planes, and writing 3.9 MB) sits just under the sum: 2x is within reach on an idle machine, "
              "and missed under load by the planes and the page faults (profile: about a tenth of such a run "
              "is the kernel zeroing fresh huge pages for the mesh builds' scratch arrays, which the "
              "in-process benchmarks, repeating the call, pay as well).")

    page.add("### Flat operands", "")
    page.para("A sum with a polygon or a segment is exact yet about as fast as qhull's floating-point hull of "
              "the pairwise sums, but per output facet it costs several times what two solids do: the tilted "
              "polygon's vertices are rational points of the unit circle (denominators near 2^20, not powers "
              "of two), so every vertex sum and facet plane is a full rational computation with gcds, where "
              "the sphere's dyadic coordinates take the packed dyadic path.")

    page.add("### The peers", "")
    page.para("qhull and CGAL are bench-only peers, never linked into the library (configure with "
              "`-DCVMS_BENCH_PEERS=ON`; each is compiled when found). They hull the pairwise vertex sums, "
              "which grow as the product of the operands' sizes, and report their own outputs: qhull merges "
              "facets in floating point, CGAL triangulates; the exact output facet count is in our rows.")


def build(bench_dir):
    page = Page()
    page.add("# Performance", "")
    page.para("Every table and every figure on this page is computed by `bench/performance_page.py` from the "
              "benchmark JSON committed in `docs/bench/` (Google Benchmark output of the `bench/` programs, "
              "release preset, peers on); `docs/fig12.svg` is drawn from `docs/bench/minkowski.json` by "
              "`bench/plot.py`. The page is not edited by hand: regenerate it with")
    page.block(["```sh", "/usr/bin/python3 bench/performance_page.py      # writes docs/performance.md",
                "/usr/bin/python3 bench/performance_page.py --check  # fails if the page and the JSON disagree",
                "```"])
    page.para("The ctest `bench_performance_page` runs the check. The runs themselves are reproduced by "
              "(`bench/README.md` describes every program and row):")
    page.block([REPRODUCE])
    page.para(NOISY_MACHINE)

    stimes, speaks, sfacets = minkowski_sections(page, path_in(bench_dir, "minkowski.json"))
    quickhull_section(page, path_in(bench_dir, "quickhull.json"), path_in(bench_dir, "quickhull_memory_kept.json"))
    sets_section(page, path_in(bench_dir, "sets.json"))
    halfspace_section(page, path_in(bench_dir, "halfspace.json"), path_in(bench_dir, "halfspace_cgal.json"))
    pieces_section(page, path_in(bench_dir, "pieces.json"))
    solid_sum_section(page, bench_dir)
    decimal_section(page, path_in(bench_dir, "decimal_sum.json"))
    load_section(page, path_in(bench_dir, "load.json"), path_in(bench_dir, "load_before_after.json"))
    end_to_end_section(page, path_in(bench_dir, "end_to_end.json"))
    python_section(page, path_in(bench_dir, "python_overhead.json"))
    explanations(page, stimes, speaks, sfacets)
    return page.text()


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--bench-dir", default=os.path.join(ROOT, "docs", "bench"),
                        help="the benchmark JSON (default: docs/bench)")
    parser.add_argument("-o", "--output", default=os.path.join(ROOT, "docs", "performance.md"),
                        help="the page (default: docs/performance.md)")
    parser.add_argument("--check", action="store_true",
                        help="write nothing; exit 1 with a diff when the page differs from what the JSON gives")
    args = parser.parse_args()
    text = build(args.bench_dir)
    if args.check:
        with open(args.output, encoding="utf-8") as f:
            committed = f.read()
        if committed != text:
            sys.stdout.writelines(difflib.unified_diff(committed.splitlines(True), text.splitlines(True),
                                                       args.output, "regenerated"))
            print(f"\n{args.output} is out of date: run bench/performance_page.py", file=sys.stderr)
            return 1
        return 0
    with open(args.output, "w", encoding="utf-8") as f:
        f.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
