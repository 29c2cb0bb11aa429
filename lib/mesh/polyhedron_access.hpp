// SPDX-License-Identifier: MIT
// What the public ConvexPolyhedron keeps private, and the library's own
// access to it: the double approximations (with proven error bounds) of the
// vertices and normals that the predicate filters read, the exact planes
// (made on first use, facet_planes.hpp) and the arena of the exact values.
// Only the library includes this header, so no user can build an instance
// whose geometry was not checked or name the types of what it keeps.
#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <optional>

#include "approx.hpp"
#include "cvms/convex_polyhedron.hpp"
#include "facet_planes.hpp"
#include "limb_arena.hpp"
#include "mesh_access.hpp"
#include "two_word_scaled.hpp"
#include "word_scaled.hpp"

namespace cvms {

namespace detail {

/// The approximations of a polyhedron's vertices, one per vertex: kept with
/// the polyhedron, carved from a result's slab where it has one.
using VertexApproximations = KeptVector<ApproxVec3>;

struct PolyhedronApproximations {
  VertexApproximations vertices;  ///< one per vertex
};

/// What the library's constructor of a ConvexPolyhedron takes, index by index.
struct PolyhedronParts {
  Mesh mesh;
  VertexApproximations vertex_approx;  ///< one per vertex
  /// The facets' planes when the builder knows them; nullopt: made from the
  /// facets' first corners when first needed (facet_planes.hpp).
  std::optional<FacetPlanes> planes;
  LimbArena limbs;  ///< where the exact values above keep their limbs, if they do
};

}  // namespace detail

/// What a ConvexPolyhedron keeps besides its mesh. Its own: a copy shares
/// the approximations (immutable) and copies the planes made so far.
struct ConvexPolyhedron::Impl {
  /// The limbs of the exact values (planes; the mesh's storage keeps them
  /// too, for its positions) when the library built them in one arena; null
  /// when they own their limbs. Declared first so that it outlives every
  /// value that points into it.
  std::shared_ptr<const detail::LimbArena> exact_limbs;
  std::shared_ptr<const detail::PolyhedronApproximations> approx;
  /// The approximations' first element: what vertex_approx reads in one load.
  const ApproxVec3* vertex_approx = nullptr;
  std::shared_ptr<detail::PlaneStore> planes;
  /// The planes once made or given (null before): what planes() reads
  /// without a call or a lock. Written by whichever reader made them; every
  /// writer writes the same pointer.
  std::atomic<const detail::FacetPlanes*> planes_made{nullptr};
  /// The vertices as integers over their common denominator
  /// (word_scaled.hpp), made on first use by whichever reader asks first;
  /// nullopt when they do not fit machine words.
  std::optional<detail::WordScaledPoints> scaled;
  std::once_flag scaled_made;
  /// The same in two-word integers (two_word_scaled.hpp), for operands
  /// whose common denominator does not fit one word; made on first use.
  std::optional<detail::TwoWordScaledPoints> two_word_scaled;
  std::once_flag two_word_scaled_made;
};

/// The library's access to ConvexPolyhedron's private parts (see the file
/// comment).
struct PolyhedronAccess {
  /// The polyhedron of parts whose geometry the library has checked or
  /// derived (polyhedron_builder.hpp makes them).
  static ConvexPolyhedron make(detail::PolyhedronParts&& parts);

  /// The approximations the library's predicates use.
  /// \pre p is not empty.
  [[nodiscard]] static const detail::PolyhedronApproximations& approximations(const ConvexPolyhedron& p) noexcept {
    return *p.impl_->approx;
  }
  /// The approximation of vertex v. \pre p is not empty.
  [[nodiscard]] static const ApproxVec3& vertex_approx(const ConvexPolyhedron& p, VertexId v) noexcept {
    return p.impl_->vertex_approx[v.index()];
  }
  /// The facets' planes (normals, their approximations; offsets only if they
  /// came with them, else empty: read offsets through plane_offset()), made
  /// now if they were not yet.
  [[nodiscard]] static const detail::FacetPlanes& planes(const ConvexPolyhedron& p) {
    const ConvexPolyhedron::Impl* impl = p.impl_.get();
    const detail::FacetPlanes* made = impl != nullptr ? impl->planes_made.load(std::memory_order_acquire) : nullptr;
    return made != nullptr ? *made : make_planes(p);
  }
  /// The offsets if they are made already (one per facet), else null: what a
  /// derived polyhedron can reuse without making them.
  [[nodiscard]] static const Rational* made_offsets(const ConvexPolyhedron& p) noexcept;
  /// The vertices as machine integers over their common denominator, made
  /// on the first call; null when they do not fit (or p is empty).
  [[nodiscard]] static const detail::WordScaledPoints* scaled_vertices(const ConvexPolyhedron& p) {
    ConvexPolyhedron::Impl* impl = p.impl_.get();
    if (impl == nullptr) return nullptr;
    std::call_once(impl->scaled_made, [&] { impl->scaled = detail::scale_to_words(p.mesh().positions()); });
    return impl->scaled ? &*impl->scaled : nullptr;
  }
  /// The vertices as two-word integers over their common denominator, made
  /// on the first call; null when they do not fit (or p is empty).
  [[nodiscard]] static const detail::TwoWordScaledPoints* two_word_scaled_vertices(const ConvexPolyhedron& p) {
    ConvexPolyhedron::Impl* impl = p.impl_.get();
    if (impl == nullptr) return nullptr;
    std::call_once(impl->two_word_scaled_made,
                   [&] { impl->two_word_scaled = detail::scale_to_two_words(p.mesh().positions()); });
    return impl->two_word_scaled ? &*impl->two_word_scaled : nullptr;
  }

 private:
  static const detail::FacetPlanes& make_planes(const ConvexPolyhedron& p);
};

}  // namespace cvms
