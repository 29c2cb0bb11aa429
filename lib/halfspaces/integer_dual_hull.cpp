// SPDX-License-Identifier: MIT
// bounded_vertices (integer_dual_hull.hpp has the mathematics). The hull
// (homogeneous_hull.hpp) decides as the quickhull on the rational points a/s,
// and a positive dilation of the dual points (homogeneous_dual.hpp) changes
// none of its decisions, so it yields the same facets in the same order as
// the rational dual hull of from_halfspaces.cpp.
#include "integer_dual_hull.hpp"

#include <array>

#include "cvms/error.hpp"
#include "homogeneous_hull.hpp"

namespace cvms::detail {
namespace {

mpz_class dot(const std::array<mpz_class, 3>& u, const HomogeneousPoint& p) { return u[0] * p.x + u[1] * p.y + u[2] * p.z; }

std::array<mpz_class, 3> cross(const HomogeneousPoint& p, const HomogeneousPoint& q) {
  return {p.y * q.z - p.z * q.y, p.z * q.x - p.x * q.z, p.x * q.y - p.y * q.x};
}

// The point where rows i, j, k are tight in homogeneous coordinates, if
// det[a_i; a_j; a_k] > 0.
std::optional<HomogeneousPoint> tight_point(const HomogeneousDual& dual, std::uint32_t i, std::uint32_t j,
                                            std::uint32_t k) {
  const HomogeneousPoint &a = dual.points[i], &b = dual.points[j], &c = dual.points[k];
  const std::array<mpz_class, 3> bc = cross(b, c), ca = cross(c, a), ab = cross(a, b);
  HomogeneousPoint x;
  x.w = dot(bc, a);
  if (sgn(x.w) <= 0) return std::nullopt;
  mpz_class* coordinate[3] = {&x.x, &x.y, &x.z};
  for (std::size_t m = 0; m < 3; ++m)
    *coordinate[m] = dual.offsets[i] * bc[m] + dual.offsets[j] * ca[m] + dual.offsets[k] * ab[m];
  return x;
}

}  // namespace

std::optional<DualVertices> bounded_vertices(const std::vector<LpRow>& rows, const std::vector<Rational>& x0) {
  DualVertices out;
  out.dual = homogeneous_dual(rows, x0);
  const HomogeneousDual& dual = out.dual;
  PolygonSoup soup;
  std::vector<std::uint32_t> row_of;
  try {
    soup = homogeneous_hull(
        dual.points, [&](std::uint32_t i) { return standing_for(dual.points[i]); }, row_of);
  } catch (const Error& e) {
    // Dual points that do not span 3D: the origin is not interior to their
    // hull, so the set is unbounded.
    if (e.category() == ErrorCategory::degenerate) return std::nullopt;
    throw;
  }
  out.vertices.reserve(soup.num_faces());
  out.tight.reserve(soup.face_indices.size());
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const auto corners = soup.face(f);
    std::optional<HomogeneousPoint> x = tight_point(dual, row_of[corners[0]], row_of[corners[1]], row_of[corners[2]]);
    if (!x) return std::nullopt;
    out.vertices.push_back(standing_for(*x));
    for (std::uint32_t c : corners) out.tight.push_back(row_of[c]);
    out.tight_offsets.push_back(static_cast<std::uint32_t>(out.tight.size()));
  }
  return out;
}

}  // namespace cvms::detail
