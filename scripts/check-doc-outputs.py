#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Checks that the command outputs quoted in the documentation are what the tool prints.

Every fenced block marked ```console in README.md and docs/*.md is a transcript:
lines starting with "$ " are shell commands, the lines below each one (up to the
next "$ " line) its expected output, stdout and stderr together. The commands of
one block run in order, in one fresh temporary directory, with `cvms` on PATH
being the tool under test; a later command may read what an earlier one wrote.
A relative path in a command that names a file of the source tree (such as
examples/data/cube.off or test/data/...) is copied into the temporary directory
at the same relative path first, so transcripts read as if run from the root of
a checkout.

Expected output may contain:
  - a line "..." alone: any number of lines (zero or more) of the real output;
  - wall-clock figures, "<number> ms" after "time: ", which are masked on both
    sides (they differ from run to run).

Any other fenced block containing a "$ cvms" line is an error: a quoted output
is either checked (```console) or not a transcript of the tool.

Usage: check-doc-outputs.py --cvms PATH/TO/cvms [--root DIR] [FILE.md ...]
Exit code 0 when every transcript matches, 1 otherwise (each mismatch shown as a
diff with the file and line of its command).
"""
import argparse
import difflib
import glob
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

ELLIPSIS = "..."
TIME = re.compile(r"(time: )[0-9]+(?:\.[0-9]+)? ms")
FENCE = re.compile(r"^(`{3,})\s*([A-Za-z0-9_+-]*)\s*$")


def mask(line):
    return TIME.sub(r"\1<time> ms", line.rstrip())


def blocks(path):
    """Yields (language, first content line number, content lines) of each fenced block."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    i = 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        fence, lang = m.group(1), m.group(2)
        start = i + 1
        j = start
        while j < len(lines) and lines[j].rstrip() != fence:
            j += 1
        yield lang, start + 1, lines[start:j]
        i = j + 1


def transcript(lines, first_line):
    """Splits a console block into (line number, command, expected output lines)."""
    steps = []
    for offset, line in enumerate(lines):
        if line.startswith("$ "):
            steps.append((first_line + offset, line[2:], []))
        elif steps:
            steps[-1][2].append(line)
        elif line.strip():
            raise ValueError(f"line {first_line + offset}: output before the first '$ ' command")
    return steps


def matches(expected, actual):
    """Line-wise match where an expected "..." line stands for any run of lines."""
    parts = [[]]
    for line in expected:
        if line.strip() == ELLIPSIS:
            parts.append([])
        else:
            parts[-1].append(mask(line))
    actual = [mask(line) for line in actual]
    if len(parts) == 1:
        return parts[0] == actual
    head, *middle, tail = parts
    if actual[:len(head)] != head or len(actual) < len(head) + len(tail):
        return False
    if tail and actual[len(actual) - len(tail):] != tail:
        return False
    pos, end = len(head), len(actual) - len(tail)
    for part in middle:
        if not part:
            continue
        found = -1
        for k in range(pos, end - len(part) + 1):
            if actual[k:k + len(part)] == part:
                found = k
                break
        if found < 0:
            return False
        pos = found + len(part)
    return True


def stage_inputs(command, root, cwd):
    """Copies every source-tree file a command names by a relative path into cwd."""
    try:
        words = shlex.split(command, comments=True)
    except ValueError:
        words = command.split()
    for word in words:
        for candidate in (word, word.split("=", 1)[-1]):
            if not candidate or os.path.isabs(candidate) or ".." in candidate.split("/"):
                continue
            source = os.path.join(root, candidate)
            target = os.path.join(cwd, candidate)
            if os.path.isfile(source) and not os.path.exists(target):
                os.makedirs(os.path.dirname(target) or cwd, exist_ok=True)
                shutil.copyfile(source, target)


def run_block(steps, cvms, root, path):
    failures = []
    with tempfile.TemporaryDirectory(prefix="cvms-doc-") as tmp:
        bindir = os.path.join(tmp, ".bin")
        work = os.path.join(tmp, "work")
        os.makedirs(bindir)
        os.makedirs(work)
        os.symlink(os.path.abspath(cvms), os.path.join(bindir, "cvms"))
        env = dict(os.environ, PATH=bindir + os.pathsep + os.environ.get("PATH", ""), LC_ALL="C")
        for line_no, command, expected in steps:
            stage_inputs(command, root, work)
            try:
                done = subprocess.run(["bash", "-c", command], cwd=work, env=env, timeout=300,
                                      stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
                output = done.stdout.decode("utf-8", "replace")
            except subprocess.TimeoutExpired:
                output = "<timed out after 300 s>\n"
            # Trailing blank lines are invisible in a document: ignored on both sides.
            actual = output.split("\n")
            while actual and not actual[-1].strip():
                actual.pop()
            while expected and not expected[-1].strip():
                expected = expected[:-1]
            if not matches(expected, actual):
                diff = "\n".join(difflib.unified_diff([mask(x) for x in expected], [mask(x) for x in actual],
                                                      "documented", "printed", lineterm=""))
                failures.append(f"{path}:{line_no}: $ {command}\n{diff}")
    return failures


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--cvms", required=True, help="the cvms tool to run for `cvms`")
    parser.add_argument("--root", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."),
                        help="source tree (default: this script's checkout)")
    parser.add_argument("files", nargs="*", help="Markdown files (default: README.md and docs/*.md)")
    args = parser.parse_args(argv)
    root = os.path.abspath(args.root)
    files = args.files or [os.path.join(root, "README.md")] + sorted(glob.glob(os.path.join(root, "docs", "*.md")))

    failures, checked = [], 0
    for path in files:
        shown = os.path.relpath(path, root)
        for lang, first_line, lines in blocks(path):
            if lang != "console":
                if any(line.startswith("$ cvms") for line in lines):
                    failures.append(f"{shown}:{first_line}: a block quoting `$ cvms` must be marked ```console")
                continue
            try:
                steps = transcript(lines, first_line)
            except ValueError as e:
                failures.append(f"{shown}: {e}")
                continue
            failures += run_block(steps, args.cvms, root, shown)
            checked += len(steps)
    for failure in failures:
        print(failure, end="\n\n")
    if failures:
        print(f"doc outputs: {len(failures)} of the quoted commands differ from what the tool prints")
        return 1
    print(f"doc outputs: {checked} quoted commands in {len(files)} files print what the documents say")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
