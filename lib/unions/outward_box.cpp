// SPDX-License-Identifier: MIT
// Boxes rounded outward (the argument is in outward_box.hpp).
#include "outward_box.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

namespace cvms::unions {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

// The double below a correctly rounded result, clamped at zero: a lower
// bound of the non-negative exact value it was rounded from.
double below_non_negative(double rounded) { return std::max(0.0, std::nextafter(rounded, -infinity)); }

Vec3 axis(int i, long s) {
  Vec3 u{0, 0, 0};
  u[i] = s;
  return u;
}

// Each bound from the exact maximum and minimum of coordinate i.
void set_axis(OutwardBox& box, int i, const Rational& min, const Rational& max) {
  box.lo[static_cast<std::size_t>(i)] = round_down(min);
  box.hi[static_cast<std::size_t>(i)] = round_up(max);
}

}  // namespace

// mpq_get_d truncates towards zero, so it is within one step of q; the
// exact comparisons then move it to the right side.
double round_down(const Rational& q) {
  if (q > DBL_MAX) return DBL_MAX;
  if (q < -DBL_MAX) return -infinity;
  double d = q.get_d();
  while (Rational(d) > q) d = std::nextafter(d, -infinity);
  return d;
}

double round_up(const Rational& q) {
  if (q < -DBL_MAX) return -DBL_MAX;
  if (q > DBL_MAX) return infinity;
  double d = q.get_d();
  while (Rational(d) < q) d = std::nextafter(d, infinity);
  return d;
}

OutwardBox point_box(const Vec3& p) {
  OutwardBox box;
  for (int i = 0; i < 3; ++i) set_axis(box, i, p[i], p[i]);
  return box;
}

OutwardBox polyhedron_box(const ConvexPolyhedron& p) {
  OutwardBox box;
  for (int i = 0; i < 3; ++i) {
    set_axis(box, i, -support(p, axis(i, -1)).value, support(p, axis(i, 1)).value);
  }
  return box;
}

// Coordinate i of L x + t is dot(row_i(L), x) + t_i: its extremes over P are
// the supports of P in the directions +-row_i(L), shifted by t_i.
OutwardBox placed_box(const PlacedPolyhedron& p) {
  OutwardBox box;
  const Mat3& linear = p.linear();
  for (int i = 0; i < 3; ++i) {
    const auto row = static_cast<std::size_t>(i);
    const Vec3 direction{linear.m[row][0], linear.m[row][1], linear.m[row][2]};
    const Rational& shift = p.translation()[i];
    if (sgn(direction.x) == 0 && sgn(direction.y) == 0 && sgn(direction.z) == 0) {
      set_axis(box, i, shift, shift);
      continue;
    }
    set_axis(box, i, shift - support(p.polyhedron(), -direction).value,
             shift + support(p.polyhedron(), direction).value);
  }
  return box;
}

OutwardBox set_box(const ConvexSet& s) {
  OutwardBox box;
  for (int i = 0; i < 3; ++i) set_axis(box, i, -support(s, axis(i, -1)).value, support(s, axis(i, 1)).value);
  return box;
}

OutwardBox merged(const OutwardBox& a, const OutwardBox& b) {
  OutwardBox box;
  for (std::size_t i = 0; i < 3; ++i) {
    box.lo[i] = std::min(a.lo[i], b.lo[i]);
    box.hi[i] = std::max(a.hi[i], b.hi[i]);
  }
  return box;
}

bool overlaps(const OutwardBox& a, const OutwardBox& b) {
  for (std::size_t i = 0; i < 3; ++i) {
    if (a.hi[i] < b.lo[i] || b.hi[i] < a.lo[i]) return false;
  }
  return true;
}

double lower_squared_distance(const OutwardBox& a, const OutwardBox& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < 3; ++i) {
    const double gap = std::max(below_non_negative(b.lo[i] - a.hi[i]), below_non_negative(a.lo[i] - b.hi[i]));
    if (gap == 0.0) continue;
    sum = below_non_negative(sum + below_non_negative(gap * gap));
  }
  return sum;
}

}  // namespace cvms::unions
