#!/usr/bin/env python3
"""Prints the tables of sums of solids that need not be convex, as one closed
solid: cvms_solid_sum_bench's rows (the sum, the pieces stage, writing the
result, the other road, the CGAL Nef peer) next to Manifold's rows
(bench/manifold_peer.py), the comb family's least-squares log-log slope of
time against output facets, and whole `cvms sum` runs
(bench/solid_sum_end_to_end.py). bench/performance_page.py puts them on the
performance page; run alone, this prints them.

One-thread rows are read in CPU time (steadier on a shared machine), the
two-thread rows in wall time (their CPU time counts the calling thread only).

usage: bench/solid_sum_table.py [--bench-dir docs/bench]
"""
import argparse
import json
import math
import os
import re

import bench_json

SOLID_LABELS = {
    "l_block": "L-block",
    "box_with_hole": "frame",
    "star_prism": "star prism",
    "coarse_torus": "coarse torus",
    "cube": "cube",
    "spot": "spot",
    "icosphere": "icosphere",
}


def times(r):
    """A ratio: two decimals below 1, one below 10, none above."""
    return f"{r:.2f}×" if r < 1 else f"{r:.1f}×" if r < 10 else f"{r:,.0f}×"


def pair_label(pair):
    def one(name):
        m = re.fullmatch(r"comb(\d+)", name)
        return f"comb of {m.group(1)} teeth" if m else SOLID_LABELS.get(name, name)

    return " ⊕ ".join(one(n) for n in pair.split("+"))


fmt_ms = bench_json.fmt_ms


SMALL_SOLIDS = ["l_block", "box_with_hole", "star_prism", "coarse_torus"]


def load(*paths):
    """{kind: {pair: {threads: (ms, entry)}}} from rows "<kind>/<pair>/<threads>" (settings such as
    "/iterations:1" dropped) of the files that exist, later files adding rows; {} without any."""
    out = {}
    for path in paths:
        if not os.path.exists(path):
            continue
        timed = dict(bench_json.rows(path, "real_time", "min"))
        timed.update(bench_json.rows(path, "cpu_time", "min"))
        for key, value in timed.items():
            parts = [p for p in key.split("/") if ":" not in p]
            if len(parts) == 3 and parts[2].isdigit():
                out.setdefault(parts[0], {}).setdefault(parts[1], {})[int(parts[2])] = value
    return out


def pair_order(pair):
    """The benchmark's order: the small solids + the cube, + each other, spot, the combs by size."""
    a, b = (pair.split("+") + [""])[:2]
    if a in SMALL_SOLIDS and b == "cube":
        return (0, SMALL_SOLIDS.index(a), 0)
    if a in SMALL_SOLIDS and b in SMALL_SOLIDS:
        return (1, SMALL_SOLIDS.index(a), SMALL_SOLIDS.index(b))
    m = re.fullmatch(r"comb(\d+)", a)
    if m:
        return (3, int(m.group(1)), 0)
    return (2, 0, 0) if a == "spot" else (4, 0, 0)


def pairs_in(*tables):
    """The pairs of all tables, in the benchmark's order."""
    seen = set()
    for table in tables:
        for kind in table.values():
            seen.update(kind)
    return sorted(seen, key=lambda pair: (pair_order(pair), pair))


def at(rows, kind, pair, threads=1):
    """(ms, entry) or None."""
    return rows.get(kind, {}).get(pair, {}).get(threads)


def in_process_table(rows):
    """Our rows: the sum, the pieces stage and writing the result; the other road."""
    lines = ["| pair | output facets | vertices | shells | genus | sum (ms) | pieces stage (ms) | writing (ms) "
             "| (sum + writing) / (pieces + writing) | union of both decompositions (ms) |",
             "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for pair in pairs_in(rows):
        if pair.startswith("comb"):
            continue
        ours, pieces = at(rows, "BM_SolidSum", pair), at(rows, "BM_PiecesStage", pair)
        write, other = at(rows, "BM_WriteResult", pair), at(rows, "BM_UnionOfPieces", pair)
        if not (ours or pieces):
            continue
        cells = [pair_label(pair)]
        if ours:
            b = ours[1]
            cells += [f"{int(b['out_facets']):,}", f"{int(b['out_vertices']):,}", f"{int(b['shells'])}",
                      f"{int(b['genus'])}"]
        else:
            cells += ["—"] * 4
        cells += [fmt_ms(ours[0] if ours else None), fmt_ms(pieces[0] if pieces else None),
                  fmt_ms(write[0] if write else None)]
        cells.append(f"{(ours[0] + write[0]) / (pieces[0] + write[0]):.2f}" if ours and pieces and write else "—")
        cells.append(fmt_ms(other[0] if other else None))
        lines.append("| " + " | ".join(cells) + " |")
    return lines


def peers_table(rows, manifold):
    """Ours next to CGAL Nef (same binary, same run) and Manifold, one row per pair."""
    lines = ["| pair | cvms (ms) | CGAL Nef (ms) | Nef / cvms | Manifold (ms) | Manifold / cvms "
             "| Manifold's output, checked exactly |",
             "|---|---:|---:|---:|---:|---:|---|"]
    for pair in pairs_in(rows, manifold):
        for threads in (1, 2):
            ours, nef = at(rows, "BM_SolidSum", pair, threads), at(rows, "BM_CgalNef", pair, threads)
            peer = at(manifold, "Manifold", pair, 1) if threads == 1 else None
            if not (ours or nef or peer):
                continue
            label = pair_label(pair) + (f", {threads} threads" if threads > 1 else "")
            cells = [label, fmt_ms(ours[0] if ours else None), fmt_ms(nef[0] if nef else None),
                     times(nef[0] / ours[0]) if ours and nef else "—", fmt_ms(peer[0] if peer else None),
                     times(peer[0] / ours[0]) if ours and peer else "—"]
            if peer:
                b = peer[1]
                verdict = "valid" if b.get("exact_valid") else f"invalid: {b.get('exact_check', '?')}"
                text = f"{int(b['peer_vertices']):,} vertices (cvms: " + (
                    f"{int(ours[1]['out_vertices']):,}" if ours else "—") + f"), {verdict}"
                if ours and ours[1].get("volume"):
                    text += f", volume off by {b['peer_volume'] / ours[1]['volume'] - 1:+.1e}"
                cells.append(text)
            else:
                cells.append("—")
            lines.append("| " + " | ".join(cell.replace("|", "\\|") for cell in cells) + " |")
    return lines


def manifold_failures(manifold):
    """(invalid results, results) of Manifold's rows."""
    checked = [b for pairs in manifold.values() for t in pairs.values() for _, b in t.values()]
    return sum(1 for b in checked if not b.get("exact_valid")), len(checked)


def summary(rows, manifold):
    """What the side-by-side table says, as a sentence or two computed from it ("" without cvms's rows)."""
    text = []
    spot = "spot+icosphere"
    ours1, ours2 = at(rows, "BM_SolidSum", spot, 1), at(rows, "BM_SolidSum", spot, 2)
    nef, peer = at(rows, "BM_CgalNef", spot), at(manifold, "Manifold", spot)
    if ours1:
        best = min(r[0] for r in (ours1, ours2) if r)
        part = (f"On spot ⊕ icosphere cvms takes {fmt_ms(ours1[0])} ms on one thread"
                + (f" and {fmt_ms(ours2[0])} ms on two" if ours2 else ""))
        ratios = []
        if nef:
            ratios.append(f"CGAL Nef {fmt_ms(nef[0])} ms ({times(nef[0] / best)} the faster cvms row)")
        if peer:
            ratios.append(f"Manifold {fmt_ms(peer[0])} ms ({times(peer[0] / best)})")
        text.append(part + (": " + ", ".join(ratios) if ratios else "") + ".")
    nef_ratios = [(n[0] / o[0], pair) for pair in pairs_in(rows)
                  if (o := at(rows, "BM_SolidSum", pair)) and (n := at(rows, "BM_CgalNef", pair))]
    if nef_ratios:
        low, high = min(nef_ratios), max(nef_ratios)
        text.append(f"Nef / cvms ranges from {times(low[0])} ({pair_label(low[1])}) to {times(high[0])} "
                    f"({pair_label(high[1])}).")
    extra = [(m[1]["peer_vertices"] / o[1]["out_vertices"]) for pair in pairs_in(rows, manifold)
             if (o := at(rows, "BM_SolidSum", pair)) and (m := at(manifold, "Manifold", pair))]
    if extra:
        text.append(f"Manifold's results have {min(extra):.1f}× to {max(extra):.1f}× the vertices of the exact "
                    "boundary: its union keeps vertices inside flat regions and straight edges, where cvms keeps "
                    "only the true corners.")
    return " ".join(text)


def comb_teeth(*tables):
    """The tooth counts k of the comb pairs "comb<k>+cube" in any table, sorted."""
    return sorted({int(m.group(1)) for pair in pairs_in(*tables) if (m := re.fullmatch(r"comb(\d+)\+cube", pair))})


def slope(points):
    """Least-squares slope of log y against log x over [(x, y)], or None."""
    points = [(math.log(x), math.log(y)) for x, y in points if x and y]
    if len(points) < 2:
        return None
    mx, my = sum(x for x, _ in points) / len(points), sum(y for _, y in points) / len(points)
    return sum((x - mx) * (y - my) for x, y in points) / sum((x - mx) ** 2 for x, _ in points)


def comb_slopes(rows, manifold):
    """{label: slope}: cvms's time against its output facets, and each one's time against the teeth k."""
    out = {}
    ks = comb_teeth(rows, manifold)
    ours = [at(rows, "BM_SolidSum", f"comb{k}+cube") for k in ks]
    s = slope([(r[1]["out_facets"], r[0]) for r in ours if r])
    if s is not None:
        out["cvms against output facets"] = s
    for label, table, kind in (("cvms", rows, "BM_SolidSum"), ("CGAL Nef", rows, "BM_CgalNef"),
                               ("Manifold", manifold, "Manifold")):
        s = slope([(k, r[0]) for k in ks if (r := at(table, kind, f"comb{k}+cube"))])
        if s is not None:
            out[f"{label} against k"] = s
    return out


def scaling_table(rows, manifold):
    lines = ["| comb teeth k | output facets | cvms (ms) | µs per output facet | CGAL Nef (ms) | Manifold (ms) |",
             "|---:|---:|---:|---:|---:|---:|"]
    for k in comb_teeth(rows, manifold):
        pair = f"comb{k}+cube"
        ours, nef, peer = at(rows, "BM_SolidSum", pair), at(rows, "BM_CgalNef", pair), at(manifold, "Manifold", pair)
        facets = ours[1]["out_facets"] if ours else None
        lines.append(f"| {k} | {f'{int(facets):,}' if facets else '—'} | {fmt_ms(ours[0] if ours else None)} "
                     f"| {f'{1e3 * ours[0] / facets:,.0f}' if facets else '—'} "
                     f"| {fmt_ms(nef[0] if nef else None)} | {fmt_ms(peer[0] if peer else None)} |")
    return lines


def end_to_end_table(results):
    lines = ["| command | wall (ms) | sum in process (ms) | wall / sum | peak RSS (MiB) |", "|---|---:|---:|---:|---:|"]
    for name, r in results.items():
        pair, run = name.rsplit("/", 1)
        a, b = pair.split("+")
        options = {"1": "-o out.off", "pieces": "--pieces -o pieces.obj"}.get(run, f"-o out.off --threads {run}")
        command = f"`cvms sum {a}.off {b}.off {options}`"
        if "wall_ms" not in r:
            lines.append(f"| {command} | failed | — | — | — |")
            continue
        s = r.get("sum_ms")
        lines.append(f"| {command} | {fmt_ms(r['wall_ms'])} | {fmt_ms(s)} | "
                     + (f"{r['wall_ms'] / s:.1f}×" if s else "—") + f" | {r['peak_rss_bytes'] / 2**20:.1f} |")
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--bench-dir", default="docs/bench")
    args = parser.parse_args()
    rows = load(os.path.join(args.bench_dir, "solid_sum.json"), os.path.join(args.bench_dir, "solid_sum_nef_spot.json"))
    manifold = load(os.path.join(args.bench_dir, "solid_sum_manifold.json"))
    for lines in (in_process_table(rows), peers_table(rows, manifold), scaling_table(rows, manifold)):
        print("\n".join(lines) + "\n")
    for label, s in comb_slopes(rows, manifold).items():
        print(f"least-squares log-log slope, {label}: {s:.2f}")
    path = os.path.join(args.bench_dir, "solid_sum_end_to_end.json")
    if os.path.exists(path):
        with open(path) as f:
            print("\n".join(end_to_end_table(json.load(f))))


if __name__ == "__main__":
    main()
