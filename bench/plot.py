#!/usr/bin/env python3
"""Writes a self-contained SVG (no plotting library) from cvms_minkowski_bench
JSON output, after the paper's Fig. 12:

  left:  Table 1 rows (Cube + Tetra ... Cube + Sphere6): runtime against the
         sum of the operands' facet counts (the paper's x axis), one polyline
         per algorithm, peers included when present;
  right: Sphere_k + rotated Sphere_k, k = 3..: runtime against the number of
         OUTPUT facets, with the output-mesh limits and the peers.

Both axes logarithmic. usage: bench/plot.py [--cpu] [--min] results.json [-o docs/fig12.svg]
"""
import bench_json
import math
import sys

# Which Google Benchmark time the tables use: real (wall) time by default;
# --cpu selects the CPU time, steadier when other jobs share the machine
# (every benchmark here is single-threaded).
TIME_FIELD = "real_time"
# Which statistic of the repetitions: the median, or with --min the minimum.
STATISTIC = "median"

# (benchmark name prefix, legend, colour, dash): one style per algorithm, same in both panels.
STYLES = {
    "CHMS": ("CHMS", "#7f7f7f", ""),
    "ESSDMS": ("ESSDMS", "#9467bd", ""),
    "CVMS_paper": ("CVMS (paper-faithful)", "#ff7f0e", ""),
    "CVMS": ("CVMS (output-sensitive)", "#d62728", ""),
    "CVMS_2threads": ("CVMS (output-sensitive, 2 threads)", "#d62728", "8,3"),
    "Limit_Mesh": ("limit: output mesh only", "#8c564b", "5,4"),
    "Limit_Build": ("limit: output polyhedron build", "#e377c2", "5,4"),
    "Qhull": ("qhull (double, pairwise sums)", "#1f77b4", "2,3"),
    "CGAL": ("CGAL convex_hull_3 Epeck (pairwise sums)", "#2ca02c", "2,3"),
}
TABLE = {"BM_CHMS": "CHMS", "BM_ESSDMS": "ESSDMS", "BM_CVMS_paper": "CVMS_paper", "BM_CVMS": "CVMS",
         "BM_CVMS_2threads": "CVMS_2threads", "BM_Qhull_PairwiseSums": "Qhull", "BM_CGAL_PairwiseSums": "CGAL"}
SCALING = {"BM_CVMS_SphereRot": "CVMS", "BM_CVMS_2threads_SphereRot": "CVMS_2threads", "BM_CVMS_paper_SphereRot": "CVMS_paper",
           "BM_Limit_Mesh_SphereRot": "Limit_Mesh", "BM_Limit_Build_SphereRot": "Limit_Build",
           "BM_Qhull_SphereRot": "Qhull", "BM_CGAL_SphereRot": "CGAL"}


def load(path):
    table, scaling = {}, {}  # algorithm -> {arg: ms}
    table_x, scaling_x = {}, {}  # arg -> x value
    for prefix, arg, ms, b in bench_json.runs(path, TIME_FIELD, STATISTIC):
        if prefix in TABLE:
            table.setdefault(TABLE[prefix], {})[arg] = ms
            if "input_facets" in b:
                table_x[arg] = b["input_facets"]
        elif prefix in SCALING:
            scaling.setdefault(SCALING[prefix], {})[arg] = ms
            if "output_facets" in b:
                scaling_x[arg] = b["output_facets"]
    return (table, table_x), (scaling, scaling_x)


def fmt(v):
    if v >= 1e6:
        return "%gM" % (v / 1e6)
    if v >= 1e3:
        return "%gk" % (v / 1e3)
    return "%g" % v


def esc(s):
    return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


def panel(series, xs, title, xlabel, ox, oy, w, h):
    """SVG elements of one log-log panel whose plot area is (ox, oy, w, h)."""
    pts = [(xs[a], t) for s in series.values() for a, t in s.items() if a in xs and t > 0]
    if not pts:
        return []
    x0 = 10 ** math.floor(math.log10(min(p[0] for p in pts)))
    x1 = 10 ** math.ceil(math.log10(max(p[0] for p in pts)))
    y0 = 10 ** math.floor(math.log10(min(p[1] for p in pts)))
    y1 = 10 ** math.ceil(math.log10(max(p[1] for p in pts)))

    def px(x):
        return ox + w * (math.log10(x) - math.log10(x0)) / (math.log10(x1) - math.log10(x0))

    def py(y):
        return oy + h - h * (math.log10(y) - math.log10(y0)) / (math.log10(y1) - math.log10(y0))

    out = [f'<rect x="{ox}" y="{oy}" width="{w}" height="{h}" fill="white" stroke="#333"/>']
    # Grid: decades solid, 2..9 light; labels at decades.
    for lo, hi, to_px, vertical in ((x0, x1, px, True), (y0, y1, py, False)):
        d = lo
        while d <= hi * 1.0001:
            for m in range(1, 10):
                v = d * m
                if v > hi * 1.0001:
                    break
                p = to_px(v)
                colour, width = ("#bbb", 1) if m == 1 else ("#eee", 1)
                if vertical:
                    out.append(f'<line x1="{p:.1f}" y1="{oy}" x2="{p:.1f}" y2="{oy + h}" stroke="{colour}" stroke-width="{width}"/>')
                else:
                    out.append(f'<line x1="{ox}" y1="{p:.1f}" x2="{ox + w}" y2="{p:.1f}" stroke="{colour}" stroke-width="{width}"/>')
            p = to_px(d)
            if vertical:
                out.append(f'<text x="{p:.1f}" y="{oy + h + 18}" text-anchor="middle">{fmt(d)}</text>')
            else:
                out.append(f'<text x="{ox - 6}" y="{p + 4:.1f}" text-anchor="end">{fmt(d)}</text>')
            d *= 10
    out.append(f'<text x="{ox + w / 2}" y="{oy - 12}" text-anchor="middle" font-weight="bold">{esc(title)}</text>')
    out.append(f'<text x="{ox + w / 2}" y="{oy + h + 40}" text-anchor="middle">{esc(xlabel)}</text>')
    out.append(f'<text transform="translate({ox - 52},{oy + h / 2}) rotate(-90)" text-anchor="middle">runtime (ms, log)</text>')
    # One polyline per algorithm, in legend order.
    legend = []
    for algorithm in STYLES:
        if algorithm not in series:
            continue
        s = sorted((xs[a], t) for a, t in series[algorithm].items() if a in xs and t > 0)
        if not s:
            continue
        name, colour, dash = STYLES[algorithm]
        coords = " ".join(f"{px(x):.1f},{py(t):.1f}" for x, t in s)
        dash_attr = f' stroke-dasharray="{dash}"' if dash else ""
        out.append(f'<polyline points="{coords}" fill="none" stroke="{colour}" stroke-width="2"{dash_attr}/>')
        for x, t in s:
            out.append(f'<circle cx="{px(x):.1f}" cy="{py(t):.1f}" r="3" fill="{colour}"/>')
        legend.append((name, colour, dash))
    # Legend in the lower right corner: every curve rises to the right, so
    # that corner stays free.
    lx, ly = ox + w - 310, oy + h - 18 - 18 * len(legend)
    out.append(f'<rect x="{lx}" y="{ly}" width="300" height="{8 + 18 * len(legend)}" fill="white" fill-opacity="0.9" stroke="#999"/>')
    for i, (name, colour, dash) in enumerate(legend):
        y = ly + 16 + 18 * i
        dash_attr = f' stroke-dasharray="{dash}"' if dash else ""
        out.append(f'<line x1="{lx + 8}" y1="{y - 4}" x2="{lx + 38}" y2="{y - 4}" stroke="{colour}" stroke-width="2"{dash_attr}/>')
        out.append(f'<circle cx="{lx + 23}" cy="{y - 4}" r="3" fill="{colour}"/>')
        out.append(f'<text x="{lx + 46}" y="{y}">{esc(name)}</text>')
    return out


def main(args):
    global TIME_FIELD, STATISTIC
    TIME_FIELD, STATISTIC, args = bench_json.options(args)
    output = "docs/fig12.svg"
    if "-o" in args:
        i = args.index("-o")
        output = args[i + 1]
        args = args[:i] + args[i + 2:]
    if len(args) != 1:
        sys.exit(__doc__)
    (table, table_x), (scaling, scaling_x) = load(args[0])
    width, height = 1200, 560
    body = panel(table, table_x, "Cube + {Tetra ... Sphere6} (the paper's Table 1 / Fig. 12)",
                 "sum of the operands' facet counts (log)", 80, 50, 480, 420)
    body += panel(scaling, scaling_x, "Sphere_k + rotated Sphere_k, k = 3 ...",
                  "output facets (log)", 690, 50, 480, 420)
    svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" viewBox="0 0 {width} {height}" '
           'font-family="DejaVu Sans, Helvetica, Arial, sans-serif" font-size="12">',
           f'<rect width="{width}" height="{height}" fill="white"/>']
    svg += body
    svg.append(f'<text x="{width / 2}" y="{height - 12}" text-anchor="middle" fill="#555">'
               f'Google Benchmark {"CPU" if TIME_FIELD == "cpu_time" else "real"} time '
               f'({"minimum" if STATISTIC == "min" else "median"} of the repetitions), release build, '
               'all algorithms side by side in one run; '
               'peers hull the pairwise vertex sums (hull time only).</text>')
    svg.append("</svg>")
    with open(output, "w") as f:
        f.write("\n".join(svg) + "\n")


if __name__ == "__main__":
    main(sys.argv[1:])
