// SPDX-License-Identifier: MIT
// The exact EPA (expanding polytope): the facet of M = A + (-B) nearest to
// the origin, from support points of M only, when the exact GJK has found
// the origin in M. epa.cpp has the algorithm and its proofs.
#pragma once

#include <optional>
#include <vector>

#include "double_epa.hpp"
#include "gjk.hpp"
#include "support_operand.hpp"

namespace cvms::detail {

/// The facet plane {x : <direction, x> = offset} of M nearest to the origin.
struct NearestFacet {
  Vec3 direction;   ///< primitive integer outward normal; ties: the smallest
  Rational offset;  ///< >= 0
  /// A point of A and a point of B with witness_a - witness_b the
  /// translation offset / |direction|^2 direction (a contact after it).
  Vec3 witness_a, witness_b;
};

/// \pre gjk is an exact_gjk outcome on a and b (no offset) with intersect set.
/// \return the nearest facet, or nothing when M is flat (no facets).
std::optional<NearestFacet> epa_nearest_facet(const SupportOperand& a, const SupportOperand& b,
                                              const GjkOutcome& gjk);

/// epa_nearest_facet with `guess` (support points of M as vertex pairs)
/// inserted before the loop instead of the double EPA's (which null asks
/// for; the tests pass wrong or empty guesses): the same answer but for
/// the witnesses. \pre the pairs are valid vertex ids of a and b.
std::optional<NearestFacet> epa_nearest_facet_from(const SupportOperand& a, const SupportOperand& b,
                                                   const GjkOutcome& gjk, const std::vector<VertexPair>* guess);

}  // namespace cvms::detail
