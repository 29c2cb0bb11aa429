// SPDX-License-Identifier: MIT
// ConvexPolyhedron from trusted parts (see the header).
#include "polyhedron_builder.hpp"

#include <string>
#include <utility>

#include "cvms/error.hpp"

namespace cvms::detail {

PolyhedronParts parts_with_planes(Mesh mesh) {
  PolyhedronParts parts;
  const Mesh& m = mesh;
  parts.approx.vertices.reserve(m.num_vertices());
  for (VertexId v : m.vertices()) parts.approx.vertices.push_back(ApproxVec3::of(m.position(v)));
  parts.normals.reserve(m.num_faces());
  parts.approx.normals.reserve(m.num_faces());
  parts.offsets.reserve(m.num_faces());
  for (FaceId f : m.faces()) {
    // Facets are strictly convex and counterclockwise from outside, so any
    // corner gives the outward normal.
    const HalfedgeId h = m.halfedge(f);
    const Vec3& a = m.position(m.from(h));
    const Vec3& b = m.position(m.to(h));
    const Vec3& c = m.position(m.to(m.next(h)));
    Vec3 n = cross(b - a, c - b);
    if (is_zero(n))
      throw Error(ErrorCategory::invalid_argument, "facet " + std::to_string(f.index()) +
                                                       " starts with three collinear vertices (trusted input is not convex)");
    n = primitive_direction(n);
    parts.offsets.push_back(dot(n, a));
    parts.approx.normals.push_back(ApproxVec3::of(n));
    parts.normals.push_back(std::move(n));
  }
  parts.mesh = std::move(mesh);
  return parts;
}

ConvexPolyhedron trusted_polyhedron(PolygonSoup soup) {
  return ConvexPolyhedron(parts_with_planes(Mesh::from_soup(std::move(soup))));
}

Mesh output_mesh(PolygonSoup soup) { return Mesh::from_soup(std::move(soup), DistinctPoints{}); }

ConvexPolyhedron assemble(Mesh mesh, std::vector<ApproxVec3> vertex_approx, FacetPlanes planes, LimbArena limbs) {
  const std::size_t faces = planes.normals.size();
  if (planes.normal_approx.size() != faces || planes.offsets.size() != faces || faces != mesh.num_faces() ||
      vertex_approx.size() != mesh.num_vertices())
    throw Error(ErrorCategory::invalid_argument,
                "assemble: " + std::to_string(faces) + " planes and " + std::to_string(vertex_approx.size()) +
                    " approximations for " + std::to_string(mesh.num_faces()) + " faces and " +
                    std::to_string(mesh.num_vertices()) + " vertices");
  PolyhedronParts parts{std::move(mesh), std::move(planes.normals), std::move(planes.offsets),
                        {std::move(vertex_approx), std::move(planes.normal_approx)},
                        std::move(limbs)};
  return ConvexPolyhedron(std::move(parts));
}

}  // namespace cvms::detail
