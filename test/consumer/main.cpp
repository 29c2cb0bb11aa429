// SPDX-License-Identifier: MIT
// A program outside the cvms tree: computes with the installed library and
// checks the results exactly. Built by CMake (find_package, from an install
// prefix and from a build tree), by pkg-config on the command line, and fully
// static (scripts/check-consumers.sh). Exits 0 only when every check holds.
#include <cstdio>
#include <cvms/convex_polyhedron.hpp>
#include <cvms/error.hpp>
#include <cvms/io.hpp>
#include <cvms/minkowski.hpp>
#include <cvms/polygon_soup.hpp>
#include <cvms/predicates.hpp>
#include <cvms/rational.hpp>
#include <cvms/shapes.hpp>
#include <cvms/vec.hpp>
#include <sstream>
#include <string>

namespace {

int failures = 0;

void check(bool ok, const char* what) {
  if (!ok) {
    std::printf("consumer: FAILED: %s\n", what);
    ++failures;
  }
}

}  // namespace

int main() {
  using cvms::Rational;
  using cvms::Sign;
  using cvms::Vec3;

  // Exact decimal parsing and printing (library code in rational.cpp).
  const Vec3 a{cvms::parse_rational("0.1"), 0, 0};
  const Vec3 b{cvms::parse_rational("0.2"), 0, 0};
  check((a + b).x == Rational(3, 10), "0.1 + 0.2 == 3/10");
  check(cvms::to_string((a + b).x) == "0.3", "to_string(0.1 + 0.2) == \"0.3\"");
  check(cvms::to_string(Rational(1, 3)) == "1/3", "to_string(1/3) == \"1/3\"");

  // Exact predicates (predicates.cpp): orientation of a point on, above and
  // (seen the other way round) below the plane z = 0.
  const Vec3 p{0, 0, 0};
  const Vec3 q{cvms::parse_rational("0.1"), 0, 0};
  const Vec3 r{0, cvms::parse_rational("0.3"), 0};
  const Vec3 on{cvms::parse_rational("0.7"), cvms::parse_rational("0.9"), 0};
  const Vec3 above{0, 0, cvms::parse_rational("1e-300")};
  check(cvms::orient3d(p, q, r, on) == Sign::zero, "orient3d coplanar == zero");
  check(cvms::orient3d(p, q, r, above) == Sign::positive, "orient3d above == positive");
  check(cvms::orient3d(p, r, q, above) == Sign::negative, "orient3d swapped == negative");

  // gmpxx itself through the public headers (links libgmpxx and libgmp).
  const Rational big = Rational(mpz_class("123456789012345678901234567890"), 7);
  check(big * 7 == Rational(mpz_class("123456789012345678901234567890")), "gmpxx big rational");

  // A real Minkowski sum: the cube [-1,1]^3 (shapes.cpp) plus the corner
  // tetrahedron conv{0, e_x, e_y, e_z} built by hand. By hand: the sum is
  // [-1,2]^3 cut by x+y <= 3, y+z <= 3, x+z <= 3 and x+y+z <= 4, so
  // 6 + 3 + 1 facets, 13 vertices, 21 edges.
  try {
    cvms::PolygonSoup soup;
    soup.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    soup.add_face({0, 2, 1});
    soup.add_face({0, 1, 3});
    soup.add_face({0, 3, 2});
    soup.add_face({1, 2, 3});
    const auto tetrahedron = cvms::ConvexPolyhedron::from_soup(soup);
    const auto result = cvms::minkowski_sum(cvms::shapes::cube(), tetrahedron);
    const cvms::ConvexPolyhedron& sum = result.polyhedron;
    check(sum.num_vertices() == 13 && sum.num_edges() == 21 && sum.num_facets() == 10,
          "cube + tetrahedron: V=13 E=21 F=10");
    check(result.stats.translated_facets + result.stats.corner_facets + result.stats.edge_facets == 10,
          "cube + tetrahedron: translated + corner + edge facets == F");
    check(sum.is_convex(), "cube + tetrahedron is convex");
    int cut_corner = 0;
    for (cvms::FaceId f : sum.mesh().faces())
      if (sum.normal(f) == Vec3{1, 1, 1} && sum.plane_offset(f) == 4) ++cut_corner;
    check(cut_corner == 1, "cube + tetrahedron has the facet x+y+z = 4");

    // The exact OFF writer and reader (io_off.cpp) round-trip the sum.
    std::stringstream off;
    cvms::write_off(off, sum.to_soup());
    const auto back = cvms::ConvexPolyhedron::from_soup(cvms::read_off(off, "<memory>"));
    check(back.num_vertices() == 13 && back.num_facets() == 10 &&
              back.vertex(cvms::VertexId(0)) == sum.vertex(cvms::VertexId(0)),
          "OFF round trip of the sum");

    // Errors carry a category: an open surface is a topology error.
    cvms::PolygonSoup open = soup;
    open.face_offsets.pop_back();
    open.face_indices.resize(open.face_offsets.back());
    bool topology = false;
    try {
      (void)cvms::ConvexPolyhedron::from_soup(open);
    } catch (const cvms::Error& e) {
      topology = e.category() == cvms::ErrorCategory::topology;
    }
    check(topology, "an open surface throws Error(topology)");
  } catch (const cvms::Error& e) {
    std::printf("consumer: unexpected cvms::Error: %s\n", e.what());
    ++failures;
  }

  std::printf("consumer: %s (%d failed)\n", failures == 0 ? "ok" : "FAILED", failures);
  return failures == 0 ? 0 : 1;
}
