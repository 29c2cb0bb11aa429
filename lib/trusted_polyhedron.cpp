// SPDX-License-Identifier: MIT
// ConvexPolyhedron from trusted facets with known normals (see the header).
#include "trusted_polyhedron.hpp"

#include <string>
#include <utility>

#include "cvms/error.hpp"
#include "dyadic.hpp"

namespace cvms::detail {

ConvexPolyhedron ConvexPolyhedronAccess::from_trusted_soup(PolygonSoup soup, std::vector<Vec3> normals) {
  if (normals.size() != soup.num_faces())
    throw Error(ErrorCategory::invalid_argument, "from_trusted_soup: " + std::to_string(normals.size()) +
                                                     " normals for " + std::to_string(soup.num_faces()) +
                                                     " faces");
  ConvexPolyhedron p;
  p.mesh_ = Mesh::from_soup_with_distinct_points(std::move(soup));
  const Mesh& m = p.mesh_;
  p.vertex_approx_.reserve(m.num_vertices());
  for (VertexId v : m.vertices()) p.vertex_approx_.push_back(ApproxVec3::of(m.position(v)));
  p.normal_approx_.reserve(m.num_faces());
  p.offsets_.reserve(m.num_faces());
  DotScratch scratch;
  for (FaceId f : m.faces()) {
    const Vec3& n = normals[f.index()];
    p.offsets_.push_back(integer_dot(n, m.position(m.from(m.halfedge(f))), scratch));
    p.normal_approx_.push_back(ApproxVec3::of(n));
  }
  p.normals_ = std::move(normals);
  return p;
}

}  // namespace cvms::detail
