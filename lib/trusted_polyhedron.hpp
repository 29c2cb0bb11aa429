// SPDX-License-Identifier: MIT
// The algorithms' output path: a ConvexPolyhedron from facets whose exact
// primitive normals the caller already knows, so that nothing is recomputed
// (no cross products, no gcds). Private to the library.
#pragma once

#include <vector>

#include "cvms/convex_polyhedron.hpp"

namespace cvms::detail {

struct ConvexPolyhedronAccess {
  /// As ConvexPolyhedron::from_trusted_soup, with normals[f] the outward
  /// normal of face f of the soup, already a primitive integer vector.
  /// Topology is checked as in Mesh::from_soup; geometry is not, and the
  /// points must be canonical and pairwise distinct.
  /// \pre normals.size() == soup.num_faces() and the from_trusted_soup
  ///   guarantee holds.
  static ConvexPolyhedron from_trusted_soup(PolygonSoup soup, std::vector<Vec3> normals);
};

}  // namespace cvms::detail
