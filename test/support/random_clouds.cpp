// SPDX-License-Identifier: MIT
// Seeded random operand pairs for the Minkowski-sum tests.
#include "support/random_clouds.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "cvms/error.hpp"
#include "cvms/convex_hull.hpp"

namespace cvms::test {
namespace {

using Rng = std::mt19937_64;

std::int64_t uniform(Rng& rng, std::int64_t lo, std::int64_t hi) {
  return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng);
}

// Mostly small clouds: CHMS (the oracle) on 200 x 200 points is slow.
int pick_size(Rng& rng, int max_points) {
  const auto r = uniform(rng, 0, 99);
  const int hi = r < 80 ? 16 : (r < 96 ? 40 : 200);
  return static_cast<int>(uniform(rng, 4, std::max(4, std::min(hi, max_points))));
}

Rational random_int(Rng& rng, std::int64_t range) { return Rational(uniform(rng, -range, range)); }

Vec3 random_int_point(Rng& rng, std::int64_t range) {
  return {random_int(rng, range), random_int(rng, range), random_int(rng, range)};
}

enum class Kind { integer, decimal, dbl, sphere, box_faces, lattice_planes, count };

const char* kind_name(Kind k) {
  switch (k) {
    case Kind::integer:
      return "integer";
    case Kind::decimal:
      return "decimal";
    case Kind::dbl:
      return "double";
    case Kind::sphere:
      return "double-sphere";
    case Kind::box_faces:
      return "box-faces";
    case Kind::lattice_planes:
      return "lattice-planes";
    default:
      return "?";
  }
}

std::vector<Vec3> random_cloud(Rng& rng, Kind kind, int n) {
  std::vector<Vec3> pts;
  switch (kind) {
    case Kind::integer: {
      static constexpr std::int64_t ranges[] = {1, 2, 3, 5, 10, 1000, 1000000};
      const std::int64_t range = ranges[uniform(rng, 0, 6)];
      for (int i = 0; i < n; ++i) pts.push_back(random_int_point(rng, range));
      break;
    }
    case Kind::decimal: {
      // Values like 12.345: exact decimal fractions with 1..3 digits.
      const std::int64_t digits = uniform(rng, 1, 3);
      Rational scale = 1;
      for (std::int64_t d = 0; d < digits; ++d) scale *= 10;
      const std::int64_t range = uniform(rng, 0, 1) ? 20 : 20000;
      for (int i = 0; i < n; ++i) {
        Vec3 p = random_int_point(rng, range);
        pts.push_back({p.x / scale, p.y / scale, p.z / scale});
      }
      break;
    }
    case Kind::dbl: {
      std::uniform_real_distribution<double> u(-1.0, 1.0);
      for (int i = 0; i < n; ++i)
        pts.push_back(
            {rational_from_double(u(rng)), rational_from_double(u(rng)), rational_from_double(u(rng))});
      break;
    }
    case Kind::sphere: {
      std::normal_distribution<double> g;
      for (int i = 0; i < n; ++i) {
        const double x = g(rng), y = g(rng), z = g(rng);
        const double r = std::sqrt(x * x + y * y + z * z) + 1e-300;
        pts.push_back(
            {rational_from_double(x / r), rational_from_double(y / r), rational_from_double(z / r)});
      }
      break;
    }
    case Kind::box_faces: {
      // Every point on a face of [-r, r]^3: many coplanar points, and many on
      // the box's edges.
      const std::int64_t range = uniform(rng, 1, 6);
      for (int i = 0; i < n; ++i) {
        Vec3 p = random_int_point(rng, range);
        p[static_cast<int>(uniform(rng, 0, 2))] = Rational(uniform(rng, 0, 1) ? range : -range);
        pts.push_back(p);
      }
      break;
    }
    case Kind::lattice_planes: {
      // Points on a few random lattice planes o + s u + t v.
      const int planes = static_cast<int>(uniform(rng, 2, 4));
      std::vector<std::array<Vec3, 3>> frames;
      for (int k = 0; k < planes; ++k)
        frames.push_back({random_int_point(rng, 5), random_int_point(rng, 2), random_int_point(rng, 2)});
      for (int i = 0; i < n; ++i) {
        const auto& [o, u, v] = frames[static_cast<std::size_t>(uniform(rng, 0, planes - 1))];
        pts.push_back(o + Rational(uniform(rng, -3, 3)) * u + Rational(uniform(rng, -3, 3)) * v);
      }
      break;
    }
    default:
      break;
  }
  return pts;
}

// A second cloud that shares edge and facet directions with the first.
std::vector<Vec3> derived_cloud(Rng& rng, const std::vector<Vec3>& base, std::string& how) {
  std::vector<Vec3> pts;
  switch (uniform(rng, 0, 3)) {
    case 0: {  // homothetic copy: every facet and edge direction shared
      static const Rational scales[] = {Rational(1), Rational(2), Rational(1, 3), Rational(5, 2)};
      const Rational& s = scales[uniform(rng, 0, 3)];
      const Vec3 t = random_int_point(rng, 7);
      for (const Vec3& p : base) pts.push_back(s * p + t);
      how = "homothetic copy (scale " + to_string(s) + ")";
      break;
    }
    case 1:  // reflection: antiparallel facets, parallel edges
      for (const Vec3& p : base) pts.push_back(-p);
      how = "reflected copy";
      break;
    case 2: {  // subset: some facets and edges shared
      pts = base;
      std::shuffle(pts.begin(), pts.end(), rng);
      pts.resize(static_cast<std::size_t>(uniform(rng, 4, static_cast<std::int64_t>(pts.size()))));
      how = "subset";
      break;
    }
    default: {  // coordinates permuted cyclically, plus a few extra points
      for (const Vec3& p : base) pts.push_back({p.y, p.z, p.x});
      for (int i = 0; i < 3; ++i) pts.push_back(random_int_point(rng, 3));
      how = "permuted copy plus 3 points";
      break;
    }
  }
  return pts;
}

// The hull of a fresh random cloud (re-drawn while it is flat).
ConvexPolyhedron random_hull_of_kind(Rng& rng, int max_points, std::string& how, std::vector<Vec3>* cloud) {
  for (;;) {
    const auto kind = static_cast<Kind>(uniform(rng, 0, static_cast<std::int64_t>(Kind::count) - 1));
    const int n = pick_size(rng, max_points);
    std::vector<Vec3> pts = random_cloud(rng, kind, n);
    try {
      ConvexPolyhedron p = convex_hull(pts);
      how = std::string(kind_name(kind)) + " n=" + std::to_string(n);
      if (cloud) *cloud = std::move(pts);
      return p;
    } catch (const Error&) {
      // flat or too few distinct points: draw again
    }
  }
}

}  // namespace

RandomPair random_pair(std::uint64_t seed, int max_points) {
  Rng rng(seed);
  RandomPair out;
  std::string how_a;
  std::vector<Vec3> cloud_a;
  out.a = random_hull_of_kind(rng, max_points, how_a, &cloud_a);
  std::string how_b;
  bool made = false;
  if (uniform(rng, 0, 3) == 0) {
    std::vector<Vec3> pts = derived_cloud(rng, cloud_a, how_b);
    try {
      out.b = convex_hull(pts);
      made = true;
    } catch (const Error&) {
    }
  }
  if (!made) {
    // Keep CHMS cheap: a big first operand gets a small second one.
    const int limit = cloud_a.size() > 40 ? 16 : max_points;
    out.b = random_hull_of_kind(rng, limit, how_b, nullptr);
  }
  out.description = "A: " + how_a + "; B: " + how_b;
  return out;
}

}  // namespace cvms::test
