#!/usr/bin/env bash
# Builds the Python module `cvms` in release mode (in build/python) and
# installs it for Debian's /usr/bin/python3 into that interpreter's site
# directory for local packages (/usr/local/lib/python3.X/dist-packages on
# Debian), so that `/usr/bin/python3 -c "import cvms"` works from any
# directory. Debian's Python is externally managed (pip refuses to install
# into it): CMake installs the package files there directly.
# PYTHON=/path/to/python3 targets another interpreter; CVMS_PYTHON_SITE sets
# the directory. Run as root for a system directory (or set CVMS_PYTHON_SITE
# to one on the interpreter's path, e.g. its user site directory).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh
python=${PYTHON:-/usr/bin/python3}
[ -x "$python" ] || { echo "cvms: $python not found (set PYTHON=/path/to/python3)" >&2; exit 1; }
# The interpreter's own answer, never the first python3 on PATH: the local
# scheme's platform directory when the interpreter has one on its path
# (Debian's posix_local), else its usual site-packages.
site=${CVMS_PYTHON_SITE:-$("$python" - <<'PY'
import sys, sysconfig
schemes = sysconfig.get_scheme_names()
if "posix_local" in schemes and sysconfig.get_path("platlib", "posix_local") in sys.path:
    print(sysconfig.get_path("platlib", "posix_local"))
else:
    print(sysconfig.get_path("platlib"))
PY
)}
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S . -B build/python -G Ninja "${launcher[@]}" \
  -DCMAKE_BUILD_TYPE=Release \
  -DCVMS_BUILD_PYTHON=ON -DCVMS_BUILD_TESTS=OFF -DCVMS_BUILD_TOOLS=OFF \
  -DCVMS_BUILD_EXAMPLES=OFF -DCVMS_BUILD_BENCHMARKS=OFF \
  -DPython_EXECUTABLE="$python" -DCVMS_PYTHON_INSTALL_DIR="$site"
cmake --build build/python --target _cvms -j"$(nproc)"
cmake --install build/python --component python
(cd / && "$python" -c 'import cvms; print("cvms", cvms.__version__, "installed in", cvms.__path__[0])')
