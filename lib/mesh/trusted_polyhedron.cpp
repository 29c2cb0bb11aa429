// SPDX-License-Identifier: MIT
// ConvexPolyhedron from trusted parts (see the header).
#include "trusted_polyhedron.hpp"

#include <string>
#include <utility>

#include "cvms/error.hpp"

namespace cvms::detail {

Mesh ConvexPolyhedronAccess::output_mesh(PolygonSoup soup) {
  return Mesh::from_soup_with_distinct_points(std::move(soup));
}

ConvexPolyhedron ConvexPolyhedronAccess::assemble(Mesh mesh, std::vector<ApproxVec3> vertex_approx,
                                                  FacetPlanes planes) {
  const std::size_t faces = planes.normals.size();
  if (planes.normal_approx.size() != faces || planes.offsets.size() != faces || faces != mesh.num_faces() ||
      vertex_approx.size() != mesh.num_vertices())
    throw Error(ErrorCategory::invalid_argument,
                "assemble: " + std::to_string(faces) + " planes and " + std::to_string(vertex_approx.size()) +
                    " approximations for " + std::to_string(mesh.num_faces()) + " faces and " +
                    std::to_string(mesh.num_vertices()) + " vertices");
  ConvexPolyhedron p;
  p.mesh_ = std::move(mesh);
  p.vertex_approx_ = std::move(vertex_approx);
  p.normals_ = std::move(planes.normals);
  p.normal_approx_ = std::move(planes.normal_approx);
  p.offsets_ = std::move(planes.offsets);
  return p;
}

}  // namespace cvms::detail
