#!/usr/bin/env python3
"""Draws the paper's Fig. 12 from cvms_minkowski_bench JSON output, with
matplotlib, as SVG (or any format matplotlib writes, by the output's suffix):

  left:  Table 1 rows (Cube + Tetra ... Cube + Sphere6): runtime against the
         sum of the operands' facet counts (the paper's x axis), one line per
         algorithm, peers included when present;
  right: Sphere_k + rotated Sphere_k, k = 3 ...: runtime against the number
         of OUTPUT facets, with the output-build limits and the peers.

Both axes logarithmic.
"""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)

import bench_json  # noqa: E402

# One style per algorithm, the same in both panels: (legend, colour, line style, marker).
STYLES = {
    "CHMS": ("CHMS", "#7f7f7f", "-", "o"),
    "ESSDMS": ("ESSDMS", "#9467bd", "-", "s"),
    "CVMS_paper": ("CVMS (paper-faithful)", "#ff7f0e", "-", "^"),
    "CVMS": ("CVMS (output-sensitive)", "#d62728", "-", "o"),
    "CVMS_2threads": ("CVMS (output-sensitive, 2 threads)", "#d62728", "--", "o"),
    "Limit_Mesh": ("limit: output mesh only", "#8c564b", ":", "v"),
    "Limit_Build": ("limit: output polyhedron build", "#e377c2", ":", "v"),
    "Qhull": ("qhull (double, pairwise sums)", "#1f77b4", "-.", "D"),
    "CGAL": ("CGAL convex_hull_3 Epeck (pairwise sums)", "#2ca02c", "-.", "D"),
}
TABLE = {"BM_CHMS": "CHMS", "BM_ESSDMS": "ESSDMS", "BM_CVMS_paper": "CVMS_paper", "BM_CVMS": "CVMS",
         "BM_CVMS_2threads": "CVMS_2threads", "BM_Qhull_PairwiseSums": "Qhull", "BM_CGAL_PairwiseSums": "CGAL"}
SCALING = {"BM_CVMS_SphereRot": "CVMS", "BM_CVMS_2threads_SphereRot": "CVMS_2threads",
           "BM_CVMS_paper_SphereRot": "CVMS_paper", "BM_Limit_Mesh_SphereRot": "Limit_Mesh",
           "BM_Limit_Build_SphereRot": "Limit_Build", "BM_Qhull_SphereRot": "Qhull", "BM_CGAL_SphereRot": "CGAL"}


def load(path, time_field, statistic):
    """((table series, table x), (scaling series, scaling x)): series[algorithm][arg] = ms, x[arg]."""
    table, scaling = {}, {}
    table_x, scaling_x = {}, {}
    for prefix, arg, ms, b in bench_json.runs(path, time_field, statistic):
        if prefix in TABLE:
            table.setdefault(TABLE[prefix], {})[arg] = ms
            if "input_facets" in b:
                table_x[arg] = b["input_facets"]
        elif prefix in SCALING:
            scaling.setdefault(SCALING[prefix], {})[arg] = ms
            if "output_facets" in b:
                scaling_x[arg] = b["output_facets"]
    return (table, table_x), (scaling, scaling_x)


def panel(ax, series, xs, title, xlabel, legend_loc):
    for algorithm, (name, colour, style, marker) in STYLES.items():
        points = sorted((xs[a], t) for a, t in series.get(algorithm, {}).items() if a in xs and t > 0)
        if points:
            ax.plot([p[0] for p in points], [p[1] for p in points], style, color=colour, marker=marker,
                    markersize=4, linewidth=1.6, label=name)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_title(title, fontsize=11)
    ax.set_xlabel(xlabel)
    ax.set_ylabel("runtime (ms)")
    ax.grid(True, which="major", color="#bbbbbb", linewidth=0.8)
    ax.grid(True, which="minor", color="#eeeeee", linewidth=0.5)
    ax.legend(loc=legend_loc, fontsize=8, framealpha=0.9)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("results", help="cvms_minkowski_bench JSON output")
    parser.add_argument("-o", "--output", default="docs/fig12.svg", help="the figure's file (default: %(default)s)")
    bench_json.add_time_options(parser)
    args = parser.parse_args()
    time_field, statistic = bench_json.time_options(args)
    (table, table_x), (scaling, scaling_x) = load(args.results, time_field, statistic)

    # Reproducible SVG: no date in its metadata, fixed element ids.
    matplotlib.rcParams["svg.hashsalt"] = "cvms-fig12"
    matplotlib.rcParams["font.family"] = "DejaVu Sans"
    matplotlib.rcParams["svg.fonttype"] = "none"  # text as text: a smaller file
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 5.6))
    panel(left, table, table_x, "Cube + {Tetra ... Sphere6} (the paper's Table 1 / Fig. 12)",
          "sum of the operands' facet counts", "upper left")
    panel(right, scaling, scaling_x, "Sphere_k + rotated Sphere_k, k = 3 ...", "output facets", "lower right")
    fig.text(0.5, 0.01,
             f"Google Benchmark {'CPU' if time_field == 'cpu_time' else 'real'} time "
             f"({'minimum' if statistic == 'min' else 'median'} of the repetitions), release build, "
             "all algorithms side by side in one run; peers hull the pairwise vertex sums (hull time only).",
             ha="center", fontsize=9, color="#555555")
    fig.tight_layout(rect=(0, 0.04, 1, 1))
    fig.savefig(args.output, metadata={"Date": None})


if __name__ == "__main__":
    main()
