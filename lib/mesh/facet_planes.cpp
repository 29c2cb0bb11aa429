// SPDX-License-Identifier: MIT
// Facet planes from corners, and the store that makes them once (see the
// header for why the result is the same plane however it is found).
#include "facet_planes.hpp"

#include <array>
#include <optional>
#include <utility>

#include "cvms/convex_polyhedron.hpp"
#include "dyadic.hpp"
#include "prefetch_exact.hpp"
#include "small_direction.hpp"

namespace cvms::detail {

void primitive_normal(Vec3Ref a, Vec3Ref b, Vec3Ref c, LimbArena& arena, Vec3& general, Vec3& out,
                      ApproxVec3& approx) {
  std::optional<SmallNormal> small;
  const std::optional<SmallDirection> u = small_integer_direction(a.approx, b.approx);
  const std::optional<SmallDirection> v = u ? small_integer_direction(a.approx, c.approx) : std::nullopt;
  if (u && v) {
    small = primitive_cross(*u, *v);
  } else if (const auto d = small_fraction_directions(a.exact, b.exact, c.exact)) {
    small = primitive_cross((*d)[0], (*d)[1]);
  }
  if (small) {
    small->store(arena, out);
    approx = small->approx();
    return;
  }
  general = primitive_direction(cross(subtract(b.exact, a.exact), subtract(c.exact, a.exact)));
  arena.store(out, general);
  approx = ApproxVec3::of(out);
}

FacetPlanes sized_planes(std::size_t facets, bool give_back_denominators) {
  FacetPlanes planes;
  planes.normal_approx.resize(facets);
  if (!give_back_denominators) {
    planes.normals.resize(facets);
    planes.offsets.resize(facets);
    return planes;
  }
  planes.normals.reserve(facets);
  planes.offsets.reserve(facets);
  for (std::size_t i = 0; i < facets; ++i) {
    Vec3& normal = planes.normals.emplace_back();
    for (int k = 0; k < 3; ++k) LimbArena::give_back_denominator(normal[k]);
    LimbArena::give_back_denominator(planes.offsets.emplace_back());
  }
  return planes;
}

FacetPlanes planes_from_first_corners(const Mesh& mesh, const std::vector<ApproxVec3>& vertex_approx,
                                      LimbArena& arena) {
  // Made once per polyhedron, so its denominators need no heap blocks of
  // their own (unlike a sum's on the calling thread: limb_arena.hpp).
  FacetPlanes out = sized_planes(mesh.num_faces(), true);
  const auto ref = [&](VertexId v) { return Vec3Ref{mesh.position(v), vertex_approx[v.index()]}; };
  Vec3 general;  // these two keep their limbs from facet to facet
  DotScratch scratch;
  const std::uint32_t faces = mesh.num_faces();
  for (std::uint32_t i = 0; i < faces; ++i) {
    // The offset reads the first corner's exact coordinates, which facet
    // order visits out of order (prefetch_exact.hpp).
    if (i + prefetch_far < faces)
      prefetch_structs(mesh.position(mesh.from(mesh.halfedge(FaceId(i + prefetch_far)))));
    if (i + prefetch_near < faces)
      prefetch_limbs(mesh.position(mesh.from(mesh.halfedge(FaceId(i + prefetch_near)))));
    const FaceId f(i);
    const std::array<VertexId, 3> t = first_corners(mesh, f);
    Vec3& normal = out.normals[f.index()];
    primitive_normal(ref(t[0]), ref(t[1]), ref(t[2]), arena, general, normal, out.normal_approx[f.index()]);
    store_integer_dot(arena, out.offsets[f.index()], normal, mesh.position(t[0]), scratch);
  }
  return out;
}

PlaneStore::PlaneStore(FacetPlanes planes, std::shared_ptr<const LimbArena> limbs)
    : given_limbs_(std::move(limbs)), given_(true), planes_(std::move(planes)) {}

PlaneStore::PlaneStore() : given_(false) {}

const FacetPlanes& PlaneStore::get(const Mesh& mesh, const std::vector<ApproxVec3>& vertex_approx) {
  if (!given_)
    std::call_once(made_, [&] { planes_ = planes_from_first_corners(mesh, vertex_approx, made_limbs_); });
  return planes_;
}

}  // namespace cvms::detail
