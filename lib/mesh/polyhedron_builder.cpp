// SPDX-License-Identifier: MIT
// ConvexPolyhedron from trusted parts (see the header).
#include "polyhedron_builder.hpp"

#include <array>
#include <string>
#include <utility>

#include "cvms/error.hpp"
#include "filtered_predicates.hpp"

namespace cvms::detail {

PolyhedronParts trusted_parts(Mesh mesh) {
  PolyhedronParts parts;
  const Mesh& m = mesh;
  parts.vertex_approx.reserve(m.num_vertices());
  for (VertexId v : m.vertices()) parts.vertex_approx.push_back(ApproxVec3::of(m.position(v)));
  const auto ref = [&](VertexId v) { return Vec3Ref{m.position(v), parts.vertex_approx[v.index()]}; };
  for (FaceId f : m.faces()) {
    const std::array<VertexId, 3> t = first_corners(m, f);
    if (collinear(ref(t[0]), ref(t[1]), ref(t[2])))
      throw Error(ErrorCategory::invalid_argument, "facet " + std::to_string(f.index()) +
                                                       " starts with three collinear vertices (trusted input is not convex)");
  }
  parts.planes = planes_from_first_corners(m, parts.vertex_approx, parts.limbs);
  parts.mesh = std::move(mesh);
  return parts;
}

ConvexPolyhedron trusted_polyhedron(PolygonSoup soup) {
  return PolyhedronAccess::make(trusted_parts(Mesh::from_soup(std::move(soup))));
}

Mesh output_mesh(PolygonSoup soup) { return MeshAccess::from_distinct_points(std::move(soup)); }

Mesh output_mesh(PolygonSoup faces, std::shared_ptr<const PackedVectors> positions,
                 const std::shared_ptr<ResultSlab>& slab) {
  return MeshAccess::from_distinct_points(std::move(faces), std::move(positions), slab);
}

void plan_output_mesh(SlabPlan& plan, std::size_t vertices, std::size_t corners, std::size_t faces) {
  // Mesh::build's arrays: an outgoing halfedge per vertex, four per halfedge
  // (to, next, prev, face) and one per face.
  plan.add<HalfedgeId>(vertices);
  plan.add<VertexId>(corners).add<HalfedgeId>(corners).add<HalfedgeId>(corners).add<FaceId>(corners);
  plan.add<HalfedgeId>(faces);
}

ConvexPolyhedron assemble(Mesh mesh, VertexApproximations vertex_approx, FacetPlanes planes,
                          LimbArena limbs) {
  const std::size_t faces = planes.size();
  const std::size_t normals =
      planes.packed_normals != nullptr ? planes.packed_normals->packed().size() : planes.normals.size();
  if (normals != faces || (!planes.offsets.empty() && planes.offsets.size() != faces) ||
      faces != mesh.num_faces() || vertex_approx.size() != mesh.num_vertices())
    throw Error(ErrorCategory::invalid_argument,
                "assemble: " + std::to_string(faces) + " planes and " + std::to_string(vertex_approx.size()) +
                    " approximations for " + std::to_string(mesh.num_faces()) + " faces and " +
                    std::to_string(mesh.num_vertices()) + " vertices");
  PolyhedronParts parts{std::move(mesh), std::move(vertex_approx), std::move(planes), std::move(limbs)};
  return PolyhedronAccess::make(std::move(parts));
}

}  // namespace cvms::detail
