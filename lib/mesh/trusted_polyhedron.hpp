// SPDX-License-Identifier: MIT
// The algorithms' output path: a ConvexPolyhedron from facets whose exact
// primitive normals and plane offsets the caller already knows, so that
// nothing is recomputed (no cross products, no gcds), built in parts that
// may be computed concurrently. Private to the library.
#pragma once

#include <vector>

#include "cvms/convex_polyhedron.hpp"

namespace cvms::detail {

/// The planes of the output facets, index by index.
struct FacetPlanes {
  std::vector<Vec3> normals;              ///< outward primitive integer normals
  std::vector<ApproxVec3> normal_approx;  ///< their approximations
  std::vector<Rational> offsets;          ///< dot(normal, x) for x on the facet
};

struct ConvexPolyhedronAccess {
  /// The half-edge mesh of an output soup, topology checked as in
  /// Mesh::from_soup. \pre the points are canonical and pairwise distinct.
  static Mesh output_mesh(PolygonSoup soup);

  /// The polyhedron from its mesh, the approximations of its vertices and
  /// the planes of its faces (index by index). Geometry is not checked.
  /// \pre the from_trusted_soup guarantee holds and the planes are exact.
  /// \throw Error(invalid_argument) if the counts do not match.
  static ConvexPolyhedron assemble(Mesh mesh, std::vector<ApproxVec3> vertex_approx, FacetPlanes planes);
};

}  // namespace cvms::detail
