// SPDX-License-Identifier: MIT
// Brute-force answers for unions of convex pieces (union_oracle.hpp).
#include "support/union_oracle.hpp"

#include <algorithm>

#include "cvms/convex_hull.hpp"
#include "cvms/error.hpp"
#include "cvms/proximity.hpp"

namespace cvms::test {
namespace {

bool piece_contains(const ConvexPolyhedron& piece, const Vec3& p) {
  for (FaceId f : piece.mesh().faces()) {
    if (dot(piece.normal(f), p) > piece.plane_offset(f)) return false;
  }
  return true;
}

std::int64_t uniform(std::mt19937_64& rng, std::int64_t lo, std::int64_t hi) {
  return std::uniform_int_distribution<std::int64_t>(lo, hi)(rng);
}

}  // namespace

bool union_contains_brute_force(const ConvexUnion& u, const Vec3& p) {
  return std::ranges::any_of(u.pieces(),
                             [&](const ConvexPolyhedron& piece) { return piece_contains(piece, p); });
}

BruteNearest nearest_brute_force(const ConvexUnion& u, const ConvexUnion& other) {
  BruteNearest best;
  bool found = false;
  for (std::size_t i = 0; i < u.size(); ++i) {
    for (std::size_t j = 0; j < other.size(); ++j) {
      Rational d = squared_distance(u.pieces()[i], other.pieces()[j]).squared_distance;
      if (!found || d < best.squared_distance) best = {d, i, j};
      found = true;
    }
  }
  return best;
}

bool intersects_brute_force(const ConvexUnion& u, const ConvexUnion& other) {
  for (const ConvexPolyhedron& a : u.pieces()) {
    for (const ConvexPolyhedron& b : other.pieces()) {
      if (intersects(a, b)) return true;
    }
  }
  return false;
}

ConvexUnion random_union(std::uint64_t seed, int count, std::int64_t spread, std::int64_t size) {
  std::mt19937_64 rng(seed);
  std::vector<ConvexPolyhedron> pieces;
  while (static_cast<int>(pieces.size()) < count) {
    const Vec3 corner{Rational(uniform(rng, -spread, spread)), Rational(uniform(rng, -spread, spread)),
                      Rational(uniform(rng, -spread, spread))};
    std::vector<Vec3> points;
    const auto n = uniform(rng, 4, 12);
    for (std::int64_t k = 0; k < n; ++k) {
      points.push_back(corner + Vec3{Rational(uniform(rng, 0, size)), Rational(uniform(rng, 0, size)),
                                     Rational(uniform(rng, 0, size))});
    }
    try {
      pieces.push_back(convex_hull(points));
    } catch (const Error&) {
      // a flat cloud: draw another
    }
  }
  return ConvexUnion(std::move(pieces));
}

Vec3 random_exact_point(std::mt19937_64& rng, std::int64_t range) {
  auto coordinate = [&] {
    const std::int64_t den = uniform(rng, 1, 4);
    return Rational(uniform(rng, -range * den, range * den), den);
  };
  Vec3 p;
  p.x = coordinate();
  p.y = coordinate();
  p.z = coordinate();
  for (int i = 0; i < 3; ++i) p[i].canonicalize();
  return p;
}

std::vector<Vec3> boundary_points(const ConvexUnion& u) {
  std::vector<Vec3> out;
  for (const ConvexPolyhedron& piece : u.pieces()) {
    for (VertexId v : piece.mesh().vertices()) out.push_back(piece.vertex(v));
    for (FaceId f : piece.mesh().faces()) {
      Vec3 sum{0, 0, 0};
      Rational count = 0;
      for (HalfedgeId h : piece.mesh().face_halfedges(f)) {
        const Vec3& from = piece.vertex(piece.mesh().from(h));
        out.push_back(Rational(1, 2) * (from + piece.vertex(piece.mesh().to(h))));
        sum += from;
        count += 1;
      }
      out.push_back(sum * Rational(1 / count));
    }
  }
  return out;
}

std::vector<Vec3> vertex_set(const ConvexPolyhedron& p) {
  std::vector<Vec3> out;
  for (VertexId v : p.mesh().vertices()) out.push_back(p.vertex(v));
  std::sort(out.begin(), out.end());
  return out;
}

Rational volume_by_tetrahedra(const ConvexPolyhedron& p) {
  const PolygonSoup soup = p.to_soup();
  Rational six_volume = 0;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    auto face = soup.face(f);
    for (std::size_t k = 1; k + 1 < face.size(); ++k)
      six_volume += dot(soup.points[face[0]], cross(soup.points[face[k]], soup.points[face[k + 1]]));
  }
  return six_volume / 6;
}

}  // namespace cvms::test
