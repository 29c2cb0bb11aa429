// SPDX-License-Identifier: MIT
// The exact planes of a polyhedron's facets, and where a ConvexPolyhedron
// keeps them: made once, when first asked for, unless its builder knew them
// already.
//
// Why lazily: validating a mesh (ConvexPolyhedron::from_mesh) decides the
// signs of a triangulated surface in general position with filtered
// orientations of its vertices, so a program that loads and checks such a
// polyhedron, or only reads its vertices, never pays for the primitive
// normals' gcds and the offsets' products, about half of loading a
// triangulated sphere. The offsets are made later still, when one is first
// asked for (ConvexPolyhedron::plane_offset), also for a sum's output, whose
// builder knows the normals: the sums and the validation never read them
// (their filters decide with normals and vertices), and in the sum they
// were an eighth of the time (an exact dot product per facet, its rational
// and its limbs). Why this is still exact and the same:
// a facet is a strictly convex polygon, counterclockwise from outside, so its
// first three corners a, b, c are not collinear and cross(b - a, c - a) is a
// positive multiple of its outward normal; the primitive integer vector of
// that direction is unique, and so is its offset dot(n, a).
#pragma once

#include <array>
#include <atomic>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

#include "approx.hpp"
#include "cvms/mesh.hpp"
#include "huge_page_blocks.hpp"
#include "limb_arena.hpp"
#include "packed_vectors.hpp"
#include "result_slab.hpp"

namespace cvms::detail {

/// The planes of the output facets, index by index.
struct FacetPlanes {
  // On huge pages when large (huge_page_blocks.hpp): the algorithms'
  // outputs (their approximations) and transforms make them anew each call.
  /// Outward primitive integer normals; empty when packed_normals holds them.
  KeptVector<Vec3> normals;
  /// The normals kept packed (a sum's output), or null.
  std::shared_ptr<const PackedVectors> packed_normals;
  KeptVector<ApproxVec3> normal_approx;  ///< the normals' approximations
  /// dot(normal, x) for x on the facet; or empty, to be made on first use
  /// (PlaneStore::offsets).
  KeptVector<Rational> offsets;

  [[nodiscard]] std::size_t size() const noexcept { return normal_approx.size(); }
  /// The normals as Vec3s, made from the packed ones on the first call.
  /// \throw std::bad_alloc only then.
  [[nodiscard]] std::span<const Vec3> exact_normals() const {
    if (packed_normals == nullptr) return normals;
    return packed_normals->vectors();
  }
};

/// Sizes planes for `facets` facets without offsets, their normals packed
/// (all 0, approximations too), both arrays carved from one slab of their
/// own (result_slab.hpp): the returned points, which planes shares, are for
/// the builder to write before anyone reads them.
[[nodiscard]] std::shared_ptr<PackedVectors> size_packed_planes(FacetPlanes& planes, std::size_t facets);

/// The plane triple of face f: its first three corners, in order (not
/// collinear and turning like the face when the face is strictly convex).
[[nodiscard]] inline std::array<VertexId, 3> first_corners(const Mesh& mesh, FaceId f) {
  const HalfedgeId h = mesh.halfedge(f);
  return {mesh.from(h), mesh.to(h), mesh.to(mesh.next(h))};
}

/// out = the primitive integer normal of cross(b - a, c - a) (nonzero), its
/// numerators kept in arena, and approx its approximation: in 128-bit
/// integers when the points are doubles of close exponents or small
/// fractions (short decimals), else rational (in `general` first, whose
/// storage the caller reuses from call to call).
/// \pre a, b, c are not collinear.
void primitive_normal(Vec3Ref a, Vec3Ref b, Vec3Ref c, LimbArena& arena, Vec3& general, Vec3& out,
                      ApproxVec3& approx);

/// The planes of every face of mesh from its first three corners (see the
/// file comment), their values' limbs kept in arena; without offsets.
/// \pre every face is a strictly convex polygon, counterclockwise seen from
///   outside, and vertex_approx[v] approximates vertex v.
FacetPlanes planes_from_first_corners(const Mesh& mesh, std::span<const ApproxVec3> vertex_approx,
                                      LimbArena& arena);

/// The offset dot(normals[f], x) of every face f of mesh, x its first
/// corner, the limbs kept in arena. \pre normals[f] is normal to face f.
KeptVector<Rational> offsets_from_first_corners(const Mesh& mesh, std::span<const Vec3> normals,
                                                LimbArena& arena);

/// A ConvexPolyhedron's planes (a move takes them along; a copy copies those
/// made, or makes its own): either given when it was built, or made from its
/// facets' first corners the first time they are needed, by whichever thread
/// asks first (std::call_once: concurrent readers of one polyhedron wait for
/// the same single computation).
class PlaneStore {
 public:
  /// Planes known already; `limbs` is the arena their values point into, if any.
  PlaneStore(FacetPlanes planes, std::shared_ptr<const LimbArena> limbs);
  /// Planes to be made from the corners on first use.
  PlaneStore();
  PlaneStore(const PlaneStore&) = delete;
  PlaneStore& operator=(const PlaneStore&) = delete;

  /// The planes of mesh, made now if they were not given or made before;
  /// their offsets may be empty (see offsets()).
  /// \pre mesh and vertex_approx are those of the polyhedron (or of a copy).
  const FacetPlanes& get(const Mesh& mesh, std::span<const ApproxVec3> vertex_approx);
  /// The planes' offsets: given with them, or made now from the normals and
  /// each facet's first corner if they were not made before (once, as the
  /// planes are). \pre as for get().
  const KeptVector<Rational>& offsets(const Mesh& mesh, std::span<const ApproxVec3> vertex_approx);
  /// The offsets if they are made or were given, else null (for a copy:
  /// it takes what is made, and makes the rest itself when asked).
  [[nodiscard]] const KeptVector<Rational>* offsets_if_made() const noexcept {
    return offsets_ready_.load(std::memory_order_acquire);
  }

 private:
  // Declared first so that they outlive the values that point into them.
  std::shared_ptr<const LimbArena> given_limbs_;
  LimbArena made_limbs_;
  LimbArena offset_limbs_;
  std::once_flag made_;
  std::once_flag offsets_made_;
  bool given_;
  FacetPlanes planes_;
  KeptVector<Rational> made_offsets_;  // when planes_ has none
  std::atomic<const KeptVector<Rational>*> offsets_ready_{nullptr};
};

}  // namespace cvms::detail
