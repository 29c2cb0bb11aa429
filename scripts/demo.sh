#!/usr/bin/env bash
# Quick start (1): installs what is missing, builds the release tool and runs
# the main job on built-in shapes.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/deps.sh
cmake --workflow --preset release >/dev/null
build/release/tools/cvms demo "$@"
