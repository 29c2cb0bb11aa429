// SPDX-License-Identifier: MIT
// The strict-convexity check of a closed planar polygon in R^3 (the faces
// and merged facets of ConvexPolyhedron::from_mesh, and is_convex), on the
// points' cached approximations: every sign goes through the filtered
// predicates on differences of points, so no exact difference is formed
// unless the filter is uncertain. O(m) predicates for m points. Private to
// the library.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "filtered_predicates.hpp"

namespace cvms::detail {

/// Outcome of checking a closed planar polygon for strict convexity.
enum class PolygonFault { none, right_turn, reversal, too_few_corners, winds_more_than_once };

/// The fault (if any), where it is, and which positions are corners.
struct PolygonCheck {
  PolygonFault fault = PolygonFault::none;
  std::size_t at = 0;        ///< polygon position of the fault
  std::vector<char> corner;  ///< per position: strict left turn (1) or straight (0)
};

/// Checks that p[0..m) (m >= 3, consecutive points distinct) is, seen from
/// the side n points to, a strictly convex counterclockwise polygon once the
/// vertices where it runs straight on are dropped.
/// \pre the points lie in one plane orthogonal to n (n nonzero).
PolygonCheck check_convex_polygon(const std::vector<Vec3Ref>& p, Vec3Ref n);

/// What the fault says about the polygon whose positions are vertex_ids
/// ("has a reflex corner at vertex 7", ...); empty for none.
std::string describe_fault(const PolygonCheck& c, const std::vector<std::uint32_t>& vertex_ids);

/// The area vector (twice the vector area) of the closed polygon point(0),
/// ..., point(m - 1): exact, in time O(m log m) multiplications of fractions
/// whatever the denominators (see the definition).
Vec3 area_vector(std::size_t m, const std::function<const Vec3&(std::size_t)>& point);

}  // namespace cvms::detail
