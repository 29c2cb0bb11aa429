// SPDX-License-Identifier: MIT
// CHMS, the convex-hull-based Minkowski sum (paper Section 6.2): the exact
// hull of all pairwise vertex sums. Slow but simple, it is the reference
// oracle for the other algorithms.
#include <cstdint>
#include <string>
#include <vector>

#include "cvms/error.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/quickhull.hpp"

namespace cvms {

ConvexPolyhedron chms(const ConvexPolyhedron& a, const ConvexPolyhedron& b) {
  const std::uint64_t count = std::uint64_t{a.num_vertices()} * b.num_vertices();
  // Checked before allocating: the hull indexes points with 32 bits.
  if (count >= 0xffffffffu)
    throw Error(ErrorCategory::limit, "chms: " + std::to_string(a.num_vertices()) + " x " +
                                          std::to_string(b.num_vertices()) +
                                          " pairwise vertex sums exceed the limit of 2^32 - 2 points");
  std::vector<Vec3> sums;
  sums.reserve(count);
  for (VertexId i : a.mesh().vertices())
    for (VertexId j : b.mesh().vertices()) sums.push_back(a.vertex(i) + b.vertex(j));
  return convex_hull(sums);
}

}  // namespace cvms
