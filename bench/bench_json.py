"""Reading Google Benchmark JSON from the cvms benchmarks, shared by every
script in bench/: one place decides which entries count and which time is
read, and how a time is printed."""
import json

_UNIT_MS = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}


def add_time_options(parser):
    """Adds --cpu and --min to an argparse parser."""
    parser.add_argument("--cpu", action="store_true",
                        help="read CPU time instead of real (wall) time: steadier when other jobs share the "
                             "machine (multithreaded rows are read in real time either way)")
    parser.add_argument("--min", action="store_true",
                        help="read each row's minimum over its repetitions instead of the median (with random "
                             "interleaving, each row's time in the run's fastest spell)")


def time_options(args):
    """(time_field, statistic) from arguments parsed with add_time_options."""
    return ("cpu_time" if args.cpu else "real_time"), ("min" if args.min else "median")


def fmt_ms(ms):
    """A time in ms with three significant digits or so (thousands separated); "—" for None."""
    if ms is None:
        return "—"
    if ms >= 100:
        return f"{ms:,.0f}"
    if ms >= 10:
        return f"{ms:.1f}"
    if ms >= 1:
        return f"{ms:.2f}"
    return f"{ms:.3f}"


def context(path):
    """The run's context block (machine, load average, library versions)."""
    with open(path) as f:
        return json.load(f).get("context", {})


def rows(path, time_field="real_time", statistic="median"):
    """{name: (ms, entry)}: one row per benchmark run name. A file with
    aggregated repetitions gives the named aggregate; when that aggregate is
    absent but the single repetitions are in the file, "min" and "median"
    are taken from them; a file without repetitions gives each run as it is.

    time_field is "real_time" or "cpu_time". Multithreaded rows (UseRealTime,
    names ending in "/real_time", which the key drops) are read in real time
    only: their CPU time is the calling thread's alone, so with "cpu_time"
    they are left out."""
    with open(path) as f:
        entries = [b for b in json.load(f)["benchmarks"] if not b.get("error_occurred")]
    aggregates, singles = {}, {}
    for b in entries:
        name = b.get("run_name", b["name"])
        if b.get("run_type") == "aggregate":
            if b.get("aggregate_name") == statistic:
                aggregates[name] = b
        else:
            singles.setdefault(name, []).append(b)
    out = {}
    for name in list(dict.fromkeys(list(aggregates) + list(singles))):
        wall = name.endswith("/real_time")
        if wall and time_field == "cpu_time":
            continue
        field = "real_time" if wall else time_field
        if name in aggregates:
            b = aggregates[name]
        else:
            runs = sorted(singles[name], key=lambda e: e[field] * _UNIT_MS[e["time_unit"]])
            if len(runs) > 1 and statistic not in ("min", "median"):
                raise SystemExit(f"{path}: no '{statistic}' of the repetitions of {name}")
            b = runs[0] if statistic == "min" else runs[(len(runs) - 1) // 2]
        key = name[: -len("/real_time")] if wall else name
        out[key] = (b[field] * _UNIT_MS[b["time_unit"]], b)
    return out


def runs(path, time_field="real_time", statistic="median"):
    """Yields (prefix, arg, ms, entry) for every row named "<prefix>/<arg>"
    with an integer arg (see rows)."""
    for name, (ms, b) in rows(path, time_field, statistic).items():
        parts = name.split("/")
        if len(parts) == 2 and parts[1].isdigit():
            yield parts[0], int(parts[1]), ms, b
