#!/usr/bin/env bash
# Quick start (2): installs what is missing, builds and runs the whole default
# test suite (every test except the soak label).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh
cmake --workflow --preset dev
