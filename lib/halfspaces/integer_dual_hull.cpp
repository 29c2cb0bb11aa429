// SPDX-License-Identifier: MIT
// bounded_vertices (integer_dual_hull.hpp has the mathematics). The hull
// (homogeneous_hull.hpp) decides as the quickhull on the rational points a/s,
// and a positive dilation of the dual points (homogeneous_dual.hpp) changes
// none of its decisions, so it yields the same facets in the same order as
// the rational dual hull of from_halfspaces.cpp. The facets' vertices are
// Cramer solutions (integer_dual_hull.hpp), computed from the rows in
// fixed-width integers when every entry has at most 255 bits (the proof of
// the identity at fixed_tight_point, of the bounds in fixed_det4.hpp), in
// mpz otherwise.
#include "integer_dual_hull.hpp"

#include <algorithm>
#include <array>

#include "cvms/error.hpp"
#include "fixed_det4.hpp"
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

// x as an mpz. \pre |x| < 2^(64 L − 1) (the FixedInt invariant).
template <int L>
void to_mpz(FixedInt<L> x, mpz_class& out) {
  const bool negative = x.negative();
  if (negative) x.negate();
  mpz_import(out.get_mpz_t(), L, -1, sizeof(std::uint64_t), 0, 0, x.limb.data());
  if (negative) mpz_neg(out.get_mpz_t(), out.get_mpz_t());
}

// tight_point in fixed-width integers, for rows (a, b) of at most 64E − 1
// bits per entry. The last-row cofactors C of the rows r_i = (a_i, b_i),
// r_j, r_k (fixed_det4.hpp, with the overflow proof) satisfy
// sum_m d_m C_m = det[r_i; r_j; r_k; d] for every d: so C_3 (d = (0, 0, 0,
// 1)) is det[a_i; a_j; a_k], and r_i·C = 0 (a repeated row), i.e.
// a_i·(−C_xyz / C_3) = b_i, and likewise for j and k: the tight point is
// −C_xyz / C_3, the same integers as Cramer's numerators above.
template <int E>
std::optional<HomogeneousPoint> fixed_tight_point(const std::vector<FixedRow<E>>& rows, std::uint32_t i, std::uint32_t j,
                                                  std::uint32_t k) {
  Cofactors<E> c = last_row_cofactors<E>(rows[i], rows[j], rows[k]);
  if (c[3].sign() <= 0) return std::nullopt;
  HomogeneousPoint x;
  to_mpz(c[3], x.w);
  mpz_class* coordinate[3] = {&x.x, &x.y, &x.z};
  for (std::size_t m = 0; m < 3; ++m) {
    c[m].negate();
    to_mpz(c[m], *coordinate[m]);
  }
  return x;
}

template <int E>
std::vector<FixedRow<E>> fixed_rows(const HomogeneousDual& dual) {
  std::vector<FixedRow<E>> rows;
  rows.reserve(dual.points.size());
  for (std::size_t r = 0; r < dual.points.size(); ++r) {
    const HomogeneousPoint& a = dual.points[r];
    rows.push_back(fixed_row<E>({a.x.get_mpz_t(), a.y.get_mpz_t(), a.z.get_mpz_t(), dual.offsets[r].get_mpz_t()}));
  }
  return rows;
}

// The widest entry of the rows (a_i, b_i), in signed limbs.
int row_width(const HomogeneousDual& dual) {
  int limbs = 1;
  for (std::size_t r = 0; r < dual.points.size(); ++r) {
    const HomogeneousPoint& a = dual.points[r];
    for (const mpz_class* v : {&a.x, &a.y, &a.z, &dual.offsets[r]}) limbs = std::max(limbs, signed_limbs(v->get_mpz_t()));
  }
  return limbs;
}

// The vertices of the dual hull's facets (soup) in the order of the
// facets, with their tight rows; false if one is not bounded. `tight`
// gives the tight point of three rows (tight_point or fixed_tight_point).
template <class Tight>
bool facet_vertices(const PolygonSoup& soup, const std::vector<std::uint32_t>& row_of, const Tight& tight,
                    DualVertices& out) {
  out.vertices.reserve(soup.num_faces());
  out.tight.reserve(soup.face_indices.size());
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const auto corners = soup.face(f);
    std::optional<HomogeneousPoint> x = tight(row_of[corners[0]], row_of[corners[1]], row_of[corners[2]]);
    if (!x) return false;
    out.vertices.push_back(standing_for(*x));
    for (std::uint32_t c : corners) out.tight.push_back(row_of[c]);
    out.tight_offsets.push_back(static_cast<std::uint32_t>(out.tight.size()));
  }
  return true;
}

template <int E>
bool fixed_facet_vertices(const PolygonSoup& soup, const std::vector<std::uint32_t>& row_of, DualVertices& out) {
  const std::vector<FixedRow<E>> rows = fixed_rows<E>(out.dual);
  return facet_vertices(
      soup, row_of, [&](std::uint32_t i, std::uint32_t j, std::uint32_t k) { return fixed_tight_point<E>(rows, i, j, k); },
      out);
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
  bool bounded = false;
  switch (row_width(dual)) {
    case 1: bounded = fixed_facet_vertices<1>(soup, row_of, out); break;
    case 2: bounded = fixed_facet_vertices<2>(soup, row_of, out); break;
    case 3: bounded = fixed_facet_vertices<3>(soup, row_of, out); break;
    case 4: bounded = fixed_facet_vertices<4>(soup, row_of, out); break;
    default:
      bounded = facet_vertices(
          soup, row_of, [&](std::uint32_t i, std::uint32_t j, std::uint32_t k) { return tight_point(dual, i, j, k); },
          out);
  }
  if (!bounded) return std::nullopt;
  return out;
}

}  // namespace cvms::detail
