#!/usr/bin/env python3
"""What a user of the command-line tool waits for: wall time and
peak memory of whole `cvms` runs, from file to file, next to the time of the
sum alone inside the same run (`cvms sum --stats` prints it), so that the
ratio end-to-end / in-process comes from one process and one machine state.

The sum's run also reports (`--stats`) how long it read and validated
its operands and wrote its output, so that each sum row has two ratios:
wall over the sum alone, and wall over read + sum + write (what is left
is the process's start and exit). The read time holds the operands' facet
planes (made before the sum's clock starts) and the write time its wait for
the disk (fsync and rename), both also shown apart. One more row writes the
largest sum to /dev/null, written directly (no temporary file, no fsync):
its write time against the file's is what replacing a file atomically
costs; `cvms check cube.off` is the process's start and exit with next to
no work.

On a shared machine wall times mean little: each row also has the child's
CPU time (user + system, from wait4), the minimum over the rounds, and its
ratio to the sum; the sum's own time is a wall time inside the run.

Rows: `cvms sum cube.off sphere6.off -o out.off`, `cvms sum sphere6.off
sphere6_rotated.off -o out.off` and `cvms check sphere6.off`, each again
with the spheres' doubles written as their shortest round-trip decimals
(`*_shortest.off`, as Python, numpy and most exporters write them; read
exactly, those are other numbers than the doubles). Inputs are made by
`cvms gen` in a scratch directory first. Each row is run --rounds times;
the minimum wall time is reported (the machine is shared), with the peak
resident memory of that process (from wait4, per child).

usage: bench/end_to_end.py [--cvms build/release/tools/cvms] [--rounds 5] [--json out.json]
"""
import argparse
from fractions import Fraction
import json
import os
import re
import subprocess
import tempfile
import time


def run_measured(argv):
    """(wall seconds, CPU seconds, the child's own peak RSS in bytes, stdout)
    of one run of argv; wait4 reaps the child itself, so its rusage is its own."""
    start = time.perf_counter()
    child = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    out = child.stdout.read().decode()
    err = child.stderr.read().decode()
    _, status, usage = os.wait4(child.pid, 0)
    wall = time.perf_counter() - start
    child.returncode = os.waitstatus_to_exitcode(status)
    if child.returncode != 0:
        raise SystemExit(f"{' '.join(argv)} failed: {err.strip()}")
    return wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss * 1024, out


def write_shortest(exact_path, out_path):
    """The OFF file exact_path (header, counts, one "x y z" line per point,
    then faces), its coordinates, all doubles, written as their shortest
    round-trip decimals (Python's repr of a float)."""
    with open(exact_path) as f:
        lines = f.read().split("\n")
    points = int(lines[1].split()[0])
    for i in range(2, 2 + points):
        lines[i] = " ".join(repr(float(Fraction(token))) for token in lines[i].split())
    with open(out_path, "w") as f:
        f.write("\n".join(lines))


def in_process_ms(stats, what="time", start="^"):
    """A time `cvms sum --stats` printed: `time` (the sum), `read time`
    (reading and validating both operands, with their planes), `write time`
    (the output, with its sync), or with start="" a part of one of them
    (`facet planes time`, `disk sync time`)."""
    m = re.search(rf"{start}{what}: ([0-9.]+) ms", stats, re.MULTILINE)
    return float(m.group(1)) if m else None


def measure(argv, rounds):
    """The run of least wall time, and the least CPU time of all runs."""
    best = None
    least_cpu = None
    for _ in range(rounds):
        wall, cpu, rss, out = run_measured(argv)
        least_cpu = cpu if least_cpu is None else min(least_cpu, cpu)
        if best is None or wall < best["wall_ms"] / 1e3:
            best = {"wall_ms": wall * 1e3, "peak_rss_bytes": rss, "sum_ms": in_process_ms(out),
                    "read_ms": in_process_ms(out, "read time"), "write_ms": in_process_ms(out, "write time"),
                    "planes_ms": in_process_ms(out, "facet planes time", ""),
                    "sync_ms": in_process_ms(out, "disk sync time", "")}
    best["cpu_ms"] = least_cpu * 1e3
    return best


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--cvms", default="build/release/tools/cvms")
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--json")
    args = parser.parse_args()
    cvms = os.path.abspath(args.cvms)
    with tempfile.TemporaryDirectory() as scratch:
        def path(name):
            return os.path.join(scratch, name)

        run_measured([cvms, "gen", "cube", "-o", path("cube.off")])
        run_measured([cvms, "gen", "sphere", "--subdivisions", "6", "-o", path("sphere6.off")])
        run_measured([cvms, "gen", "rotated-sphere", "--subdivisions", "6", "-o", path("sphere6_rotated.off")])
        for name in ("sphere6", "sphere6_rotated"):
            write_shortest(path(name + ".off"), path(name + "_shortest.off"))
        rows = {}
        for form in ("", "_shortest"):
            a, b = f"sphere6{form}.off", f"sphere6_rotated{form}.off"
            rows[f"sum cube.off {a} -o out.off"] = [cvms, "sum", path("cube.off"), path(a), "-o", path("out.off"),
                                                    "--stats"]
            rows[f"sum {a} {b} -o out.off"] = [cvms, "sum", path(a), path(b), "-o", path("out.off"), "--stats"]
            rows[f"check {a}"] = [cvms, "check", path(a)]
        # The same sum into a device: no temporary file, no fsync, no rename.
        rows["sum sphere6.off sphere6_rotated.off -o /dev/null"] = [
            cvms, "sum", path("sphere6.off"), path("sphere6_rotated.off"), "-o", "/dev/null", "--stats"]
        rows["check cube.off"] = [cvms, "check", path("cube.off")]
        results = {name: measure(argv, args.rounds) for name, argv in rows.items()}

    def ms(value, parens=None):
        if value is None:
            return "—"
        return f"{value:.1f}" + (f" ({parens:.1f})" if parens is not None else "")

    def ratio(a, b):
        return f"{a / b:.1f}×" if a is not None and b else "—"

    print("| command | wall (ms) | CPU (ms) | sum in process (ms) | read (planes) (ms) | write (sync) (ms) "
          "| wall / sum | CPU / sum | wall / (read + sum + write) | peak RSS (MiB) |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for name, r in results.items():
        work = r["sum_ms"] + r["read_ms"] + r["write_ms"] if r["sum_ms"] and r["read_ms"] is not None else None
        print(f"| `cvms {name}` | {ms(r['wall_ms'])} | {ms(r['cpu_ms'])} | {ms(r['sum_ms'])} "
              f"| {ms(r['read_ms'], r['planes_ms'])} | {ms(r['write_ms'], r['sync_ms'])} "
              f"| {ratio(r['wall_ms'], r['sum_ms'])} | {ratio(r['cpu_ms'], r['sum_ms'])} "
              f"| {ratio(r['wall_ms'], work)} | {r['peak_rss_bytes'] / 2**20:.1f} |")
    if args.json:
        with open(args.json, "w") as f:
            json.dump(results, f, indent=2)


if __name__ == "__main__":
    main()
