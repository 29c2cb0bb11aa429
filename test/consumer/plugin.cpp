// SPDX-License-Identifier: MIT
// A plugin: a shared object that links the static libcvms.a into itself, as a
// loadable module or a language binding does. That link needs the library
// compiled position-independent, its thread-local scratch included.
// scripts/check-consumers.sh builds it and loads it with plugin_host.cpp.
#include <cvms/minkowski.hpp>
#include <cvms/predicates.hpp>
#include <cvms/rational.hpp>
#include <cvms/shapes.hpp>
#include <cvms/vec.hpp>

// 0 when the sum and the predicate are right, 1 otherwise, 2 on an exception.
extern "C" __attribute__((visibility("default"))) int cvms_plugin_run() {
  try {
    // Cube + octahedron: a rhombicuboctahedron, V=24 E=48 F=26.
    const cvms::ConvexPolyhedron p =
        cvms::minkowski_sum(cvms::shapes::cube(), cvms::shapes::octahedron()).polyhedron;
    const cvms::Vec3 o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, z{0, 0, cvms::parse_rational("1e-300")};
    const bool ok = p.num_vertices() == 24 && p.num_edges() == 48 && p.num_facets() == 26 &&
                    cvms::orient3d(o, x, y, z) == cvms::Sign::positive;
    return ok ? 0 : 1;
  } catch (...) {
    return 2;
  }
}
