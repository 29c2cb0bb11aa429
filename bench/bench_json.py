"""Reading Google Benchmark JSON from the cvms benchmarks, shared by
table.py, scaling.py and plot.py: one place decides which entries count and
which time is read."""
import json
import sys

_UNIT_MS = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}


def options(args):
    """(time_field, statistic, other args) from a script's arguments: --cpu
    reads CPU time instead of real (wall) time, steadier when other jobs
    share the machine; --min reads each row's minimum over its repetitions
    instead of the median (the benchmarks report it; with random
    interleaving it is each row's time in the run's fastest spell)."""
    time_field = "cpu_time" if "--cpu" in args else "real_time"
    statistic = "min" if "--min" in args else "median"
    return time_field, statistic, [a for a in args if a not in ("--cpu", "--min")]


def runs(path, time_field, statistic="median"):
    """Yields (prefix, arg, ms, entry) for every successful "<prefix>/<arg>"
    run (the given statistic only, when repetitions were aggregated).
    time_field is "real_time" or "cpu_time". Multithreaded rows
    (UseRealTime, names ending in "/real_time") are read in real time only:
    their CPU time would be the calling thread's alone, so with "cpu_time"
    they are left out."""
    entries = json.load(open(path))["benchmarks"]
    aggregates = {b.get("aggregate_name") for b in entries if b.get("run_type") == "aggregate"}
    if aggregates and statistic not in aggregates:
        sys.exit(f"{path}: no '{statistic}' of the repetitions (it has {', '.join(sorted(aggregates))}); "
                 "the minimum needs a benchmark build that reports it")
    for b in entries:
        if b.get("run_type") == "aggregate" and b.get("aggregate_name") != statistic:
            continue
        # An aggregate's name has its statistic appended ("..._median");
        # run_name is the repetitions' own.
        name = b.get("run_name", b["name"])
        wall = name.endswith("/real_time")
        if wall:
            if time_field == "cpu_time":
                continue
            name = name[: -len("/real_time")]
        parts = name.split("/")
        if b.get("error_occurred") or len(parts) != 2:
            continue
        field = "real_time" if wall else time_field
        yield parts[0], int(parts[1]), b[field] * _UNIT_MS[b["time_unit"]], b


def load(path):
    """Every successful entry of the file (medians only, when repetitions
    were aggregated), whatever its name's shape."""
    return [
        b
        for b in json.load(open(path))["benchmarks"]
        if not b.get("error_occurred")
        and (b.get("run_type") != "aggregate" or b.get("aggregate_name") == "median")
    ]


def milliseconds(entry, time_field):
    """The entry's time_field ("real_time" or "cpu_time") in milliseconds."""
    return entry[time_field] * _UNIT_MS[entry["time_unit"]]
