// SPDX-License-Identifier: MIT
// Smallest use of an installed cvms: exact decimal arithmetic, one exact
// predicate, and a Minkowski sum checked exactly. Exits 0 when all are right.
#include <cstdio>
#include <cvms/minkowski.hpp>
#include <cvms/predicates.hpp>
#include <cvms/rational.hpp>
#include <cvms/shapes.hpp>
#include <cvms/vec.hpp>

int main() {
  const cvms::Rational sum = cvms::parse_rational("0.1") + cvms::parse_rational("0.2");
  const cvms::Vec3 o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, z{0, 0, cvms::parse_rational("1e-300")};
  // Cube + octahedron: the combinatorics of a rhombicuboctahedron (8 triangles,
  // 6 + 12 squares; vertices the 24 permutations of (+-2, +-1, +-1)).
  const cvms::ConvexPolyhedron p =
      cvms::minkowski_sum(cvms::shapes::cube(), cvms::shapes::octahedron()).polyhedron;
  const bool ok = cvms::to_string(sum) == "0.3" && cvms::orient3d(o, x, y, z) == cvms::Sign::positive &&
                  p.num_vertices() == 24 && p.num_edges() == 48 && p.num_facets() == 26;
  std::printf("cvms test_package: 0.1 + 0.2 = %s, orient3d = %s, cube + octahedron: V=%u E=%u F=%u (%s)\n",
              cvms::to_string(sum).c_str(),
              cvms::orient3d(o, x, y, z) == cvms::Sign::positive ? "positive" : "WRONG", p.num_vertices(),
              p.num_edges(), p.num_facets(), ok ? "ok" : "WRONG");
  return ok ? 0 : 1;
}
