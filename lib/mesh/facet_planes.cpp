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

namespace {

// Planes for `facets` facets without offsets, every value 0 and ready to be
// stored into by a LimbArena. Rationals are constructed in place, never
// moved there (moving one re-initialises its source, which allocates), and
// each denominator's limb is freed as soon as it is made
// (LimbArena::give_back_denominator), so that sizing reuses one heap block
// instead of keeping three per facet.
FacetPlanes sized_planes(std::size_t facets) {
  FacetPlanes planes;
  planes.normal_approx.resize(facets);
  planes.normals.reserve(facets);
  for (std::size_t i = 0; i < facets; ++i) {
    Vec3& normal = planes.normals.emplace_back();
    for (int k = 0; k < 3; ++k) LimbArena::give_back_denominator(normal[k]);
  }
  return planes;
}

}  // namespace

std::shared_ptr<PackedVectors> size_packed_planes(FacetPlanes& planes, std::size_t facets) {
  // A slab of their own rather than a part of the vertices' and the mesh's:
  // on one thread they are made after the mesh's scratch is gone, which
  // keeps the peak where it was.
  SlabPlan plan;
  plan.add<ApproxVec3>(facets);
  DyadicPoints::plan(plan, facets);
  const std::shared_ptr<ResultSlab> slab = ResultSlab::make(plan);
  planes.normal_approx = KeptVector<ApproxVec3>(facets, carving_from<ApproxVec3>(slab));
  auto normals = std::make_shared<PackedVectors>(DyadicPoints(facets, carving_from<PackedDyadic>(slab)));
  planes.packed_normals = normals;
  return normals;
}

FacetPlanes planes_from_first_corners(const Mesh& mesh, std::span<const ApproxVec3> vertex_approx,
                                      LimbArena& arena) {
  // Made once per polyhedron, so its denominators need no heap blocks of
  // their own (limb_arena.hpp).
  FacetPlanes out = sized_planes(mesh.num_faces());
  const auto ref = [&](VertexId v) { return Vec3Ref{mesh.position(v), vertex_approx[v.index()]}; };
  Vec3 general;  // keeps its limbs from facet to facet
  for (FaceId f : mesh.faces()) {
    const std::array<VertexId, 3> t = first_corners(mesh, f);
    primitive_normal(ref(t[0]), ref(t[1]), ref(t[2]), arena, general, out.normals[f.index()],
                     out.normal_approx[f.index()]);
  }
  return out;
}

KeptVector<Rational> offsets_from_first_corners(const Mesh& mesh, std::span<const Vec3> normals,
                                                LimbArena& arena) {
  const std::uint32_t faces = mesh.num_faces();
  KeptVector<Rational> out;
  out.reserve(faces);
  DotScratch scratch;
  for (std::uint32_t i = 0; i < faces; ++i) {
    // The first corner's exact coordinates, which facet order visits out of
    // order (prefetch_exact.hpp).
    if (i + prefetch_far < faces)
      prefetch_structs(mesh.position(mesh.from(mesh.halfedge(FaceId(i + prefetch_far)))));
    if (i + prefetch_near < faces)
      prefetch_limbs(mesh.position(mesh.from(mesh.halfedge(FaceId(i + prefetch_near)))));
    // Made once per polyhedron: no heap block per denominator (limb_arena.hpp).
    Rational& offset = out.emplace_back();
    LimbArena::give_back_denominator(offset);
    store_integer_dot(arena, offset, normals[i], mesh.position(mesh.from(mesh.halfedge(FaceId(i)))), scratch);
  }
  return out;
}

PlaneStore::PlaneStore(FacetPlanes planes, std::shared_ptr<const LimbArena> limbs)
    : given_limbs_(std::move(limbs)), given_(true), planes_(std::move(planes)) {
  if (planes_.offsets.size() == planes_.size())
    offsets_ready_.store(&planes_.offsets, std::memory_order_release);
}

PlaneStore::PlaneStore() : given_(false) {}

const FacetPlanes& PlaneStore::get(const Mesh& mesh, std::span<const ApproxVec3> vertex_approx) {
  if (!given_)
    std::call_once(made_, [&] { planes_ = planes_from_first_corners(mesh, vertex_approx, made_limbs_); });
  return planes_;
}

const KeptVector<Rational>& PlaneStore::offsets(const Mesh& mesh, std::span<const ApproxVec3> vertex_approx) {
  // Given with the planes, or made before (both published: the constructor, the once-call).
  if (const KeptVector<Rational>* made = offsets_if_made()) return *made;
  const FacetPlanes& planes = get(mesh, vertex_approx);
  std::call_once(offsets_made_, [&] {
    made_offsets_ = offsets_from_first_corners(mesh, planes.exact_normals(), offset_limbs_);
    offsets_ready_.store(&made_offsets_, std::memory_order_release);
  });
  return made_offsets_;
}

}  // namespace cvms::detail
