"""The summed pairs of cvms_solid_sum_bench for the scripts that run peers
and whole commands outside the benchmark process (bench/manifold_peer.py,
bench/solid_sum_end_to_end.py): the pairs are the benchmark's own (its
BM_SolidSum rows) and the operand files are the ones it writes
(`--write_operands=DIR`), so every peer sums the identical solids."""
import re
import subprocess


def pairs(bench):
    """[(pair name, a, b)] in the benchmark's order, one per BM_SolidSum pair."""
    listed = subprocess.run([bench, "--benchmark_list_tests=true", "--benchmark_filter=^BM_SolidSum/"],
                            check=True, capture_output=True, text=True).stdout.split()
    out = []
    for row in listed:
        m = re.match(r"BM_SolidSum/([^/]+)/1$", row)
        if m:
            a, b = m.group(1).split("+")
            out.append((m.group(1), a, b))
    return out


def write_operands(bench, directory):
    """Writes every operand as <directory>/<name>.off (triangles, exact)."""
    subprocess.run([bench, f"--write_operands={directory}"], check=True)


def add_arguments(parser):
    """The options both scripts share."""
    parser.add_argument("--bench", default="build/release/bench/cvms_solid_sum_bench",
                        help="the benchmark binary: its pairs and the operand files it writes")
    parser.add_argument("--cvms", default="build/release/tools/cvms", help="the command-line tool")
    parser.add_argument("--filter", default="", help="only the pairs whose name matches this regular expression")
    parser.add_argument("--rounds", type=int, default=3, help="runs of each row; the minimum is reported")
    parser.add_argument("--json", help="write the results here")
