// SPDX-License-Identifier: MIT
// Exact splits of convex cells and fragments (see convex_cell.hpp for why
// the tight planes give the edges). Signs come from side_of_plane; the new
// points are exact rationals.
#include "convex_cell.hpp"

#include <algorithm>
#include <iterator>

namespace cvms::decomposition {

Vec3 segment_plane_point(const Vec3& u, const Vec3& v, const Plane& plane) {
  Vec3 d = v - u;
  Rational t = (plane.offset - dot(plane.normal, u)) / dot(plane.normal, d);
  return u + t * d;
}

Cell box_cell(const Vec3& lo, const Vec3& hi, std::vector<Plane>& planes, std::uint32_t sorted_count) {
  std::uint32_t ids[3][2];
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 n{0, 0, 0};
    n[axis] = 1;
    ids[axis][0] = plane_index(planes, sorted_count, Plane{n, lo[axis]});
    ids[axis][1] = plane_index(planes, sorted_count, Plane{n, hi[axis]});
  }
  Cell cell;
  for (int corner = 0; corner < 8; ++corner) {
    CellVertex v;
    for (int axis = 0; axis < 3; ++axis) {
      int high = (corner >> axis) & 1;
      v.point[axis] = high != 0 ? hi[axis] : lo[axis];
      v.planes.push_back(ids[axis][high]);
    }
    std::sort(v.planes.begin(), v.planes.end());
    cell.vertices.push_back(std::move(v));
  }
  return cell;
}

namespace {

std::vector<std::uint32_t> common_planes(const CellVertex& a, const CellVertex& b) {
  std::vector<std::uint32_t> common;
  std::set_intersection(a.planes.begin(), a.planes.end(), b.planes.begin(), b.planes.end(),
                        std::back_inserter(common));
  return common;
}

void add_plane(std::vector<std::uint32_t>& list, std::uint32_t index) {
  auto it = std::lower_bound(list.begin(), list.end(), index);
  if (it == list.end() || *it != index) list.insert(it, index);
}

}  // namespace

CellSplit split_cell(Cell cell, const std::vector<Plane>& planes, std::uint32_t index, int side) {
  const Plane& plane = planes[index];
  const std::size_t n = cell.vertices.size();
  std::vector<int> signs(n);
  bool any_back = false, any_front = false;
  for (std::size_t i = 0; i < n; ++i) {
    signs[i] = oriented_side(plane, side, cell.vertices[i].point);
    any_back = any_back || signs[i] < 0;
    any_front = any_front || signs[i] > 0;
  }
  for (std::size_t i = 0; i < n; ++i)
    if (signs[i] == 0) add_plane(cell.vertices[i].planes, index);
  CellSplit split;
  if (!any_front) {
    split.back = std::move(cell);
    return split;
  }
  if (!any_back) {
    split.front = std::move(cell);
    return split;
  }
  // The crossing points first (they read the edges' ends), kept after the
  // vertices of each part.
  std::vector<CellVertex> crossings;
  for (std::size_t i = 0; i < n; ++i) {
    if (signs[i] >= 0) continue;
    for (std::size_t j = 0; j < n; ++j) {
      if (signs[j] <= 0) continue;
      std::vector<std::uint32_t> common = common_planes(cell.vertices[i], cell.vertices[j]);
      if (common.size() < 2) continue;
      add_plane(common, index);
      crossings.push_back(CellVertex{segment_plane_point(cell.vertices[i].point, cell.vertices[j].point, plane),
                                     std::move(common)});
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (signs[i] == 0) split.back.vertices.push_back(cell.vertices[i]);
    if (signs[i] < 0) split.back.vertices.push_back(std::move(cell.vertices[i]));
    if (signs[i] >= 0) split.front.vertices.push_back(std::move(cell.vertices[i]));
  }
  split.back.vertices.insert(split.back.vertices.end(), crossings.begin(), crossings.end());
  split.front.vertices.insert(split.front.vertices.end(), std::make_move_iterator(crossings.begin()),
                              std::make_move_iterator(crossings.end()));
  return split;
}

FragmentSplit split_fragment(Fragment fragment, const Plane& plane, int side) {
  const std::size_t n = fragment.points.size();
  std::vector<int> signs(n);
  bool any_back = false, any_front = false;
  for (std::size_t i = 0; i < n; ++i) {
    signs[i] = oriented_side(plane, side, fragment.points[i]);
    any_back = any_back || signs[i] < 0;
    any_front = any_front || signs[i] > 0;
  }
  FragmentSplit split;
  if (!any_back && !any_front) {
    split.coplanar = true;
    return split;
  }
  if (!any_front) {
    split.has_back = true;
    split.back = std::move(fragment);
    return split;
  }
  if (!any_back) {
    split.has_front = true;
    split.front = std::move(fragment);
    return split;
  }
  // Both parts have area: a convex polygon with vertices strictly on both
  // sides. Walk its edges once, keeping each side's vertices and the
  // crossing points in order.
  split.has_back = split.has_front = true;
  split.back.plane = split.front.plane = fragment.plane;
  split.back.side = split.front.side = fragment.side;
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t j = (i + 1) % n;
    if (signs[i] <= 0) split.back.points.push_back(fragment.points[i]);
    if (signs[i] >= 0) split.front.points.push_back(fragment.points[i]);
    if (signs[i] * signs[j] < 0) {
      Vec3 p = segment_plane_point(fragment.points[i], fragment.points[j], plane);
      split.back.points.push_back(p);
      split.front.points.push_back(std::move(p));
    }
  }
  return split;
}

}  // namespace cvms::decomposition
