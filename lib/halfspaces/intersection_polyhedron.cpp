// SPDX-License-Identifier: MIT
// intersection_polyhedron (intersection_polyhedron.hpp has the argument).
// The trusted builder takes the planes as they are; they equal the ones
// parts_with_planes would compute: the outward primitive integer normal of
// a plane is unique, and the offset is its value on the plane.
#include "intersection_polyhedron.hpp"

#include <algorithm>
#include <span>

#include "cvms/error.hpp"
#include "homogeneous_hull.hpp"
#include "polyhedron_builder.hpp"

namespace cvms::detail {
namespace {

std::span<const std::uint32_t> tight_rows(const DualVertices& v, std::uint32_t vertex) {
  return {v.tight.data() + v.tight_offsets[vertex], v.tight_offsets[vertex + 1] - v.tight_offsets[vertex]};
}

bool contains(std::span<const std::uint32_t> rows, std::uint32_t r) {
  return std::find(rows.begin(), rows.end(), r) != rows.end();
}

// A row tight at the first three corners of a facet (given as vertices).
std::uint32_t facet_row(const DualVertices& v, std::span<const std::uint32_t> corners) {
  for (std::uint32_t r : tight_rows(v, corners[0]))
    if (contains(tight_rows(v, corners[1]), r) && contains(tight_rows(v, corners[2]), r)) return r;
  throw Error(ErrorCategory::invalid_argument, "intersection_polyhedron: a facet with no tight row");  // unreachable
}

// The plane a·x == b of row r as an outward primitive integer normal and
// its offset.
void add_plane(const DualVertices& v, std::uint32_t r, FacetPlanes& planes) {
  const HomogeneousPoint& a = v.dual.points[r];
  mpz_class g;
  mpz_gcd(g.get_mpz_t(), a.x.get_mpz_t(), a.y.get_mpz_t());
  mpz_gcd(g.get_mpz_t(), g.get_mpz_t(), a.z.get_mpz_t());
  Vec3 n{Rational(a.x / g), Rational(a.y / g), Rational(a.z / g)};
  Rational offset(v.dual.offsets[r], g);
  offset.canonicalize();
  planes.normal_approx.push_back(ApproxVec3::of(n));
  planes.normals.push_back(std::move(n));
  planes.offsets.push_back(std::move(offset));
}

}  // namespace

ConvexPolyhedron intersection_polyhedron(const DualVertices& v) {
  std::vector<std::uint32_t> vertex_of;
  PolygonSoup soup = homogeneous_hull(
      v.cramer, [&](std::uint32_t i) { return v.vertices[i]; }, vertex_of);
  soup.points.reserve(vertex_of.size());
  for (std::uint32_t i : vertex_of) soup.points.push_back(v.vertices[i]);
  FacetPlanes planes;
  std::vector<std::uint32_t> corners;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    corners.clear();
    for (std::uint32_t c : soup.face(f).first(3)) corners.push_back(vertex_of[c]);
    add_plane(v, facet_row(v, corners), planes);
  }
  std::vector<ApproxVec3> approx;
  approx.reserve(soup.points.size());
  for (const Vec3& p : soup.points) approx.push_back(ApproxVec3::of(p));
  return assemble(output_mesh(std::move(soup)), std::move(approx), std::move(planes));
}

}  // namespace cvms::detail
