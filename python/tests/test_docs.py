# SPDX-License-Identifier: MIT
"""Every ```python block of docs/python.md and README.md runs, and prints what
its comments say: a line `print(...)  # text` must print `text`."""

import contextlib
import io
import pathlib
import re

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


def blocks():
    for name in ["docs/python.md", "README.md"]:
        text = (ROOT / name).read_text()
        for i, block in enumerate(re.findall(r"^```python\n(.*?)^```", text, re.M | re.S)):
            yield pytest.param(block, id=f"{name}#{i}")


@pytest.mark.parametrize("block", list(blocks()))
def test_block_runs_and_prints_what_it_says(block):
    if "dask" in block:
        pytest.importorskip("dask.distributed")
    expected = [m.group(1) for m in re.finditer(r"^\s*print\(.*\)\s+# (.*)$", block, re.M)]
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        exec(compile(block, "<doc>", "exec"), {"__name__": "__main__"})
    printed = out.getvalue().splitlines()
    if expected:
        assert printed == expected
    else:
        assert printed  # every block shows something
