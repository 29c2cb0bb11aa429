#!/usr/bin/env bash
# Fails on process words: the tree says what the code is and why, in terms
# that stay true; how it got there lives in git commit messages and
# CHANGELOG.md. Each hit is printed as file:line:text.
#
# Usage: scripts/check-words.sh [FILE|DIR]...
#        scripts/check-words.sh --self-test
#   No argument: every tracked file (git ls-files; outside a git checkout,
#   e.g. in a source archive, the check is skipped). Otherwise the files
#   given and every file under the directories given. --self-test plants
#   each kind of word in a temporary file and checks that every one is found
#   and that look-alikes (hex constants, digests, times) are not.
# Always skipped: CHANGELOG.md, docs/bench/*.json (generated benchmark data)
# and files with a NUL byte (binary).
#
# A process word is, case-insensitively:
#   - a numbered work item: "stop", "issue(s)" or "task" followed by a
#     number, also across a line break;
#   - "session" as a word;  (check-words: allow)
#   - a commit hash: 7 to 40 hex digits with at least one letter a-f and one
#     digit, after commit/at/from/in/on/main/base/since/reverted/revert(s)/
#     cherry-picked/fixed-by, or alone in parentheses; a 0x constant never
#     matches (no word boundary between the x and its digits), nor does a
#     longer hex string such as a SHA-256 digest;
#   - a date, YYYY-MM-DD;
#   - a narrative: "tried and reverted", "measured on", "before/after", or two  (check-words: allow)
#     time figures joined by -> or a right arrow (a before-and-after).
# A line that must keep such a word ends with the marker "check-words: allow"
# (prefer rewording).
set -euo pipefail
cd "$(dirname "$0")/.."

exec /usr/bin/env python3 - "$@" <<'PY'
import os, re, subprocess, sys, tempfile

HEX = r"(?=[0-9a-f]*[a-f])(?=[0-9a-f]*[0-9])[0-9a-f]{7,40}"
UNIT = r"(?:ns|us|µs|ms|s|sec|seconds|min)"
RULES = [re.compile(rx, re.IGNORECASE) for rx in (
    r"\b(?:stops?|issues?|tasks?)\s+#?\d+",
    r"\bsessions?\b",
    r"\b(?:commits?|at|from|in|on|main|base|since|reverted|reverts?|cherry-picked|fixed-by)\s+"
    + HEX + r"\b",
    r"\(\s*" + HEX + r"\s*\)",
    r"\b(?:19|20)\d\d-(?:0[1-9]|1[0-2])-(?:0[1-9]|[12]\d|3[01])\b",
    r"\btried and reverted\b|\bmeasured on\b|\bbefore\s*/\s*after\b",
    r"\d[\d.,]*\s*" + UNIT + r"?\s*(?:->|→)\s*\d[\d.,]*\s*" + UNIT + r"\b",
)]
# "issue" at the end of a line and a number at the start of the next one.
DANGLING = re.compile(r"\b(?:stops?|issues?|tasks?)\s*$", re.IGNORECASE)
NUMBER_FIRST = re.compile(r"^[\s/#*;>-]*#?\d")
ALLOW = "check-words: allow"


def skipped(path):
    p = os.path.normpath(path)
    return p == "CHANGELOG.md" or (p.startswith("docs/bench/") and p.endswith(".json"))


def check(files):
    hits = []
    for path in files:
        if skipped(path) or not os.path.isfile(path):
            continue
        with open(path, "rb") as f:
            data = f.read()
        if b"\0" in data:
            continue
        previous = ""
        for n, line in enumerate(data.decode("utf-8", "replace").splitlines(), 1):
            if ALLOW not in line and (any(rx.search(line) for rx in RULES) or
                                      (DANGLING.search(previous) and NUMBER_FIRST.search(line))):
                hits.append(f"{path}:{n}:{line.strip()}")
            previous = line
    return hits


def self_test():
    # Each planted line must be found (the marker keeps this file itself clean).
    planted = [
        "// see stop 41 for the numbers",  # check-words: allow
        "# Issue 18 item 6: a failed write",  # check-words: allow
        "(issues 15 and 16)",  # check-words: allow
        "// as in task 3",  # check-words: allow
        "written in one session",  # check-words: allow
        "rebuilt from main at f06faae",  # check-words: allow
        "before the double filters (commit 787142b)",  # check-words: allow
        "a fix (7de4b3a) of the bound",  # check-words: allow
        "### Long run, 2026-11-23",  # check-words: allow
        "a prefetch was tried and reverted",  # check-words: allow
        "| load | 41 ms -> 29 ms |",  # check-words: allow
        "loading went from 1.9 s → 0.8 s",  # check-words: allow
        "measured on the small machine",  # check-words: allow
    ]
    # A number on the line after "issue": found on that second line.
    dangling = ["// the limits of", "// (see the issue", "// 18 item 5)"]  # check-words: allow
    clean = [
        "constexpr std::uint64_t kMask = 0x7de4b3a5f00dull;",
        "EXPECT_EQ(sha256(text), \"e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855\");",
        "stops at the first token; the 18 items of a list",
        "the issue of a prefetch; a task queue of 4 threads",
        "it->second = 2; x -> y; 4 -> 5 facets",
        "a 2-dimensional set at 1e-9; version 1.2.3",
        "the hash (deadbeef) is a word, the digits (1234567) are a number",
        "measured side by side in one run",
        "used_sessionless_id = 3;",
    ]
    with tempfile.TemporaryDirectory() as d:
        bad, good, cut = (os.path.join(d, n) for n in ("planted.txt", "clean.txt", "dangling.txt"))
        for path, lines in ((bad, planted), (good, clean), (cut, dangling)):
            with open(path, "w") as f:
                f.write("\n".join(lines) + "\n")
        found, wrong, split = check([bad]), check([good]), check([cut])
    for hit in found + wrong + split:
        print(hit)
    ok = len(found) == len(planted) and not wrong and [h.split(":")[1] for h in split] == ["3"]
    print(f"check-words self-test: {len(found)} of {len(planted)} planted lines found, "
          f"{len(split)} of 1 across a line break, {len(wrong)} false positive(s) in "
          f"{len(clean)} look-alikes: {'ok' if ok else 'FAILED'}")
    return 0 if ok else 1


args = sys.argv[1:]
if args == ["--self-test"]:
    sys.exit(self_test())
if args:
    files = []
    for a in args:
        if os.path.isdir(a):
            for root, dirs, names in os.walk(a):
                dirs.sort()
                files += [os.path.join(root, n) for n in sorted(names)]
        else:
            files.append(a)
else:
    listed = subprocess.run(["git", "ls-files", "-z"], capture_output=True)
    if listed.returncode != 0:
        print("check-words: not a git checkout, skipped")
        sys.exit(0)
    files = [f for f in listed.stdout.decode().split("\0") if f]

hits = check(files)
for hit in hits:
    print(hit)
if hits:
    print(f"check-words: {len(hits)} line(s) with process words (numbered stops, issues "
          "or tasks, 'session', commit hashes, dates, before/after narratives): say why "  # check-words: allow
          "the code is as it is instead; history goes in git and CHANGELOG.md", file=sys.stderr)
    sys.exit(1)
print(f"check-words: no process words in {len(files)} file(s)")
PY
