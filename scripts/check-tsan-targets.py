#!/usr/bin/env python3
"""The TSan preset builds every suite labelled `threads`.

ctest runs the suites with that label under ThreadSanitizer; a suite the
preset's build does not list is never built there, and ctest skips its
placeholder silently (it has no label). So the two lists must agree.
"""
import json
import re
import sys
from pathlib import Path

root = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).resolve().parent.parent
suites = re.findall(r"cvms_test_suite\(\s*(\w+)[^)]*?\bLABEL\s+threads\b",
                    (root / "test" / "CMakeLists.txt").read_text())
presets = json.loads((root / "CMakePresets.json").read_text())
tsan = next(p for p in presets["buildPresets"] if p["name"] == "tsan")
missing = sorted(set(suites) - set(tsan.get("targets", [])))
if not suites:
    sys.exit("check-tsan-targets: no suite labelled threads in test/CMakeLists.txt")
if missing:
    sys.exit("check-tsan-targets: labelled threads but not built by the tsan build preset "
             "(CMakePresets.json): " + ", ".join(missing))
print(f"check-tsan-targets: {len(suites)} suites labelled threads, all built by the tsan preset")
