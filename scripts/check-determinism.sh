#!/usr/bin/env bash
# Determinism across processes and builds: runs the same cvms CLI commands
# twice with the static-library CLI and once with a CLI linked against the
# shared library, and requires byte-identical output files, stdout and exit
# codes (cmp). In-process determinism is test/determinism_test.cpp.
#
# Usage: scripts/check-determinism.sh [STATIC_BUILD_DIR [SHARED_BUILD_DIR]]
#   STATIC_BUILD_DIR  a built tree with tools/cvms (default build/dev)
#   SHARED_BUILD_DIR  a build tree of the shared library (default
#                     build/pkg-shared, which scripts/check-consumers.sh makes;
#                     library-only there, so it is reconfigured here with the
#                     tools on and only the CLI is built; created if missing)
# Prints "determinism: N passed, M failed"; skips (exit 0) if the CLI is not built.
set -euo pipefail
cd "$(dirname "$0")/.."
static_dir=${1:-build/dev}
shared_dir=${2:-build/pkg-shared}
static_cli=$static_dir/tools/cvms
if [[ ! -x $static_cli ]]; then
  echo "determinism: skipped ($static_cli is not built)"
  exit 0
fi

if [[ -f $shared_dir/CMakeCache.txt ]]; then
  cmake -S . -B "$shared_dir" -DBUILD_SHARED_LIBS=ON -DCVMS_BUILD_TOOLS=ON >/dev/null
else
  cmake -S . -B "$shared_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DBUILD_SHARED_LIBS=ON \
    -DCVMS_BUILD_TESTS=OFF -DCVMS_BUILD_BENCHMARKS=OFF -DCVMS_BUILD_TOOLS=ON >/dev/null
fi
cmake --build "$shared_dir" --target cvms_cli -j2 >/dev/null
shared_cli=$shared_dir/tools/cvms
if ! ldd "$shared_cli" | grep 'libcvms\.so' >/dev/null; then
  echo "determinism: $shared_cli is not linked against libcvms.so" >&2
  exit 1
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
inputs=$work/inputs
mkdir -p "$inputs"
cp test/data/cube.off test/data/tetra_exact.off test/data/points.xyz "$inputs/"
# 3000 pseudo-random points with many ties (a fixed LCG, no awk rand()),
# and a ball-like cloud of rationals, so that orders actually matter.
awk 'BEGIN { s = 12345; for (i = 0; i < 3000; i++) { for (c = 0; c < 3; c++) {
       s = (s * 69069 + 1) % 4294967296; v[c] = int(s / 65536) % 41 - 20 }
       print v[0], v[1], v[2] } }' >"$inputs/cloud.xyz"
awk 'BEGIN { s = 777; for (i = 0; i < 400; i++) { for (c = 0; c < 3; c++) {
       s = (s * 69069 + 1) % 4294967296; v[c] = (int(s / 65536) % 201 - 100) "/" (1 + int(s / 7) % 7) }
       print v[0], v[1], v[2] } }' >"$inputs/fractions.xyz"

# run CLI OUTDIR: every command writes OUTDIR/<name>.<ext>, its stdout and
# stderr and its exit code.
run() {
  local cli=$1 out=$2
  mkdir -p "$out"
  local i=$inputs
  local -a commands=(
    "hull_cloud_off|hull $i/cloud.xyz -o $out/hull_cloud.off"
    "hull_cloud_obj|hull $i/cloud.xyz -o $out/hull_cloud.obj"
    "hull_fractions_off|hull $i/fractions.xyz -o $out/hull_fractions.off"
    "hull_fractions_float|hull $i/fractions.xyz --float -o $out/hull_fractions_float.off"
    "hull_points_stl|hull $i/points.xyz -o $out/hull_points.stl"
    "sum_cube_tetra|sum $i/cube.off $i/tetra_exact.off -o $out/sum_cube_tetra.off"
    "sum_cube_tetra_chms|sum $i/cube.off $i/tetra_exact.off --algorithm chms -o $out/sum_cube_tetra_chms.obj"
    "check_cube|check $i/cube.off"
    "check_missing|check $i/missing.off"
  )
  for entry in "${commands[@]}"; do
    local name=${entry%%|*} args=${entry#*|}
    # shellcheck disable=SC2086 # args is a word list on purpose
    set +e
    "$cli" $args >"$out/$name.stdout" 2>"$out/$name.stderr"
    echo $? >"$out/$name.exit"
    set -e
  done
  # The sums of the hulls above, once they exist (the hull files are inputs now).
  if [[ -s $out/hull_cloud.off && -s $out/hull_fractions.off ]]; then
    set +e
    "$cli" sum "$out/hull_cloud.off" "$out/hull_fractions.off" -o "$out/sum_hulls.off" \
      >"$out/sum_hulls.stdout" 2>"$out/sum_hulls.stderr"
    echo $? >"$out/sum_hulls.exit"
    "$cli" sum "$out/hull_fractions.off" "$inputs/cube.off" -o "$out/sum_fractions_cube.stl" \
      >"$out/sum_fractions_cube.stdout" 2>"$out/sum_fractions_cube.stderr"
    echo $? >"$out/sum_fractions_cube.exit"
    set -e
  fi
}

run "$static_cli" "$work/static1"
run "$static_cli" "$work/static2"
run "$shared_cli" "$work/shared"
# stderr names the input paths, which are the same for all runs; output
# paths differ, so they are normalised out of stdout and stderr.
for d in static1 static2 shared; do
  for f in "$work/$d"/*.stdout "$work/$d"/*.stderr; do sed -i "s#$work/$d#OUT#g" "$f"; done
done

passed=0
failed=0
for f in "$work/static1"/*; do
  name=$(basename "$f")
  for other in static2 shared; do
    if cmp -s "$f" "$work/$other/$name"; then
      passed=$((passed + 1))
    else
      failed=$((failed + 1))
      echo "  FAIL  $name differs between static1 and $other"
    fi
  done
done
produced=$(find "$work/static1" -type f \( -name '*.off' -o -name '*.obj' -o -name '*.stl' \) | wc -l)
if [[ $produced -lt 5 ]]; then
  echo "  FAIL  only $produced output files were produced"
  failed=$((failed + 1))
fi
echo "determinism: $passed passed, $failed failed ($produced output files, 2 static runs + 1 shared)"
[[ $failed -eq 0 ]]
