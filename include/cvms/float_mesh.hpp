// SPDX-License-Identifier: MIT
/// \file
/// Convex sets in doubles: rounded so that the rounded set is still a valid
/// convex set (FloatMode::nearest) or certainly contains the exact one
/// (FloatMode::outer), and exported as the flat arrays that game engines,
/// physics engines and slicers take.
///
/// Rounding each vertex of an exact convex polyhedron to its nearest double
/// may break convexity: four coplanar corners of a facet need not stay
/// coplanar, and a vertex may fall inside its neighbours' hull. Both modes
/// therefore take the exact convex hull of double points, whose facets are
/// maximal and exactly planar in those doubles:
///  - nearest: the hull of the vertices rounded to their nearest doubles;
///  - outer: the hull of the corners of every vertex's enclosing double box
///    (per coordinate the largest double below and the smallest above, one
///    value when the coordinate is a double), which contains the exact set.
///
/// \code
/// cvms::ConvexPolyhedron s = cvms::minkowski_sum(a, b).polyhedron;
/// cvms::FloatMesh mesh = cvms::to_float_mesh(s, cvms::FloatMode::outer);
/// engine.add_convex(mesh.positions.data(), mesh.num_vertices(), mesh.triangles.data(), mesh.num_triangles());
/// \endcode
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "cvms/convex_polyhedron.hpp"
#include "cvms/convex_set.hpp"

namespace cvms {

/// How an exact convex set becomes a convex set with double coordinates.
enum class FloatMode {
  /// The exact hull of the vertices rounded to their nearest doubles (ties
  /// to even): a valid convex set within the Hausdorff distance
  /// max over vertices v of |v - round(v)| <= max over v of sqrt(3) * ulp(v)/2
  /// of the exact set (ulp(v) the largest unit in the last place among v's
  /// coordinates). It may have fewer vertices than the exact set and, for a
  /// tiny or very thin set, a lower dimension.
  nearest,
  /// The exact hull of the corners of the vertices' enclosing double boxes:
  /// it contains the exact set (certified, not estimated), within the
  /// Hausdorff distance max over v of sqrt(3) * ulp(v); of the same
  /// dimension as the exact set or higher (a flat set whose plane is not
  /// spanned by doubles gets a thickness of one ulp).
  outer
};

/// The set rounded as `mode` says: every coordinate of the result is exactly
/// a double. A set whose coordinates are all doubles is returned unchanged.
/// \throw Error(invalid_argument) if a coordinate (or, for outer, its
///   rounding away from zero) is beyond the double range, naming the vertex.
/// Complexity: one exact hull of n (nearest) or at most 8n (outer) double
///   points, O(n log n) expected; O(n) when every coordinate is a double.
[[nodiscard]] ConvexSet round_to_doubles(const ConvexSet& set, FloatMode mode);
/// As round_to_doubles(ConvexSet(p), mode), without copying p.
/// \throw Error(invalid_argument) as above.
[[nodiscard]] ConvexSet round_to_doubles(const ConvexPolyhedron& p, FloatMode mode);

/// A rounded convex set as flat arrays. `positions` holds x, y, z of each
/// vertex in turn; the faces are index lists into the vertices, counter-
/// clockwise seen from outside, and `triangles` is every face fanned from
/// its first corner. The vertices and faces are those a writer prints for
/// the same set and mode (write_file with Coordinates::double_ or
/// Coordinates::double_outer), in the same order. A polygon has one face; a
/// segment or a point has vertices and no face.
struct FloatMesh {
  std::vector<double> positions;  ///< x0 y0 z0 x1 y1 z1 ...: 3 * num_vertices() values
  std::vector<std::uint32_t> triangles;  ///< i0 j0 k0 i1 j1 k1 ...: 3 * num_triangles() indices
  /// Face f's corners are face_indices[face_offsets[f] .. face_offsets[f + 1]);
  /// num_faces() + 1 offsets, the first 0 (as in PolygonSoup).
  std::vector<std::uint32_t> face_offsets{0};
  std::vector<std::uint32_t> face_indices;  ///< every face's corners in turn

  /// The number of vertices.
  [[nodiscard]] std::size_t num_vertices() const noexcept { return positions.size() / 3; }
  /// The number of triangles.
  [[nodiscard]] std::size_t num_triangles() const noexcept { return triangles.size() / 3; }
  /// The number of polygonal faces.
  [[nodiscard]] std::size_t num_faces() const noexcept {
    return face_offsets.size() - 1;
  }
};

/// The set rounded by round_to_doubles(set, mode), as flat arrays.
/// \throw Error(invalid_argument) as round_to_doubles.
/// Complexity: that of round_to_doubles, plus linear in the output.
[[nodiscard]] FloatMesh to_float_mesh(const ConvexSet& set, FloatMode mode = FloatMode::nearest);
/// As to_float_mesh(ConvexSet(p), mode), without copying p.
/// \throw Error(invalid_argument) as round_to_doubles.
[[nodiscard]] FloatMesh to_float_mesh(const ConvexPolyhedron& p, FloatMode mode = FloatMode::nearest);

}  // namespace cvms
