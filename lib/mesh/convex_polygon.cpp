// SPDX-License-Identifier: MIT
// All turns must be left or straight on; then the polygon is convex iff its
// corners' edge directions turn around exactly once, i.e. (every turn being
// in (0, pi)) iff their angles, measured counterclockwise from the first
// corner edge, descend exactly once.
#include "convex_polygon.hpp"

#include "angular_order.hpp"
#include "dyadic.hpp"
#include "element_names.hpp"

namespace cvms::detail {

namespace {

// The edge of the polygon between two of its corners.
struct Chord {
  Vec3Ref from, to;
};

}  // namespace

PolygonCheck check_convex_polygon(const std::vector<Vec3Ref>& p, Vec3Ref n) {
  const std::size_t m = p.size();
  PolygonCheck r;
  r.corner.assign(m, 0);
  std::vector<std::size_t> corners;
  for (std::size_t i = 0; i < m; ++i) {
    const Vec3Ref prev = p[(i + m - 1) % m];
    const Vec3Ref next = p[(i + 1) % m];
    const Sign s = sign_triple_in_plane(n, prev, p[i], p[i], next);
    if (s == Sign::negative) return {PolygonFault::right_turn, i, {}};
    if (s == Sign::zero) {
      if (sign_dot_of_differences(prev, p[i], p[i], next) != Sign::positive) return {PolygonFault::reversal, i, {}};
    } else {
      r.corner[i] = 1;
      corners.push_back(i);
    }
  }
  const std::size_t k = corners.size();
  if (k < 3) return {PolygonFault::too_few_corners, 0, {}};
  std::vector<Chord> e;
  e.reserve(k);
  for (std::size_t j = 0; j < k; ++j) e.push_back({p[corners[j]], p[corners[(j + 1) % k]]});
  const Chord& ref = e[0];
  // Angles about n from ref (lib/predicates/angular_order.hpp).
  auto half = [&](const Chord& v) {
    return half_turn(sign_triple_in_plane(n, ref.from, ref.to, v.from, v.to),
                     [&] { return sign_dot_of_differences(ref.from, ref.to, v.from, v.to); });
  };
  // Each chord's half-turn once; ref's own is 0 (along ref), which the
  // predicates could only find exactly (a zero cross product).
  std::vector<int> halves(k, 0);
  for (std::size_t j = 1; j < k; ++j) halves[j] = half(e[j]);
  auto angle_less = [&](std::size_t a, std::size_t b) {
    return compare_angle(halves[a], halves[b], [&] {
             return sign_triple_in_plane(n, e[a].from, e[a].to, e[b].from, e[b].to);
           }) == Sign::negative;
  };
  std::size_t descents = 0;
  for (std::size_t j = 0; j < k; ++j)
    if (angle_less((j + 1) % k, j)) ++descents;
  if (descents != 1) return {PolygonFault::winds_more_than_once, 0, {}};
  return r;
}

std::string describe_fault(const PolygonCheck& c, const std::vector<std::uint32_t>& vertex_ids) {
  switch (c.fault) {
    case PolygonFault::right_turn: return "has a reflex corner at vertex " + str(vertex_ids[c.at]);
    case PolygonFault::reversal: return "turns back on itself at vertex " + str(vertex_ids[c.at]);
    case PolygonFault::too_few_corners: return "has fewer than 3 corners";
    case PolygonFault::winds_more_than_once: return "winds around more than once (self-intersecting)";
    case PolygonFault::none: break;
  }
  return "";
}

// The area vector (twice the vector area) of a polygon, the sum of the
// cross products of its fan from p[0], added in a balanced tree of
// unreduced fractions: the terms' denominators differ, and a running sum
// would grow by each of them in turn (quadratic in the degree).
Vec3 area_vector(std::size_t m, const std::function<const Vec3&(std::size_t)>& point) {
  using Fraction = std::pair<mpz_class, mpz_class>;  // numerator, denominator > 0
  std::vector<Fraction> terms[3];
  for (std::size_t i = 1; i + 1 < m; ++i) {
    const Vec3 t = cross(subtract(point(i), point(0)), subtract(point(i + 1), point(0)));
    for (int c = 0; c < 3; ++c) terms[c].emplace_back(t[c].get_num(), t[c].get_den());
  }
  Vec3 n{0, 0, 0};
  for (int c = 0; c < 3; ++c) {
    std::vector<Fraction>& level = terms[c];
    while (level.size() > 1) {
      std::size_t out = 0;
      for (std::size_t i = 0; i + 1 < level.size(); i += 2, ++out) {
        const auto& [a, b] = level[i];
        const auto& [x, y] = level[i + 1];
        level[out] = {a * y + x * b, b * y};
      }
      if (level.size() % 2 == 1) level[out++] = std::move(level.back());
      level.resize(out);
    }
    if (!level.empty()) {
      n[c] = Rational(level[0].first, level[0].second);
      n[c].canonicalize();
    }
  }
  return n;
}


}  // namespace cvms::detail
