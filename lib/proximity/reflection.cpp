// SPDX-License-Identifier: MIT
// -P by negation (see reflection.hpp). Negation reverses orientation, so each
// facet cycle is reversed to stay counterclockwise seen from outside; the
// facet order is kept, so facet f of -P has normal -normal(f) and offset
// plane_offset(f).
#include "reflection.hpp"

#include <algorithm>

#include "polyhedron_builder.hpp"

namespace cvms::detail {
namespace {

ApproxVec3 negated(const ApproxVec3& a) {
  return {{-a.x.value, a.x.error}, {-a.y.value, a.y.error}, {-a.z.value, a.z.error}};
}

}  // namespace

ConvexPolyhedron reflection(const ConvexPolyhedron& p) {
  PolygonSoup soup = p.to_soup();
  for (Vec3& x : soup.points) x = -x;
  for (std::size_t f = 0; f < soup.num_faces(); ++f)
    std::reverse(soup.face_indices.begin() + soup.face_offsets[f], soup.face_indices.begin() + soup.face_offsets[f + 1]);
  VertexApproximations vertices;
  vertices.reserve(p.num_vertices());
  for (VertexId v : p.mesh().vertices()) vertices.push_back(negated(vertex_approx(p, v)));
  FacetPlanes planes;
  planes.normals.reserve(p.num_facets());
  planes.normal_approx.reserve(p.num_facets());
  // The offsets stay those of p (dot(-n, -x) = dot(n, x)); not made there,
  // they are made by -P when asked (a sum's operand never is).
  const Rational* offsets = PolyhedronAccess::made_offsets(p);
  if (offsets != nullptr) planes.offsets.reserve(p.num_facets());
  for (FaceId f : p.mesh().faces()) {
    planes.normals.push_back(-p.normal(f));
    planes.normal_approx.push_back(negated(normal_approx(p, f)));
    if (offsets != nullptr) planes.offsets.push_back(offsets[f.index()]);
  }
  return assemble(output_mesh(std::move(soup)), std::move(vertices), std::move(planes));
}

}  // namespace cvms::detail
