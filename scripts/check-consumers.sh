#!/usr/bin/env bash
# Builds and runs test/consumer (and the conan test_package's CMake project)
# in every way a user consumes cvms, each against a fresh install prefix:
#   - CMake find_package: static install, shared install, build tree;
#   - pkg-config on the command line: static and shared installs, --static;
#   - fully static executables (-static), by pkg-config and by CMake;
#   - a plugin: a shared object linking the static libcvms.a (by CMake and by
#     pkg-config), loaded with dlopen and run on two threads;
#   - package metadata: version check, soname, relocatable cvms.pc, LICENSE.
#
# Usage: scripts/check-consumers.sh [STATIC_BUILD_DIR [SHARED_BUILD_DIR]]
#   STATIC_BUILD_DIR: an already built static cvms build tree to install and
#   to use as the build-tree package (CI passes build/dev). Without it, a
#   library-only static build is made in build/pkg-static.
#   SHARED_BUILD_DIR: an already configured shared-library build tree
#   (BUILD_SHARED_LIBS=ON) to install (CI passes its packager build, so the
#   library is not compiled twice). Without it, a library-only shared build
#   is made in build/pkg-shared.
# Prints "consumers: N passed, M failed" and exits non-zero if any failed.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD

cxx=${CXX:-c++}
# Consumers must compile cleanly with the warnings a careful user enables.
cxxflags=(-std=c++20 -O1 -Wall -Wextra -Wpedantic -Werror)
lib_only=(-DCVMS_BUILD_TESTS=OFF -DCVMS_BUILD_BENCHMARKS=OFF -DCVMS_BUILD_TOOLS=OFF -DCVMS_BUILD_EXAMPLES=OFF)

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
log="$work/log"

passed=0
failed=0
# check NAME COMMAND...: runs COMMAND quietly; on failure shows its output.
check() {
  local name=$1
  shift
  if "$@" >"$log" 2>&1; then
    passed=$((passed + 1))
    echo "  ok    $name"
  else
    failed=$((failed + 1))
    echo "  FAIL  $name"
    sed 's/^/        /' "$log" | tail -n 40
  fi
}

build_lib() {  # build_lib DIR [cmake args...]: configure + build the library only
  local dir=$1
  shift
  cmake -S "$root" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release "${lib_only[@]}" "$@" >/dev/null
  cmake --build "$dir" -j2 >/dev/null
}

cmake_consumer() {  # cmake_consumer SRC BUILD [cmake args...]: configure, build
  local src=$1 dir=$2
  shift 2
  cmake -S "$src" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release "$@" &&
    cmake --build "$dir"
}

is_fully_static() {  # no program interpreter, no shared library needed
  ! readelf -lW "$1" | grep 'INTERP' >/dev/null && ! readelf -dW "$1" | grep 'NEEDED' >/dev/null
}

needs_libcvms_so() { readelf -dW "$1" | grep "NEEDED.*\[libcvms\.so" >/dev/null; }

pc() { PKG_CONFIG_PATH="$1/lib/pkgconfig${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}" pkg-config "${@:2}"; }

pc_build() {  # pc_build PREFIX OUT [extra flags...]: g++ main.cpp $(pkg-config ...)
  local prefix=$1 out=$2
  shift 2
  local static=()
  [[ " $* " == *" -static "* ]] && static=(--static)
  # shellcheck disable=SC2046  # word splitting of pkg-config output is intended
  "$cxx" "${cxxflags[@]}" "$@" test/consumer/main.cpp -o "$out" \
    $(pc "$prefix" "${static[@]}" --cflags --libs cvms)
}

version=$(sed -n 's/^project(cvms VERSION \([0-9.]*\).*/\1/p' CMakeLists.txt)
major_minor=${version%.*}

echo "== libraries"
static_build=${1:-}
if [[ -z "$static_build" ]]; then
  static_build=build/pkg-static
  build_lib "$static_build"
else
  cmake --build "$static_build" --target cvms -j2 >/dev/null
fi
shared_build=${2:-}
if [[ -z "$shared_build" ]]; then
  shared_build=build/pkg-shared
  build_lib "$shared_build" -DBUILD_SHARED_LIBS=ON
else
  if ! grep -q '^BUILD_SHARED_LIBS:BOOL=ON$' "$shared_build/CMakeCache.txt"; then
    echo "consumers: $shared_build is not a shared-library build (BUILD_SHARED_LIBS=ON)" >&2
    exit 1
  fi
  cmake --build "$shared_build" --target cvms -j2 >/dev/null
fi
static_prefix="$work/static"
shared_prefix="$work/shared"
cmake --install "$static_build" --prefix "$static_prefix" >/dev/null
cmake --install "$shared_build" --prefix "$shared_prefix" >/dev/null
echo "   static: $static_build -> fresh prefix; shared: $shared_build -> fresh prefix"

# Each check is one function; it chains its commands with && because errexit
# is off inside a function called from an if (check's).
static_cmake() {
  cmake_consumer test/consumer "$work/c-static" -DCMAKE_PREFIX_PATH="$static_prefix" &&
    "$work/c-static/cvms_consumer"
}
static_cmake_no_so() { ! readelf -dW "$work/c-static/cvms_consumer" | grep libcvms >/dev/null; }
shared_cmake() {
  cmake_consumer test/consumer "$work/c-shared" -DCMAKE_PREFIX_PATH="$shared_prefix" &&
    needs_libcvms_so "$work/c-shared/cvms_consumer" &&
    "$work/c-shared/cvms_consumer"
}
shared_soname() {
  local lib="$shared_prefix/lib"
  readelf -dW "$lib/libcvms.so.$version" | grep "SONAME.*\[libcvms\.so\.$major_minor\]" >/dev/null &&
    [[ "$(readlink "$lib/libcvms.so")" == "libcvms.so.$major_minor" ]] &&
    [[ "$(readlink "$lib/libcvms.so.$major_minor")" == "libcvms.so.$version" ]]
}
tree_cmake() {
  cmake_consumer test/consumer "$work/c-tree" -Dcvms_DIR="$root/$static_build" &&
    "$work/c-tree/cvms_consumer"
}
full_static_cmake() {
  cmake_consumer test/consumer "$work/c-full" -DCMAKE_PREFIX_PATH="$static_prefix" \
    -DCVMS_CONSUMER_FULLY_STATIC=ON &&
    is_fully_static "$work/c-full/cvms_consumer" &&
    "$work/c-full/cvms_consumer"
}
# The static library is position-independent by default: a shared object
# links libcvms.a (its thread-local data included) and runs when loaded.
plugin_so() { echo "$1/libcvms_plugin.so"; }
plugin_cmake() {
  cmake_consumer test/consumer "$work/c-plugin" -DCMAKE_PREFIX_PATH="$static_prefix" \
    -DCVMS_CONSUMER_PLUGIN=ON &&
    ! readelf -dW "$(plugin_so "$work/c-plugin")" | grep libcvms >/dev/null &&
    "$work/c-plugin/cvms_plugin_host" "$(plugin_so "$work/c-plugin")"
}
plugin_pc() {
  # shellcheck disable=SC2046  # word splitting of pkg-config output is intended
  "$cxx" "${cxxflags[@]}" -shared -fPIC -Wl,-z,defs test/consumer/plugin.cpp -o "$work/pc-plugin.so" \
    $(pc "$static_prefix" --cflags --libs cvms) &&
    "$cxx" "${cxxflags[@]}" test/consumer/plugin_host.cpp -o "$work/pc-plugin-host" -pthread -ldl &&
    "$work/pc-plugin-host" "$work/pc-plugin.so"
}
# CMAKE_POSITION_INDEPENDENT_CODE=OFF still turns it off (configured only).
pic_off() {
  cmake -S "$root" -B "$work/nopic" -G Ninja -DCMAKE_BUILD_TYPE=Release "${lib_only[@]}" \
    -DCMAKE_POSITION_INDEPENDENT_CODE=OFF >/dev/null &&
    grep -q 'FLAGS = .*-fPIC' "$static_build/build.ninja" &&
    ! grep -q 'FLAGS = .*-fPIC' "$work/nopic/build.ninja"
}
license_installed() {
  cmp "$root/LICENSE" "$static_prefix/share/doc/cvms/LICENSE" &&
    cmp "$root/LICENSE" "$shared_prefix/share/doc/cvms/LICENSE"
}
test_package_cmake() {
  cmake_consumer test_package "$work/c-tp" -DCMAKE_PREFIX_PATH="$static_prefix" &&
    "$work/c-tp/test_package"
}
# find_package(cvms REQ): a request for another minor version must be refused
# before 1.0 (another major version after), by the version file's rule.
version_request() {
  mkdir -p "$work/vreq" &&
    cat >"$work/vreq/CMakeLists.txt" <<'EOT' &&
cmake_minimum_required(VERSION 3.25)
project(vreq LANGUAGES CXX)
find_package(cvms ${REQ} CONFIG REQUIRED)
EOT
    cmake -S "$work/vreq" -B "$work/vreq/b-$1" -DREQ="$1" -DCMAKE_PREFIX_PATH="$static_prefix"
}
version_refused() { ! version_request "$1"; }
pc_meta() {
  pc "$static_prefix" --validate cvms &&
    [[ "$(pc "$static_prefix" --modversion cvms)" == "$version" ]]
}
pc_relocated() {  # cvms.pc was configured for another prefix: must still point here
  local inc libdir
  inc=$(pc "$static_prefix" --cflags-only-I cvms | tr ' ' '\n' | sed -n 's/^-I//p' | head -n1) &&
    libdir=$(pc "$static_prefix" --libs-only-L cvms | tr ' ' '\n' | sed -n 's/^-L//p' | head -n1) &&
    [[ "$(realpath "$inc")" == "$(realpath "$static_prefix/include")" ]] &&
    [[ "$(realpath "$libdir")" == "$(realpath "$static_prefix/lib")" ]]
}
pc_libs() {
  pc "$static_prefix" --libs cvms | grep -- "-lcvms.*-lgmpxx.*-lgmp" >/dev/null &&
    pc "$static_prefix" --static --libs cvms | grep -- "-lcvms.*-lgmpxx.*-lgmp" >/dev/null
}
pc_static() { pc_build "$static_prefix" "$work/pc-static" && "$work/pc-static"; }
pc_shared() {
  pc_build "$shared_prefix" "$work/pc-shared" &&
    needs_libcvms_so "$work/pc-shared" &&
    LD_LIBRARY_PATH="$shared_prefix/lib" "$work/pc-shared"
}
pc_full_static() {
  pc_build "$static_prefix" "$work/pc-full" -static &&
    is_fully_static "$work/pc-full" &&
    "$work/pc-full"
}

# The installed headers are the public surface: none of the library's
# internals (the filter machinery, its counters, unchecked construction) may
# appear in them, and each must compile on its own.
installed_surface() {
  ! grep -rnE 'from_trusted_soup|ConvexPolyhedronAccess|Vec[23]Ref|ApproxVec[23]|PredicateCounters|predicate_counters|EdgeFacetSearch|ContributingVertexSearch|KeptAllocator|KeptVector|ResultSlab|allocate_kept|LimbArena|PolyhedronParts|PolyhedronApproximations|FacetPlanes|PlaneStore|DistinctPoints|PackedVectors|DyadicPoints|cond INTERNAL|namespace detail|detail::|std::atomic' \
    "$static_prefix/include" &&
    [[ ! -e "$static_prefix/include/cvms/kept_allocator.hpp" ]]
}
headers_self_contained() {
  local h
  for h in "$static_prefix"/include/cvms/*.hpp; do
    printf '#include <cvms/%s>\n' "$(basename "$h")" |
      "$cxx" "${cxxflags[@]}" -fsyntax-only -I"$static_prefix/include" -x c++ - || return 1
  done
}

other_minor="${version%%.*}.$(($(echo "$version" | cut -d. -f2) + 1))"

echo "== CMake find_package"
check "static install: build, run" static_cmake
check "static install: no libcvms.so needed" static_cmake_no_so
check "shared install: build, run via RPATH, needs libcvms.so" shared_cmake
check "shared install: soname libcvms.so.$major_minor and symlinks" shared_soname
check "build tree (-Dcvms_DIR=$static_build): build, run" tree_cmake
check "fully static (-static, CvmsGMP_USE_STATIC_LIBS): build, run" full_static_cmake
check "conan test_package's CMake project on the static install" test_package_cmake
check "plugin: shared object linking the static libcvms.a, dlopen, two threads" plugin_cmake
check "CMAKE_POSITION_INDEPENDENT_CODE=OFF: no -fPIC" pic_off
check "find_package(cvms $major_minor) accepted" version_request "$major_minor"
check "find_package(cvms $other_minor) refused" version_refused "$other_minor"

echo "== installed headers"
check "no library internals in the installed headers" installed_surface
check "every installed header compiles on its own" headers_self_contained

echo "== pkg-config"
check "cvms.pc valid, version $version" pc_meta
check "cvms.pc relocatable" pc_relocated
check "--libs and --static --libs: -lcvms -lgmpxx -lgmp" pc_libs
check "static install: c++ \$(pkg-config --cflags --libs cvms), run" pc_static
check "shared install: c++ \$(pkg-config --cflags --libs cvms), run" pc_shared
check "fully static: c++ -static \$(pkg-config --static ...), run" pc_full_static
check "plugin: c++ -shared \$(pkg-config ...) on libcvms.a, dlopen, run" plugin_pc

echo "== package files"
check "LICENSE installed in share/doc/cvms" license_installed

echo "consumers: $passed passed, $failed failed"
[[ $failed -eq 0 ]]
