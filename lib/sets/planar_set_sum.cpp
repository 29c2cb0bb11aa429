// SPDX-License-Identifier: MIT
// Sums of points, segments and polygons in parallel planes: the planar
// convolution (cvms/planar_sum.hpp) in the exact chart of the plane
// (plane_chart.hpp). The chart is an affine bijection of each plane
// orthogonal to the normal that maps sums to sums up to the constant offset
// of the planes, so the convolution's index pairs are the vertices of the
// sum in 3D; they are added in 3D, never lifted back. Also the stretched
// facets of segment_sum.cpp and polygon_sum.cpp: a facet plus a segment
// parallel to it.
#include <vector>

#include "cvms/planar_sum.hpp"
#include "plane_chart.hpp"
#include "set_sum_parts.hpp"

namespace cvms::detail {

namespace {

std::vector<Vec2> charted(const std::vector<Vec3>& points, const PlaneChart& chart) {
  std::vector<Vec2> flat;
  flat.reserve(points.size());
  for (const Vec3& p : points) flat.push_back(chart(p));
  return flat;
}

}  // namespace

ConvexSet coplanar_sum(const std::vector<Vec3>& a, const std::vector<Vec3>& b, const Vec3& normal) {
  const PlaneChart chart(normal);
  std::vector<Vec3> sum;
  for (const auto& [i, j] : planar_sum_indices(charted(a, chart), charted(b, chart))) sum.push_back(a[i] + b[j]);
  if (sum.size() == 1) return ConvexSet::point(sum[0]);
  if (sum.size() == 2) return ConvexSet::segment(sum[0], sum[1]);
  return ConvexSet::polygon(sum);
}

std::vector<std::pair<VertexId, std::uint32_t>> stretched_facet(const ConvexPolyhedron& p, FaceId f, const Vec3& from,
                                                                const Vec3& to) {
  const Mesh& m = p.mesh();
  const PlaneChart chart(p.normal(f));
  std::vector<VertexId> corners;
  std::vector<Vec2> flat;
  for (HalfedgeId h : m.face_halfedges(f)) {
    corners.push_back(m.from(h));
    flat.push_back(chart(p.vertex(m.from(h))));
  }
  const std::vector<Vec2> segment{chart(from), chart(to)};
  std::vector<std::pair<VertexId, std::uint32_t>> pairs;
  for (const auto& [i, j] : planar_sum_indices(flat, segment)) pairs.emplace_back(corners[i], j);
  return pairs;
}

}  // namespace cvms::detail
