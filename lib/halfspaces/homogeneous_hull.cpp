// SPDX-License-Identifier: MIT
// homogeneous_hull (homogeneous_hull.hpp). The soup is the one hull_soup
// gives on the rational points: every decision of the quickhull is the exact
// sign of a predicate, whichever stage answers it.
#include "homogeneous_hull.hpp"

#include <array>
#include <cmath>
#include <limits>

#include "approx.hpp"
#include "error_bounds.hpp"
#include "hull_soup.hpp"

namespace cvms::detail {
namespace {

// The double of n/d (d > 0) with a bound on its error: mpq_get_d truncates
// the value toward zero whatever its representation, so the fraction is
// converted unreduced (no gcd) and truncation_error bounds the result
// (error_bounds.hpp, "Approx::of").
Approx quotient(const mpz_class& n, const mpz_class& d, mpq_class& scratch) {
  mpz_set(mpq_numref(scratch.get_mpq_t()), n.get_mpz_t());
  mpz_set(mpq_denref(scratch.get_mpq_t()), d.get_mpz_t());
  const double v = mpq_get_d(scratch.get_mpq_t());
  if (!std::isfinite(v)) return {v, std::numeric_limits<double>::infinity()};
  return {v, filtered::truncation_error(v)};
}

struct Approximation {
  std::vector<std::array<double, 3>> coords;
  double max_error = 0;
};

Approximation approximate(const std::vector<HomogeneousPoint>& points) {
  Approximation out;
  out.coords.reserve(points.size());
  mpq_class scratch;
  for (const HomogeneousPoint& p : points) {
    const Approx c[3] = {quotient(p.x, p.w, scratch), quotient(p.y, p.w, scratch), quotient(p.z, p.w, scratch)};
    out.coords.push_back({c[0].value, c[1].value, c[2].value});
    for (const Approx& a : c) out.max_error = a.error <= out.max_error ? out.max_error : a.error;
  }
  return out;
}

}  // namespace

Vec3 standing_for(const HomogeneousPoint& p) {
  Vec3 q{Rational(p.x, p.w), Rational(p.y, p.w), Rational(p.z, p.w)};
  for (int m = 0; m < 3; ++m) q[m].canonicalize();
  return q;
}

PolygonSoup homogeneous_hull(const std::vector<HomogeneousPoint>& points, const std::function<Vec3(std::uint32_t)>& exact,
                             std::vector<std::uint32_t>& source_index) {
  const Approximation approx = approximate(points);
  const ExactOrient orient = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    return homogeneous_orient3d(points[a], points[b], points[c], points[d]);
  };
  return hull_soup(ApproximatePoints{approx.coords, approx.max_error, exact}, orient, source_index);
}

}  // namespace cvms::detail
