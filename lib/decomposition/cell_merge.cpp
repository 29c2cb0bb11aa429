// SPDX-License-Identifier: MIT
// Two interior-disjoint convex bodies A and B have a convex union exactly
// when vol(hull(A u B)) == vol(A) + vol(B): the hull contains A u B, and
// equal volumes of closed polyhedra one inside the other leave no room for
// a difference of positive volume, and a difference of zero volume between
// a convex body and a closed finite union of polyhedra is empty. The
// volumes are exact rationals, so the test is exact.
//
// The merge is greedy: each piece in turn absorbs the neighbours it can
// (see merge_convex_cells). Only pieces whose bounding boxes meet (a convex
// union is connected) and that pass the exact necessary conditions
// share_cross_section and facets_keep_sides are given to the exact hull.
#include "cell_merge.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <map>

#include "cvms/convex_hull.hpp"
#include "cvms/predicates.hpp"

namespace cvms::decomposition {
namespace {

struct Piece {
  ConvexPolyhedron polyhedron;
  Rational volume6;
  Vec3 lo, hi;
};

Piece make_piece(ConvexPolyhedron polyhedron) {
  Piece piece;
  const auto& points = polyhedron.mesh().positions();
  piece.lo = piece.hi = points.front();
  for (const Vec3& p : points)
    for (int axis = 0; axis < 3; ++axis) {
      if (p[axis] < piece.lo[axis]) piece.lo[axis] = p[axis];
      if (piece.hi[axis] < p[axis]) piece.hi[axis] = p[axis];
    }
  piece.volume6 = six_volume(polyhedron);
  piece.polyhedron = std::move(polyhedron);
  return piece;
}

bool boxes_meet(const Piece& a, const Piece& b) {
  for (int axis = 0; axis < 3; ++axis)
    if (a.hi[axis] < b.lo[axis] || b.hi[axis] < a.lo[axis]) return false;
  return true;
}

// Whether a facet plane H of a has all of b on or in front of it and a and
// b have the same vertices on H. Necessary for a convex union C of
// interior-disjoint a and b: some facet plane H of a separates them, and
// then a and b both meet H in the whole cross section C n H (a point of
// C n H is in a or in b, and each of them is the closure of its open half of
// C), a polygon whose vertices are those of a on H and those of b on H. It
// also makes the merge visit only cells that share a whole facet.
bool share_cross_section(const Piece& a, const Piece& b) {
  const ConvexPolyhedron& pa = a.polyhedron;
  const auto& points_a = pa.mesh().positions();
  const auto& points_b = b.polyhedron.mesh().positions();
  for (FaceId f : pa.mesh().faces()) {
    std::vector<Vec3> on_b;
    bool behind = false;
    for (const Vec3& p : points_b) {
      Sign s = side_of_plane(p, pa.normal(f), pa.plane_offset(f));
      if (s == Sign::negative) {
        behind = true;
        break;
      }
      if (s == Sign::zero) on_b.push_back(p);
    }
    if (behind || on_b.size() < 3) continue;
    std::vector<Vec3> on_a;
    for (const Vec3& p : points_a)
      if (side_of_plane(p, pa.normal(f), pa.plane_offset(f)) == Sign::zero) on_a.push_back(p);
    std::sort(on_a.begin(), on_a.end());
    std::sort(on_b.begin(), on_b.end());
    if (on_a == on_b) return true;
  }
  return false;
}

// Whether every facet plane of a has all of b on one closed side. Necessary
// for a convex union: if a u b = C is convex, every facet plane of a either
// supports C (b behind or on it) or is the plane between a and b (b in
// front or on it). Cheap (filtered predicates), it rejects most pairs before
// the exact hull.
bool facets_keep_sides(const Piece& a, const Piece& b) {
  const ConvexPolyhedron& pa = a.polyhedron;
  const auto& points = b.polyhedron.mesh().positions();
  for (FaceId f : pa.mesh().faces()) {
    bool behind = false, front = false;
    for (const Vec3& p : points) {
      Sign s = side_of_plane(p, pa.normal(f), pa.plane_offset(f));
      behind = behind || s == Sign::negative;
      front = front || s == Sign::positive;
      if (behind && front) return false;
    }
  }
  return true;
}

// The merged piece when the union of a and b is convex.
bool try_merge(Piece& a, const Piece& b) {
  if (!boxes_meet(a, b) || !share_cross_section(a, b) || !facets_keep_sides(a, b) || !facets_keep_sides(b, a))
    return false;
  std::vector<Vec3> points = a.polyhedron.mesh().positions();
  const auto& more = b.polyhedron.mesh().positions();
  points.insert(points.end(), more.begin(), more.end());
  ConvexPolyhedron hull = convex_hull(points);
  if (six_volume(hull) != a.volume6 + b.volume6) return false;
  a = make_piece(std::move(hull));
  return true;
}

}  // namespace

Rational six_volume(const ConvexPolyhedron& polyhedron) {
  PolygonSoup soup = polyhedron.to_soup();
  const Vec3& origin = soup.points.front();
  Rational sum;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    auto face = soup.face(f);
    const Vec3 a = soup.points[face[0]] - origin;
    for (std::size_t k = 1; k + 1 < face.size(); ++k)
      sum += dot(a, cross(soup.points[face[k]] - origin, soup.points[face[k + 1]] - origin));
  }
  return sum;
}

std::vector<ConvexPolyhedron> merge_convex_cells(const std::vector<std::vector<Vec3>>& cells,
                                                 detail::ProgressReporter& progress) {
  progress.begin("decomposition: merge", 2 * std::uint64_t{cells.size()});
  std::vector<Piece> pieces;
  pieces.reserve(cells.size());
  for (const auto& cell : cells) {
    pieces.push_back(make_piece(convex_hull(cell)));
    progress.advance(1);
  }
  // The pieces at each vertex: two pieces with a convex union share the
  // vertices of their cross section, so only these are candidates. An
  // ordered map: exact keys, and no hashing of values derived from input.
  std::map<Vec3, std::vector<std::uint32_t>> at;
  auto index_piece = [&](std::uint32_t i) {
    for (const Vec3& p : pieces[i].polyhedron.mesh().positions()) at[p].push_back(i);
  };
  for (std::uint32_t i = 0; i < pieces.size(); ++i) index_piece(i);
  std::vector<std::uint8_t> alive(pieces.size(), 1);
  // Each piece in turn absorbs neighbours while it can, scanning again after
  // each growth; a piece that stops growing never changes again, and every
  // later piece tries it after its own last growth, so one sweep leaves no
  // two neighbours with a convex union untried.
  for (std::uint32_t i = 0; i < pieces.size(); ++i) {
    progress.advance(1);
    bool grew = alive[i] != 0;
    while (grew) {
      grew = false;
      std::vector<std::uint32_t> near;
      for (const Vec3& p : pieces[i].polyhedron.mesh().positions())
        for (std::uint32_t j : at[p])
          if (j != i && alive[j] != 0) near.push_back(j);
      std::sort(near.begin(), near.end());
      near.erase(std::unique(near.begin(), near.end()), near.end());
      for (std::uint32_t j : near) {
        progress.advance(0);
        if (!try_merge(pieces[i], pieces[j])) continue;
        alive[j] = 0;
        index_piece(i);
        grew = true;
        break;
      }
    }
  }
  std::vector<ConvexPolyhedron> result;
  for (std::uint32_t i = 0; i < pieces.size(); ++i)
    if (alive[i] != 0) result.push_back(std::move(pieces[i].polyhedron));
  progress.end();
  return result;
}

}  // namespace cvms::decomposition
