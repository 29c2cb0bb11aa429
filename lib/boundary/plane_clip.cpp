// SPDX-License-Identifier: MIT
// See plane_clip.hpp.
#include "plane_clip.hpp"

#include <cstddef>
#include <utility>

#include "filtered_predicates.hpp"
#include "plane_crossing.hpp"

namespace cvms::detail {
namespace {

bool has_integer_coordinates(const Vec3& v) {
  return mpz_cmp_ui(v.x.get_den_mpz_t(), 1) == 0 && mpz_cmp_ui(v.y.get_den_mpz_t(), 1) == 0 &&
         mpz_cmp_ui(v.z.get_den_mpz_t(), 1) == 0;
}

// The point where the segment [a, b] crosses the plane, for a and b
// strictly on opposite sides: on integers when the normal is an integer
// vector (a facet's primitive normal, plane_crossing.hpp), else as
// a + t (b - a) with t = s_a / (s_a - s_b), s = dot(normal, x) - offset.
ClipPoint crossing(const ClipPoint& a, const ClipPoint& b, const ClipPlane& plane) {
  Vec3 x;
  if (has_integer_coordinates(*plane.normal)) {
    plane_crossing(a.exact, b.exact, *plane.normal, *plane.offset, x);
  } else {
    const Rational sa = dot(*plane.normal, a.exact) - *plane.offset;
    const Rational sb = dot(*plane.normal, b.exact) - *plane.offset;
    const Rational t = sa / (sa - sb);
    x = a.exact + (b.exact - a.exact) * t;
  }
  const ApproxVec3 approx = ApproxVec3::of(x);
  return {std::move(x), approx};
}

// Appends the crossing point of corners i and j and returns its index.
std::uint32_t add_crossing(ClipPoints& points, std::uint32_t i, std::uint32_t j, const ClipPlane& plane) {
  ClipPoint x = crossing(points[i], points[j], plane);
  points.push_back(std::move(x));
  return static_cast<std::uint32_t>(points.size() - 1);
}

// split() with the corners' sides known.
SplitPolygon split_by_sides(ClipPoints& points, const ClipPolygon& polygon, const ClipPlane& plane,
                            const std::vector<Sign>& sides) {
  const std::size_t m = polygon.size();
  SplitPolygon out;
  for (std::size_t i = 0; i < m; ++i) {
    const std::size_t j = (i + 1) % m;
    if (sides[i] != Sign::positive) out.inside.push_back(polygon[i]);
    if (sides[i] != Sign::negative) out.outside.push_back(polygon[i]);
    if ((sides[i] == Sign::negative && sides[j] == Sign::positive) ||
        (sides[i] == Sign::positive && sides[j] == Sign::negative)) {
      const std::uint32_t x = add_crossing(points, polygon[i], polygon[j], plane);
      out.inside.push_back(x);
      out.outside.push_back(x);
    }
  }
  if (out.inside.size() < 3) out.inside.clear();
  if (out.outside.size() < 3) out.outside.clear();
  return out;
}

}  // namespace

Sign side(Vec3Ref p, const ClipPlane& plane) {
  return side_of_plane(p, Vec3Ref{*plane.normal, *plane.normal_approx}, *plane.offset, plane.offset_approx);
}

SplitPolygon split(ClipPoints& points, const ClipPolygon& polygon, const ClipPlane& plane) {
  std::vector<Sign> sides(polygon.size());
  for (std::size_t i = 0; i < polygon.size(); ++i) sides[i] = side(points[polygon[i]], plane);
  return split_by_sides(points, polygon, plane, sides);
}

namespace {
// True if some half-space of the region has every corner of the piece on
// or outside its plane: the region then meets the piece in zero area. Tested
// on the whole piece before any cut, as a cut made before that half-space is
// reached would be thrown away with its crossing points.
bool misses_region(const ClipPoints& points, const ClipPolygon& piece, const std::vector<ClipPlane>& region) {
  for (const ClipPlane& plane : region) {
    bool any_inside = false;
    for (std::size_t i = 0; i < piece.size() && !any_inside; ++i)
      any_inside = side(points[piece[i]], plane) == Sign::negative;
    if (!any_inside) return true;
  }
  return false;
}

// Appends to `out` the parts of `piece` outside the region, or the piece
// itself if it meets the region in zero area. `sides` is scratch space.
void subtract_from(ClipPoints& points, ClipPolygon&& piece, const std::vector<ClipPlane>& region,
                   std::vector<ClipPolygon>& out, std::vector<Sign>& sides) {
  if (misses_region(points, piece, region)) {
    out.push_back(std::move(piece));
    return;
  }
  const std::size_t first = out.size();
  ClipPolygon left;  // the part inside the planes seen so far, once cut
  bool cut = false;
  for (const ClipPlane& plane : region) {
    const ClipPolygon& current = cut ? left : piece;
    bool any_outside = false;
    bool any_inside = false;
    sides.resize(current.size());
    for (std::size_t i = 0; i < current.size(); ++i) {
      sides[i] = side(points[current[i]], plane);
      any_outside = any_outside || sides[i] == Sign::positive;
      any_inside = any_inside || sides[i] == Sign::negative;
    }
    if (!any_outside) continue;  // the plane does not cut what is left
    if (!any_inside) {           // the region meets the piece in zero area
      out.resize(first);
      out.push_back(std::move(piece));
      return;
    }
    SplitPolygon parts = split_by_sides(points, current, plane, sides);
    out.push_back(std::move(parts.outside));
    left = std::move(parts.inside);
    cut = true;
  }
}

}  // namespace

void subtract_region(ClipPoints& points, std::vector<ClipPolygon>& pieces, const std::vector<ClipPlane>& region) {
  std::vector<ClipPolygon> out;
  out.reserve(pieces.size());
  std::vector<Sign> sides;
  for (ClipPolygon& piece : pieces) subtract_from(points, std::move(piece), region, out, sides);
  pieces = std::move(out);
}

}  // namespace cvms::detail
