// SPDX-License-Identifier: MIT
// ConvexSet: the lower-dimensional forms and their canonical representation.
//
// Why the polygon check is complete: after dropping repeated and collinear
// vertices, a closed cycle in a plane whose every corner turns strictly left
// is a convex polygon iff its edge directions turn through exactly one full
// turn. Each left turn moves the direction counterclockwise by less than a
// half turn, so the total is a whole number w >= 1 of turns, and w is the
// number of times the direction passes from the lower half-plane of
// directions into the upper one (upper: y > 0, or y == 0 and x > 0). The
// check counts those passes in the chart of the plane (plane_chart.hpp,
// orientation-preserving for the canonical normal), with orient2d only.
#include "cvms/convex_set.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "cvms/error.hpp"
#include "cvms/predicates.hpp"
#include "convex_polygon.hpp"
#include "plane_chart.hpp"

namespace cvms {

namespace detail {

Vec3 canonical_normal(const Vec3& v) {
  Vec3 n = primitive_direction(v);
  const int first = sgn(n.x) != 0 ? 0 : (sgn(n.y) != 0 ? 1 : 2);
  return sgn(n[first]) < 0 ? -n : n;
}

}  // namespace detail

namespace {

[[noreturn]] void wrong_dimension(const char* what, int dimension) {
  throw Error(ErrorCategory::invalid_argument, std::string("ConvexSet::") + what + ": the set has dimension " +
                                                   std::to_string(dimension));
}

bool upper_direction(const Vec2& d) { return sgn(d.y) > 0 || (sgn(d.y) == 0 && sgn(d.x) > 0); }

// A vertex of the cycle with its index in the caller's input (for messages).
struct Corner {
  Vec3 point;
  std::size_t input;
};

std::string vertex_name(const Corner& c) { return "polygon: vertex " + std::to_string(c.input); }

// Drops repeated consecutive vertices (cyclically).
std::vector<Corner> distinct_corners(std::span<const Vec3> cycle) {
  std::vector<Corner> corners;
  for (std::size_t i = 0; i < cycle.size(); ++i)
    if (corners.empty() || corners.back().point != cycle[i]) corners.push_back({cycle[i], i});
  while (corners.size() > 1 && corners.front().point == corners.back().point) corners.pop_back();
  return corners;
}

// Keeps the strictly convex corners of a cycle counterclockwise in `chart`;
// throws for a reflex corner, a spike or a cycle winding more than once.
std::vector<Corner> strictly_convex_corners(const std::vector<Corner>& corners, const detail::PlaneChart& chart) {
  const std::size_t n = corners.size();
  std::vector<Vec2> flat;
  flat.reserve(n);
  for (const Corner& c : corners) flat.push_back(chart(c.point));
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& prev = flat[(i + n - 1) % n];
    const Vec2& next = flat[(i + 1) % n];
    const Sign turn = orient2d(prev, flat[i], next);
    if (turn == Sign::negative) throw Error(ErrorCategory::not_convex, vertex_name(corners[i]) + " is a reflex corner");
    if (turn == Sign::zero) {
      if (sign_dot(flat[i] - prev, next - flat[i]) == Sign::negative)
        throw Error(ErrorCategory::not_convex, vertex_name(corners[i]) + " is a spike (the boundary turns back)");
      continue;  // on a straight run
    }
    kept.push_back(i);
  }
  std::size_t passes = 0;
  for (std::size_t k = 0; k < kept.size(); ++k) {
    const std::size_t a = kept[k], b = kept[(k + 1) % kept.size()], c = kept[(k + 2) % kept.size()];
    if (!upper_direction(flat[b] - flat[a]) && upper_direction(flat[c] - flat[b])) ++passes;
  }
  if (passes != 1)
    throw Error(ErrorCategory::not_convex, "polygon: the boundary winds around " + std::to_string(passes) +
                                               " times (it is not a simple convex polygon)");
  std::vector<Corner> result;
  result.reserve(kept.size());
  for (std::size_t i : kept) result.push_back(corners[i]);
  return result;
}

}  // namespace

ConvexSet::ConvexSet(ConvexPolyhedron polyhedron) {
  if (polyhedron.num_vertices() == 0) return;
  dimension_ = 3;
  polyhedron_ = std::move(polyhedron);
}

ConvexSet ConvexSet::point(const Vec3& p) {
  ConvexSet s;
  s.dimension_ = 0;
  s.vertices_ = {p};
  return s;
}

ConvexSet ConvexSet::segment(const Vec3& a, const Vec3& b) {
  if (a == b) throw Error(ErrorCategory::degenerate, "segment: both endpoints are " + to_string(a.x) + " " +
                                                         to_string(a.y) + " " + to_string(a.z));
  ConvexSet s;
  s.dimension_ = 1;
  s.vertices_ = b < a ? std::vector<Vec3>{b, a} : std::vector<Vec3>{a, b};
  return s;
}

ConvexSet ConvexSet::polygon(std::span<const Vec3> cycle) {
  std::vector<Corner> corners = distinct_corners(cycle);
  if (corners.size() < 3)
    throw Error(ErrorCategory::degenerate,
                "polygon: " + std::to_string(corners.size()) + " distinct vertices (at least 3 are needed)");
  // The area vector of the cycle: nonzero for any polygon that will pass,
  // and pointing to the side from which the input is counterclockwise.
  const Vec3 area = detail::area_vector(corners.size(), [&corners](std::size_t i) -> const Vec3& { return corners[i].point; });
  if (is_zero(area)) {
    // Zero area: collinear points are a degenerate polygon, anything else
    // (a bow tie) is not convex, as ConvexPolyhedron::from_mesh says.
    for (std::size_t i = 2; i < corners.size(); ++i)
      if (!is_parallel(corners[1].point - corners[0].point, corners[i].point - corners[0].point))
        throw Error(ErrorCategory::not_convex, "polygon: zero signed area (it is not a convex polygon)");
    throw Error(ErrorCategory::degenerate, "polygon: the vertices enclose no area (they are collinear)");
  }
  const Vec3 n = detail::canonical_normal(area);
  const Rational offset = dot(n, corners[0].point);
  for (const Corner& c : corners)
    if (side_of_plane(c.point, n, offset) != Sign::zero)
      throw Error(ErrorCategory::not_convex, vertex_name(c) + " is not in the plane of the others");
  if (sign_dot(area, n) == Sign::negative) std::reverse(corners.begin(), corners.end());
  std::vector<Corner> convex = strictly_convex_corners(corners, detail::PlaneChart(n));
  const auto smallest = std::min_element(convex.begin(), convex.end(),
                                         [](const Corner& a, const Corner& b) { return a.point < b.point; });
  std::rotate(convex.begin(), smallest, convex.end());
  ConvexSet s;
  s.dimension_ = 2;
  s.normal_ = n;
  s.offset_ = offset;
  s.vertices_.reserve(convex.size());
  for (Corner& c : convex) s.vertices_.push_back(std::move(c.point));
  return s;
}

std::size_t ConvexSet::num_vertices() const noexcept {
  return dimension_ == 3 ? polyhedron_.num_vertices() : vertices_.size();
}

std::vector<Vec3> ConvexSet::vertices() const {
  if (dimension_ != 3) return vertices_;
  return polyhedron_.mesh().positions();
}

const ConvexPolyhedron& ConvexSet::polyhedron() const {
  if (dimension_ != 3) wrong_dimension("polyhedron", dimension_);
  return polyhedron_;
}

const Vec3& ConvexSet::normal() const {
  if (dimension_ != 2) wrong_dimension("normal", dimension_);
  return normal_;
}

const Rational& ConvexSet::plane_offset() const {
  if (dimension_ != 2) wrong_dimension("plane_offset", dimension_);
  return offset_;
}

std::vector<Vec3> ConvexSet::edge_normals() const {
  if (dimension_ != 2) wrong_dimension("edge_normals", dimension_);
  std::vector<Vec3> normals;
  normals.reserve(vertices_.size());
  for (std::size_t i = 0; i < vertices_.size(); ++i)
    normals.push_back(cross(vertices_[(i + 1) % vertices_.size()] - vertices_[i], normal_));
  return normals;
}

ConvexSet ConvexSet::translated(const Vec3& offset) const {
  if (dimension_ == 3) return ConvexSet(polyhedron_.translated(offset));
  ConvexSet s = *this;
  for (Vec3& v : s.vertices_) v += offset;
  if (dimension_ == 2) s.offset_ += dot(normal_, offset);
  return s;
}

ConvexSet ConvexSet::reflected() const {
  if (dimension_ == 3) return ConvexSet(polyhedron_.reflected());
  std::vector<Vec3> mirrored;
  mirrored.reserve(vertices_.size());
  for (const Vec3& v : vertices_) mirrored.push_back(-v);
  switch (dimension_) {
    case 0:
      return point(mirrored[0]);
    case 1:
      return segment(mirrored[0], mirrored[1]);
    case 2:
      return polygon(mirrored);
    default:
      return {};
  }
}

PolygonSoup ConvexSet::to_soup() const {
  if (dimension_ == 3) return polyhedron_.to_soup();
  PolygonSoup soup;
  soup.points = vertices_;
  if (dimension_ == 2) {
    std::vector<std::uint32_t> face(vertices_.size());
    for (std::uint32_t i = 0; i < face.size(); ++i) face[i] = i;
    soup.add_face(face);
  }
  return soup;
}

}  // namespace cvms
