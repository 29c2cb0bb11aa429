// SPDX-License-Identifier: MIT
// bounded_vertices (integer_dual_hull.hpp has the mathematics). The hull
// (homogeneous_hull.hpp) decides as the quickhull on the rational points a/s,
// and a positive dilation of the dual points (homogeneous_dual.hpp) changes
// none of its decisions, so it yields the same facets in the same order as
// the rational dual hull of from_halfspaces.cpp. Each facet's vertex comes
// from the pole y of its plane, which the hull gives with the facet (from
// the integer cofactors its exact predicates cached for that plane when the
// entries fit the fixed widths, by Cramer's rule in mpz otherwise): a·y
// == s = D b − a·X at every dual point on the plane, so a·(X + y) == D b
// there and the vertex is x = (X + y) / D = (X w + y_xyz) / (D w) for
// y = y_xyz / w.
#include "integer_dual_hull.hpp"

#include <utility>

#include "cvms/error.hpp"
#include "homogeneous_hull.hpp"

namespace cvms::detail {
namespace {

// The integers reused from vertex to vertex (their limbs, that is).
struct VertexScratch {
  HomogeneousPoint shifted;
  mpz_class g, reduced_w;
  Rational coordinate;
};

// x = (y.x, y.y, y.z) / y.w in lowest terms, w > 0, the values' limbs in
// arena. A pole's integers often share a large factor (the vertices of
// Sphere5's facet planes are doubles, and their poles' 450-bit coordinates
// share all but a few bits): then the factor g that reduces the first
// coordinate divides the others as well, and reducing them over w / g costs
// a division each instead of a gcd of two 450-bit numbers (9 → 4 M
// instructions on Sphere5's rows). Either way (y/g)/(w/g) = y/w, and
// canonicalize reduces either form to the one canonical rational.
void write_over_common_denominator(const HomogeneousPoint& y, Vec3& x, VertexScratch& s, LimbArena& arena) {
  const mpz_srcptr numerator[3] = {y.x.get_mpz_t(), y.y.get_mpz_t(), y.z.get_mpz_t()};
  const mpz_ptr g = s.g.get_mpz_t(), reduced_w = s.reduced_w.get_mpz_t();
  const mpz_ptr num = mpq_numref(s.coordinate.get_mpq_t()), den = mpq_denref(s.coordinate.get_mpq_t());
  mpz_gcd(g, numerator[0], y.w.get_mpz_t());
  mpz_divexact(reduced_w, y.w.get_mpz_t(), g);
  mpz_divexact(num, numerator[0], g);
  arena.store(x[0], num, reduced_w);  // divided by their gcd: lowest terms
  for (int m = 1; m < 3; ++m) {
    if (mpz_divisible_p(numerator[m], g) != 0) {
      mpz_divexact(num, numerator[m], g);
      mpz_set(den, reduced_w);
    } else {
      mpz_set(num, numerator[m]);
      mpz_set(den, y.w.get_mpz_t());
    }
    mpq_canonicalize(s.coordinate.get_mpq_t());
    arena.store(x[m], num, den);
  }
}

// The vertex (X + y) / D of a facet with pole y, w > 0, written into x (y
// is a view of an arena's limbs, never written: limb_arena.hpp).
void vertex_from_pole(const HomogeneousPoint& origin, const HomogeneousPoint& y, Vec3& x, VertexScratch& s,
                      LimbArena& arena) {
  const bool at_origin = sgn(origin.x) == 0 && sgn(origin.y) == 0 && sgn(origin.z) == 0 && origin.w == 1;
  if (at_origin) {
    write_over_common_denominator(y, x, s, arena);
    return;
  }
  HomogeneousPoint& shifted = s.shifted;
  const mpz_class* from[3] = {&y.x, &y.y, &y.z};
  const mpz_class* origin_coordinate[3] = {&origin.x, &origin.y, &origin.z};
  mpz_class* to[3] = {&shifted.x, &shifted.y, &shifted.z};
  for (int m = 0; m < 3; ++m) {
    mpz_set(to[m]->get_mpz_t(), from[m]->get_mpz_t());
    mpz_addmul(to[m]->get_mpz_t(), origin_coordinate[m]->get_mpz_t(), y.w.get_mpz_t());
  }
  mpz_mul(shifted.w.get_mpz_t(), y.w.get_mpz_t(), origin.w.get_mpz_t());
  write_over_common_denominator(shifted, x, s, arena);
}

}  // namespace

std::optional<DualVertices> bounded_vertices(const std::vector<LpRow>& rows,
                                             const std::vector<Rational>& x0, ProgressReporter* progress) {
  return bounded_vertices(homogeneous_dual(rows, x0), progress);
}

std::optional<DualVertices> bounded_vertices(HomogeneousDual homogeneous, ProgressReporter* progress) {
  DualVertices out;
  out.dual = std::move(homogeneous);
  const HomogeneousDual& dual = out.dual;
  PolygonSoup soup;
  std::vector<std::uint32_t> row_of;
  FacePoles poles;
  try {
    soup = homogeneous_hull(
        dual.points, [&](std::uint32_t i) { return standing_for(dual.points[i]); }, row_of, &poles, progress);
  } catch (const Error& e) {
    // Dual points that do not span 3D: the origin is not interior to their
    // hull, so the set is unbounded.
    if (e.category() == ErrorCategory::degenerate) return std::nullopt;
    throw;
  }
  out.vertices.reserve(soup.num_faces());
  out.tight.reserve(soup.face_indices.size());
  VertexScratch scratch;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    // A facet whose plane does not have the origin strictly below it: the
    // set is unbounded (integer_dual_hull.hpp).
    if (sgn(poles.poles[f].w) <= 0) return std::nullopt;
    vertex_from_pole(dual.origin, poles.poles[f], out.vertices.emplace_back(), scratch, out.limbs);
    for (std::uint32_t c : soup.face(f)) out.tight.push_back(row_of[c]);
    out.tight_offsets.push_back(static_cast<std::uint32_t>(out.tight.size()));
  }
  return out;
}

}  // namespace cvms::detail
