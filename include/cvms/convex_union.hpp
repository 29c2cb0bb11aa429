// SPDX-License-Identifier: MIT
/// \file
/// A union of convex polyhedra (its pieces, which may overlap): the exact
/// form of a non-convex Minkowski sum before its boundary is built, and the
/// form collision libraries and motion planners consume (sets of convex
/// pieces). A convex decomposition (cvms/decomposition.hpp) is a union whose
/// pieces have disjoint interiors; a sum of two unions is the union of the
/// pairwise sums of their pieces (A1 u A2) + (B1 u B2) = u (Ai + Bj).
///
/// Queries answer exactly and visit only the pieces a hierarchy of bounding
/// boxes cannot rule out.
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "cvms/convex_polyhedron.hpp"
#include "cvms/convex_set.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/proximity.hpp"
#include "cvms/vec.hpp"

namespace cvms {

/// A distance between a union and another set.
struct UnionDistance {
  DistanceResult distance;      ///< squared distance and witnesses (0 and a common point if they meet)
  std::size_t piece = 0;        ///< the piece of this union that attains it
  std::size_t other_piece = 0;  ///< the other union's piece (0 when the other is convex)
};

/// A finite union of convex polyhedra. Immutable value type; copies share
/// their pieces; const member functions may run concurrently. A
/// default-constructed instance is the empty union (no pieces).
///
/// \code
/// cvms::ConvexUnion u(std::vector<cvms::ConvexPolyhedron>{box, wedge});
/// u.contains(cvms::Vec3{0, 0, 0});
/// cvms::UnionDistance d = u.squared_distance(obstacle);
/// \endcode
class ConvexUnion {
 public:
  /// The empty union.
  ConvexUnion();
  ~ConvexUnion();
  /// Copies share the immutable pieces (cheap).
  ConvexUnion(const ConvexUnion&);
  /// Moves leave the source empty.
  ConvexUnion(ConvexUnion&&) noexcept;
  /// Copies share the immutable pieces (cheap).
  ConvexUnion& operator=(const ConvexUnion&);
  /// Moves leave the source empty.
  ConvexUnion& operator=(ConvexUnion&&) noexcept;

  /// The union of these pieces, in this order.
  /// \throw Error(invalid_argument) naming the first empty
  ///   (default-constructed) piece.
  explicit ConvexUnion(std::vector<ConvexPolyhedron> pieces);

  /// The pieces, in the order given or computed.
  [[nodiscard]] std::span<const ConvexPolyhedron> pieces() const noexcept;
  /// Number of pieces.
  [[nodiscard]] std::size_t size() const noexcept;
  /// True when there are no pieces.
  [[nodiscard]] bool empty() const noexcept { return size() == 0; }

  /// Whether p is in the union (boundary included), exactly: on the facet
  /// planes of the pieces whose boxes contain p.
  [[nodiscard]] bool contains(const Vec3& p) const;

  /// Whether the union and the other set share a point (touching counts),
  /// by the exact intersects() of cvms/proximity.hpp on the pieces whose
  /// boxes meet the other's. An empty union meets nothing.
  /// \throw Error(invalid_argument) if the other convex set is empty.
  [[nodiscard]] bool intersects(const ConvexPolyhedron& other) const;
  /// As above, for a polyhedron placed by a rigid motion.
  [[nodiscard]] bool intersects(const PlacedPolyhedron& other) const;
  /// As above, for a convex set of any dimension.
  [[nodiscard]] bool intersects(const ConvexSet& other) const;
  /// As above, for another union: whether any two pieces meet.
  [[nodiscard]] bool intersects(const ConvexUnion& other) const;

  /// The exact squared distance to the other set and its witnesses: the
  /// minimum over piece pairs, with the pieces that attain it (witness_a in
  /// this union's piece, witness_b in the other set). Among pairs at the
  /// same minimum, the first in (piece, other_piece) order. Branch and bound
  /// on the box hierarchy: pieces are visited in order of a lower bound of
  /// their box distance, until that bound exceeds the best exact value.
  /// \throw Error(invalid_argument) if either set is empty.
  [[nodiscard]] UnionDistance squared_distance(const ConvexPolyhedron& other) const;
  /// As above, for a convex set of any dimension.
  [[nodiscard]] UnionDistance squared_distance(const ConvexSet& other) const;
  /// As above, for another union (both hierarchies pruned together).
  [[nodiscard]] UnionDistance squared_distance(const ConvexUnion& other) const;

 private:
  // Pieces and the lazily built box hierarchy; defined inside the library.
  struct Impl;
  std::shared_ptr<const Impl> impl_;
};

/// (A1 u ... u An) + (B1 u ... u Bm) as the union of the n m pairwise sums
/// Ai + Bj, each by minkowski_sum with `options` (its algorithm and limits).
/// options.threads spreads the pairs over that many threads (no more than the
/// machine has cores; each pair on one thread); the result's pieces are in
/// the order (i, j) lexicographic whatever the thread count. Limits apply to
/// each pair and to the total output (facets and memory over all pairs, the
/// memory at SumLimits::bytes_per_output_facet per facet whatever the
/// algorithm), checked as the pairs' results arrive; while the total is
/// within them, each running thread may also hold one pair's sum up to the
/// per-pair limits. When options.diagnostics is set it receives the
/// counters summed over all pairs. An error from a pair stops the threads
/// from taking more pairs and is rethrown, naming the pair; the pair named
/// (and the result) is the same for every thread count: the first failing
/// pair in (i, j) order. options.progress (cvms/progress.hpp) hears the
/// stage "union: pairs", in pairs summed; the pairs' own stages are not
/// reported (they run on several threads at once), but each pair stops
/// soon after the callback asks to.
/// \throw Error(invalid_argument) if either union is empty;
/// \throw Error(cancelled) if options.progress returns false, naming a pair;
/// \throw Error(limit) as minkowski_sum, for the first pair or the total,
///   naming the pair; also before any sum when n m pieces of at least 4
///   facets each could not fit the limits.
ConvexUnion minkowski_sum(const ConvexUnion& a, const ConvexUnion& b, const Options& options = {});

}  // namespace cvms
