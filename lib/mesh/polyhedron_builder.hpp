// SPDX-License-Identifier: MIT
// The library's only ways to make a ConvexPolyhedron besides the checked
// ConvexPolyhedron::from_mesh, and its read access to what the public class
// keeps private: the double approximations (with proven error bounds) of
// vertices and normals that the predicate filters use.
//
// Two ways in, both for facets the caller already knows to be maximal,
// strictly convex, counterclockwise from outside, with only extreme vertices:
//  - trusted_polyhedron(soup): planes made from each facet's first corners
//    (the exact hull's output, transforms);
//  - assemble(mesh, approximations, planes): the algorithms' output path,
//    whose exact primitive normals and offsets are known already, so that
//    nothing is recomputed (no cross products, no gcds), built in parts that
//    may be computed concurrently.
// Topology is always checked (Mesh::from_soup); the geometry guarantee is the
// caller's. Private to the library: the public header declares these types
// without defining them, so no user can build an unchecked instance.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "approx.hpp"
#include "facet_planes.hpp"
#include "packed_vectors.hpp"
#include "limb_arena.hpp"
#include "cvms/convex_polyhedron.hpp"
#include "mesh_access.hpp"
#include "polyhedron_access.hpp"

namespace cvms::detail {

/// The parts of a mesh whose faces meet the guarantee above: the vertices'
/// approximations and the planes from each face's first corners, made now
/// (an algorithm's output comes with its planes, as the peers' do).
/// \throw Error(invalid_argument) if a face starts with three collinear
///   vertices (then it has no plane).
PolyhedronParts trusted_parts(Mesh mesh);

/// The polyhedron of a soup that meets the guarantee (topology checked).
ConvexPolyhedron trusted_polyhedron(PolygonSoup soup);

/// The half-edge mesh of an output soup, topology checked as in
/// Mesh::from_soup. \pre the points are canonical and pairwise distinct.
Mesh output_mesh(PolygonSoup soup);
/// The same for a soup without points whose points are packed (made into
/// Vec3s only if a caller asks), the connectivity carved from slab when it
/// is not null and has room. \pre as above.
Mesh output_mesh(PolygonSoup faces, std::shared_ptr<const PackedVectors> positions,
                 const std::shared_ptr<ResultSlab>& slab);
/// Adds to plan the room output_mesh carves for a mesh of `vertices`
/// vertices, `corners` face corners (halfedges) and `faces` faces.
void plan_output_mesh(SlabPlan& plan, std::size_t vertices, std::size_t corners, std::size_t faces);

/// The polyhedron from its mesh, the approximations of its vertices and the
/// planes of its faces (index by index; without offsets, the polyhedron
/// makes them on first use), with the arena of every value stored in one
/// (the polyhedron keeps it). Geometry is not checked.
/// \pre the guarantee holds and the planes are exact.
/// \throw Error(invalid_argument) if the counts do not match.
ConvexPolyhedron assemble(Mesh mesh, VertexApproximations vertex_approx, FacetPlanes planes,
                          LimbArena limbs = {});

inline const ApproxVec3& vertex_approx(const ConvexPolyhedron& p, VertexId v) noexcept {
  return PolyhedronAccess::vertex_approx(p, v);
}
/// vertex(v) with its approximation, for the filtered predicates.
inline Vec3Ref vertex_ref(const ConvexPolyhedron& p, VertexId v) { return {p.vertex(v), vertex_approx(p, v)}; }
/// The approximation of normal(f); makes the planes if they were not yet.
inline const ApproxVec3& normal_approx(const ConvexPolyhedron& p, FaceId f) {
  return PolyhedronAccess::planes(p).normal_approx[f.index()];
}
/// normal(f) with its approximation, for the filtered predicates.
inline Vec3Ref normal_ref(const ConvexPolyhedron& p, FaceId f) {
  const FacetPlanes& planes = PolyhedronAccess::planes(p);
  return {planes.exact_normals()[f.index()], planes.normal_approx[f.index()]};
}

}  // namespace cvms::detail
