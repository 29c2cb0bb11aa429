#!/usr/bin/env bash
# Runs the cvms CLI under valgrind (memcheck, full leak check) on a few
# inputs: good files, bad files (the CLI must exit 1 with one line on stderr,
# and valgrind must still report no error and no leak), a hull and a sum.
#
# Usage: scripts/check-valgrind.sh [CLI]   (default build/dev/tools/cvms)
# Valgrind's own failures exit 99, so they are told apart from the CLI's
# documented exit code 1 for bad input; each run's "ERROR SUMMARY" must say 0.
# Prints "valgrind: N passed, M failed"; skips (exit 0) if the CLI is not built
# or valgrind is not installed.
set -euo pipefail
cd "$(dirname "$0")/.."
cli=${1:-build/dev/tools/cvms}
if [[ ! -x $cli ]]; then
  echo "valgrind: skipped ($cli is not built)"
  exit 0
fi
if ! command -v valgrind >/dev/null; then
  echo "valgrind: skipped (valgrind is not installed; Debian: apt-get install valgrind)"
  exit 0
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Bad solids the readers accept but the polyhedron checks reject.
cat >"$work/reflex.off" <<'END'
OFF
# a tetrahedron whose base is dented upwards to (1, 1, 1/2): reflex edges
5 6 0
0 0 0
4 0 0
0 4 0
1 1 1
1 1 1/2
3 0 1 3
3 1 2 3
3 2 0 3
3 0 2 4
3 2 1 4
3 1 0 4
END
cat >"$work/open.off" <<'END'
OFF
4 3 0
0 0 0
1 0 0
0 1 0
0 0 1
3 0 2 1
3 0 1 3
3 0 3 2
END
printf 'OFF\n1000000000000 1 0\n0 0 0\n' >"$work/lying.off"

passed=0
failed=0
# expect CODE NAME ARGS...: runs the CLI under valgrind, requires exit CODE
# and a clean valgrind report.
expect() {
  local code=$1 name=$2
  shift 2
  local log=$work/$name.valgrind
  set +e
  valgrind --error-exitcode=99 --leak-check=full --show-leak-kinds=definite,indirect \
    --errors-for-leak-kinds=definite,indirect --log-file="$log" "$cli" "$@" >"$work/$name.out" 2>"$work/$name.err"
  local got=$?
  set -e
  if [[ $got -eq $code ]] && grep -q "ERROR SUMMARY: 0 errors" "$log"; then
    passed=$((passed + 1))
    echo "  ok    $name (exit $got)"
  else
    failed=$((failed + 1))
    echo "  FAIL  $name: exit $got, expected $code"
    grep -E "ERROR SUMMARY|Invalid|uninitialised|definitely|indirectly" "$log" | head -n 20 | sed 's/^/        /'
    sed 's/^/        stderr: /' "$work/$name.err" | head -n 5
  fi
}

expect 0 check_cube check test/data/cube.off
expect 0 check_tetra_exact check test/data/tetra_exact.off
expect 0 check_reflex check "$work/reflex.off"  # a valid solid that is not convex
expect 0 sum_reflex sum "$work/reflex.off" test/data/cube.off -o "$work/reflex_sum.off"  # the sum as one solid
expect 0 check_reflex_sum check "$work/reflex_sum.off"
expect 1 sum_reflex_three sum "$work/reflex.off" test/data/cube.off test/data/cube.off -o "$work/reflex_three.off"
expect 0 sum_reflex_pieces sum "$work/reflex.off" test/data/cube.off --pieces -o "$work/reflex_sum.obj"
expect 1 check_open check "$work/open.off"
expect 1 check_lying_header check "$work/lying.off"
for bad in test/data/bad/truncated_faces.off test/data/bad/nan.off test/data/bad/binary_junk.stl; do
  [[ -f $bad ]] && expect 1 "check_$(basename "$bad")" check "$bad"
done
expect 0 hull_points hull test/data/points.xyz -o "$work/hull.off"
expect 0 sum_cube_tetra sum test/data/cube.off test/data/tetra_exact.off -o "$work/sum.off"
expect 0 sum_cube_tetra_stl sum test/data/cube.off test/data/tetra_colors.off --algorithm chms -o "$work/sum.stl"
echo "valgrind: $passed passed, $failed failed"
[[ $failed -eq 0 ]]
