// SPDX-License-Identifier: MIT
// The operands of cvms_proximity_bench, shared by its exact rows
// (proximity_bench.cpp) and its FCL rows (proximity_peer_fcl.cpp): pair
// (0 Cube/Cube, 1..3 Sphere3..5/rotSphere3..5, 4..6 Sphere3..5/Cube) and
// placement of B (0 overlapping, 1 touching, 2 separated). B is moved by
// lambda p, p the point of M = A + (-B) farthest in a fixed direction (a
// boundary point; the origin is inside M because both shapes are centred
// there): lambda = 1/2 overlaps, 1 touches, 3/2 separates.
#pragma once

#include <array>
#include <string>

#include "cvms/proximity.hpp"
#include "cvms/shapes.hpp"

namespace cvms_bench {

inline constexpr int kPairs = 7;
inline constexpr const char* kPlacements[] = {"overlapping", "touching", "separated"};

struct Operands {
  cvms::ConvexPolyhedron a;
  cvms::ConvexPolyhedron b;
  std::string label;
};

inline Operands base_pair(int pair) {
  if (pair == 0) return {cvms::shapes::cube(), cvms::shapes::cube(), "Cube/Cube"};
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
