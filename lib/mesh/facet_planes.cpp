// SPDX-License-Identifier: MIT
// Facet planes from corners, and the store that makes them once (see the
// header for why the result is the same plane however it is found).
#include "facet_planes.hpp"

#include <array>
#include <optional>
#include <utility>

#include "cvms/convex_polyhedron.hpp"
#include "dyadic.hpp"
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

FacetPlanes planes_from_first_corners(const Mesh& mesh, const std::vector<ApproxVec3>& vertex_approx,
                                      LimbArena& arena) {
  FacetPlanes out;
  out.normals.resize(mesh.num_faces());
  out.normal_approx.resize(mesh.num_faces());
  out.offsets.resize(mesh.num_faces());
  const auto ref = [&](VertexId v) { return Vec3Ref{mesh.position(v), vertex_approx[v.index()]}; };
  Vec3 general;  // these two keep their limbs from facet to facet
  DotScratch scratch;
  for (FaceId f : mesh.faces()) {
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
