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

// x = (y.x, y.y, y.z) / y.w in lowest terms, w > 0, made in place from y's
// integers (a moved rational allocates again). A pole's integers often share
// a large factor (the vertices of Sphere5's facet planes are doubles, and
// their poles' 450-bit coordinates share all but a few bits): then the
// factor g that reduces the first coordinate divides the others as well,
// and reducing them over w / g costs a division each instead of a gcd of
// two 450-bit numbers (9 → 4 M instructions on Sphere5's rows). Either way
// (y/g)/(w/g) = y/w, and canonicalize reduces either form to the one
// canonical rational.
void write_over_common_denominator(HomogeneousPoint& y, Vec3& x) {
  mpz_class* numerator[3] = {&y.x, &y.y, &y.z};
  mpz_ptr first_numerator = mpq_numref(x[0].get_mpq_t()), first_denominator = mpq_denref(x[0].get_mpq_t());
  mpz_swap(first_numerator, y.x.get_mpz_t());
  const mpz_ptr g = first_denominator;  // gcd(x, w), until w / g takes its place
  mpz_gcd(g, first_numerator, y.w.get_mpz_t());
  mpz_divexact(first_numerator, first_numerator, g);
  bool over_reduced[3] = {true, false, false};
  for (int m = 1; m < 3; ++m) {
    mpz_ptr p = mpq_numref(x[m].get_mpq_t());
    mpz_swap(p, numerator[m]->get_mpz_t());
    over_reduced[m] = mpz_divisible_p(p, g) != 0;
    if (over_reduced[m]) mpz_divexact(p, p, g);
  }
  mpz_divexact(y.w.get_mpz_t(), y.w.get_mpz_t(), g);
  mpz_swap(first_denominator, y.w.get_mpz_t());  // x[0] = (x / g) / (w / g); y.w = g
  const mpz_srcptr reduced_w = first_denominator, factor = y.w.get_mpz_t();
  for (int m = 1; m < 3; ++m) {
    if (over_reduced[m])
      mpz_set(mpq_denref(x[m].get_mpq_t()), reduced_w);
    else
      mpz_mul(mpq_denref(x[m].get_mpq_t()), reduced_w, factor);  // w
    x[m].canonicalize();
  }
}

// The vertex (X + y) / D of a facet with pole y, w > 0, written into x
// (made in place from y's integers: a moved rational allocates again).
void vertex_from_pole(const HomogeneousPoint& origin, HomogeneousPoint& y, Vec3& x) {
  const bool at_origin = sgn(origin.x) == 0 && sgn(origin.y) == 0 && sgn(origin.z) == 0 && origin.w == 1;
  if (!at_origin) {
    mpz_addmul(y.x.get_mpz_t(), origin.x.get_mpz_t(), y.w.get_mpz_t());
    mpz_addmul(y.y.get_mpz_t(), origin.y.get_mpz_t(), y.w.get_mpz_t());
    mpz_addmul(y.z.get_mpz_t(), origin.z.get_mpz_t(), y.w.get_mpz_t());
    y.w *= origin.w;
  }
  write_over_common_denominator(y, x);
}

}  // namespace

std::optional<DualVertices> bounded_vertices(const std::vector<LpRow>& rows, const std::vector<Rational>& x0) {
  return bounded_vertices(homogeneous_dual(rows, x0));
}

std::optional<DualVertices> bounded_vertices(HomogeneousDual homogeneous) {
  DualVertices out;
  out.dual = std::move(homogeneous);
  const HomogeneousDual& dual = out.dual;
  PolygonSoup soup;
  std::vector<std::uint32_t> row_of;
  std::vector<HomogeneousPoint> poles;
  try {
    soup = homogeneous_hull(
        dual.points, [&](std::uint32_t i) { return standing_for(dual.points[i]); }, row_of, &poles);
  } catch (const Error& e) {
    // Dual points that do not span 3D: the origin is not interior to their
    // hull, so the set is unbounded.
    if (e.category() == ErrorCategory::degenerate) return std::nullopt;
    throw;
  }
  out.vertices.reserve(soup.num_faces());
  out.tight.reserve(soup.face_indices.size());
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    // A facet whose plane does not have the origin strictly below it: the
    // set is unbounded (integer_dual_hull.hpp).
    if (sgn(poles[f].w) <= 0) return std::nullopt;
    vertex_from_pole(dual.origin, poles[f], out.vertices.emplace_back());
    for (std::uint32_t c : soup.face(f)) out.tight.push_back(row_of[c]);
    out.tight_offsets.push_back(static_cast<std::uint32_t>(out.tight.size()));
  }
  return out;
}

}  // namespace cvms::detail
