// SPDX-License-Identifier: MIT
// The operands of cvms_proximity_bench, shared by its exact rows
// (proximity_bench.cpp) and its FCL rows (proximity_peer_fcl.cpp): pair
// (0 Cube/Cube, 1..3 Sphere3..5/rotSphere3..5, 4..6 Sphere3..5/Cube,
// 7 Sphere6/rotSphere6, 8 Sphere6/Cube, 9 and 10 the hulls of two clouds of
// 1,000 and 5,000 points with 6-digit decimal coordinates) and
// placement of B (0 overlapping, 1 touching, 2 separated). B is moved by
// lambda p, p the point of M = A + (-B) farthest in a fixed direction (a
// boundary point; the origin is inside M because both shapes are centred
// there): lambda = 1/2 overlaps, 1 touches, 3/2 separates.
#pragma once

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/proximity.hpp"
#include "cvms/shapes.hpp"

namespace cvms_bench {

inline constexpr int kPairs = 11;
/// The pairs before Sphere6 and the clouds (the whole-sum reference is too
/// slow beyond them).
inline constexpr int kSmallPairs = 7;
inline constexpr const char* kPlacements[] = {"overlapping", "touching", "separated"};

struct Operands {
  cvms::ConvexPolyhedron a;
  cvms::ConvexPolyhedron b;
  std::string label;
};

// n points spread over the unit sphere (a Fibonacci lattice turned by
// `turn` radians about z), each coordinate rounded to 6 decimals, and their
// exact hull: every point is a vertex (the rounding, 5e-7, is far below the
// bulge between neighbours, about 1e-3 at n = 5,000).
inline cvms::ConvexPolyhedron decimal_cloud(int n, double turn) {
  std::vector<cvms::Vec3> points;
  const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
  const auto decimal = [](double x) { return cvms::Rational(static_cast<long>(std::lround(x * 1e6)), 1000000L); };
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / n;
    const double r = std::sqrt(1.0 - z * z);
    const double phi = golden * i + turn;
    points.push_back({decimal(r * std::cos(phi)), decimal(r * std::sin(phi)), decimal(z)});
  }
  return cvms::convex_hull(points);
}

inline Operands base_pair(int pair) {
  if (pair == 0) return {cvms::shapes::cube(), cvms::shapes::cube(), "Cube/Cube"};
  if (pair == 7) return {cvms::shapes::geodesic_sphere(6), cvms::shapes::rotated_geodesic_sphere(6), "Sphere6/rotSphere6"};
  if (pair == 8) return {cvms::shapes::geodesic_sphere(6), cvms::shapes::cube(), "Sphere6/Cube"};
  if (pair >= 9) {
    const int n = pair == 9 ? 1000 : 5000;
    return {decimal_cloud(n, 0.0), decimal_cloud(n, 0.3), "Cloud" + std::to_string(n) + "/Cloud" + std::to_string(n)};
  }
  const int k = 3 + (pair - 1) % 3;
  if (pair <= 3)
    return {cvms::shapes::geodesic_sphere(k), cvms::shapes::rotated_geodesic_sphere(k),
            "Sphere" + std::to_string(k) + "/rotSphere" + std::to_string(k)};
  return {cvms::shapes::geodesic_sphere(k), cvms::shapes::cube(), "Sphere" + std::to_string(k) + "/Cube"};
}

// The operands of a row, built once (B moved by lambda p: see the file comment).
inline const Operands& operands(int pair, int placement) {
  static std::array<std::array<Operands, 3>, kPairs> cache;
  static std::array<std::array<bool, 3>, kPairs> built{};
  if (!built[pair][placement]) {
    Operands o = base_pair(pair);
    const cvms::Vec3 d{cvms::Rational(1), cvms::Rational(1, 3), cvms::Rational(1, 5)};
    const cvms::Vec3 p = cvms::support(o.a, d).point - cvms::support(o.b, -d).point;
    const cvms::Rational lambda = cvms::Rational(placement + 1, 2);
    o.b = o.b.translated(lambda * p);
    cache[pair][placement] = std::move(o);
    built[pair][placement] = true;
  }
  return cache[pair][placement];
}

}  // namespace cvms_bench
