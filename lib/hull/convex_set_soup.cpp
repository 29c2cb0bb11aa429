// SPDX-License-Identifier: MIT
// convex_set_from_soup: a soup as the convex set it describes, flat ones
// included (the rules are in cvms/convex_hull.hpp).
//
// Why the checks on several coplanar faces suffice: faces that are convex,
// consistently oriented (all counterclockwise seen from one side, every
// directed edge used at most once) form an oriented 2-chain in the plane
// whose boundary is the set of edges used once. If that boundary is one
// convex cycle C, the chain covers every point inside C with the same
// winding number as C (1) and nothing outside, so the union of the faces is
// exactly the convex polygon bounded by C: the polygon returned.
#include <algorithm>
#include <map>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "affine_dimension.hpp"
#include "convex_polygon.hpp"
#include "cvms/convex_hull.hpp"
#include "cvms/error.hpp"
#include "cvms/predicates.hpp"

namespace cvms {

namespace {

// The index of the first point at each position, so that repeated points of
// a soup (one copy per triangle, as in STL) are one vertex.
std::vector<std::uint32_t> first_copies(const PolygonSoup& soup) {
  std::map<Vec3, std::uint32_t> first;
  std::vector<std::uint32_t> copy(soup.points.size());
  for (std::uint32_t i = 0; i < copy.size(); ++i) copy[i] = first.emplace(soup.points[i], i).first->second;
  return copy;
}

// The dimension of the affine hull of the points some face uses. When every
// point is used (the usual soup: Mesh::from_soup rejects unused points),
// soup.points is read in place instead of a copy of every exact coordinate.
int used_dimension(const PolygonSoup& soup) {
  std::vector<bool> used(soup.points.size(), false);
  for (std::size_t f = 0; f < soup.num_faces(); ++f)
    for (std::uint32_t i : soup.face(f)) {
      if (i >= soup.points.size())
        throw Error(ErrorCategory::topology, "face " + std::to_string(f) + ": vertex index " + std::to_string(i) +
                                                 " is out of range (" + std::to_string(soup.points.size()) +
                                                 " points)");
      used[i] = true;
    }
  if (std::find(used.begin(), used.end(), false) == used.end()) return detail::affine_span(soup.points).dimension;
  std::vector<Vec3> points;
  for (std::size_t i = 0; i < used.size(); ++i)
    if (used[i]) points.push_back(soup.points[i]);
  return detail::affine_span(points).dimension;
}

std::vector<Vec3> face_points(const PolygonSoup& soup, std::size_t f) {
  std::vector<Vec3> points;
  for (std::uint32_t i : soup.face(f)) points.push_back(soup.points[i]);
  return points;
}

ConvexSet face_polygon(const PolygonSoup& soup, std::size_t f) {
  try {
    return ConvexSet::polygon(face_points(soup, f));
  } catch (const Error& e) {
    throw Error(e.category(), "face " + std::to_string(f) + ": " + e.message());
  }
}

// Sign of the face's area vector along n: its orientation seen from n.
Sign orientation(const std::vector<Vec3>& points, const Vec3& n) {
  return sign_dot(detail::area_vector(points.size(), [&points](std::size_t i) -> const Vec3& { return points[i]; }), n);
}

ConvexSet tiled_polygon(const PolygonSoup& soup) {
  const std::vector<std::uint32_t> copy = first_copies(soup);
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> directed;  // edge -> face
  Vec3 normal;
  Sign side = Sign::zero;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const ConvexSet polygon = face_polygon(soup, f);
    const Sign s = orientation(face_points(soup, f), polygon.normal());
    if (f == 0) {
      normal = polygon.normal();
      side = s;
    } else if (polygon.normal() != normal) {
      throw Error(ErrorCategory::not_convex, "face " + std::to_string(f) + " is not in the plane of face 0");
    } else if (s != side) {
      throw Error(ErrorCategory::not_convex, "face " + std::to_string(f) + " is oriented against face 0");
    }
    const auto face = soup.face(f);
    for (std::size_t k = 0; k < face.size(); ++k) {
      const std::pair<std::uint32_t, std::uint32_t> e{copy[face[k]], copy[face[(k + 1) % face.size()]]};
      if (e.first == e.second) continue;  // a repeated vertex, dropped by ConvexSet::polygon
      if (!directed.emplace(e, f).second)
        throw Error(ErrorCategory::topology, "face " + std::to_string(f) + ": the directed edge " +
                                                 std::to_string(e.first) + " -> " + std::to_string(e.second) +
                                                 " is also in face " + std::to_string(directed[e]));
    }
  }
  std::map<std::uint32_t, std::uint32_t> boundary_next;
  for (const auto& [e, f] : directed)
    if (!directed.contains({e.second, e.first}) && !boundary_next.emplace(e.first, e.second).second)
      throw Error(ErrorCategory::topology,
                  "the boundary of the faces passes twice through vertex " + std::to_string(e.first));
  std::vector<Vec3> cycle;
  std::uint32_t v = boundary_next.begin()->first;
  do {
    cycle.push_back(soup.points[v]);
    const auto it = boundary_next.find(v);
    if (it == boundary_next.end() || cycle.size() > boundary_next.size())
      throw Error(ErrorCategory::topology, "the boundary of the faces is not one closed cycle");
    v = it->second;
  } while (v != boundary_next.begin()->first);
  if (cycle.size() != boundary_next.size())
    throw Error(ErrorCategory::topology, "the boundary of the faces is not one cycle (" +
                                             std::to_string(boundary_next.size() - cycle.size()) +
                                             " boundary edges off the first)");
  try {
    return ConvexSet::polygon(cycle);
  } catch (const Error& e) {
    throw Error(ErrorCategory::not_convex, "the boundary of the faces: " + std::string(e.message()));
  }
}

// A single face whose points span space: named as a non-planar face (the
// mistake it is), with the first vertex off the plane of its first three
// non-collinear ones, rather than as the open surface it also is.
[[noreturn]] void throw_not_planar_face(const PolygonSoup& soup) {
  const std::span<const std::uint32_t> ids = soup.face(0);
  const Vec3& p0 = soup.points[ids[0]];
  std::size_t j = 1;
  while (soup.points[ids[j]] == p0) ++j;
  std::size_t k = j + 1;
  while (is_parallel(soup.points[ids[j]] - p0, soup.points[ids[k]] - p0)) ++k;
  std::size_t off = k + 1;
  while (orient3d(p0, soup.points[ids[j]], soup.points[ids[k]], soup.points[ids[off]]) == Sign::zero) ++off;
  throw Error(ErrorCategory::not_convex, "face 0 is not planar (vertex " + std::to_string(ids[off]) +
                                             " is off the plane of vertices " + std::to_string(ids[0]) + ", " +
                                             std::to_string(ids[j]) + " and " + std::to_string(ids[k]) + ")");
}

}  // namespace

ConvexSet convex_set_from_soup(PolygonSoup soup) {
  if (soup.num_faces() == 0) return convex_hull_set(soup.points);
  const int dimension = used_dimension(soup);
  if (dimension == 3 && soup.num_faces() == 1) throw_not_planar_face(soup);
  if (dimension == 3) return ConvexSet(ConvexPolyhedron::from_soup(std::move(soup)));
  if (dimension < 2)
    throw Error(ErrorCategory::degenerate, "the faces enclose no area (all their points are " +
                                               std::string(dimension == 0 ? "equal" : "collinear") + ")");
  if (soup.num_faces() == 1) return face_polygon(soup, 0);
  return tiled_polygon(soup);
}

}  // namespace cvms
