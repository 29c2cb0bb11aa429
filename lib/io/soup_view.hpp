// SPDX-License-Identifier: MIT
// What the writers read: a polygon soup's points and faces, not owned, so that
// a polyhedron is written straight from its own mesh. Copying its exact
// coordinates into a PolygonSoup first, and destroying the copy, would cost
// a large share of writing a sum (a third for Sphere6 + rotated Sphere6).
#pragma once

#include <cstddef>
#include <cstdint>
#include <ostream>
#include <span>

#include "cvms/io.hpp"
#include "cvms/polygon_soup.hpp"
#include "dyadic_points.hpp"
#include "face_lists.hpp"

namespace cvms::io_detail {

struct SoupView {
  std::span<const Vec3> points;                 ///< unless packed
  std::span<const std::uint32_t> face_offsets;  ///< as PolygonSoup's: faces + 1 entries from 0
  std::span<const std::uint32_t> face_indices;
  /// The points when they are packed (a sum's output, written without
  /// making a Rational of them), else null. The text writers read these;
  /// the STL writer takes points only.
  const detail::DyadicPoints* packed = nullptr;
  /// Empty, or the point written at position j is order[j] of `points` (or
  /// `packed`): a numbering without moving a coordinate. The faces are in
  /// the written numbering (canonical_view.hpp).
  std::span<const std::uint32_t> order;

  [[nodiscard]] std::size_t num_points() const noexcept { return packed != nullptr ? packed->size() : points.size(); }
  /// The index in `points` (or `packed`) of the point written at position j.
  [[nodiscard]] std::size_t source(std::size_t j) const noexcept { return order.empty() ? j : order[j]; }
  /// The point written at position j. \pre not packed.
  [[nodiscard]] const Vec3& point(std::size_t j) const noexcept { return points[source(j)]; }
  /// Coordinate `axis` of the point written at position j. \pre packed.
  [[nodiscard]] const detail::PackedDyadic& packed_coordinate(std::size_t j, int axis) const noexcept {
    return packed->coordinate(source(j), axis);
  }

  static SoupView of(const PolygonSoup& soup) noexcept {
    return {soup.points, soup.face_offsets, soup.face_indices, nullptr, {}};
  }
  /// \pre face_offsets is not empty (check_soup_for_writing checks it).
  [[nodiscard]] std::size_t num_faces() const noexcept { return face_offsets.size() - 1; }
  /// \pre f < num_faces() and the offsets are consistent.
  [[nodiscard]] std::span<const std::uint32_t> face(std::size_t f) const noexcept {
    return face_indices.subspan(face_offsets[f], face_offsets[f + 1] - face_offsets[f]);
  }
};

/// The polyhedron's own points with its faces' index lists (made into
/// `faces`, which the view reads): no copy of an exact coordinate, and for
/// the text formats no Rational of a packed one (a sum's output).
SoupView polyhedron_view(const ConvexPolyhedron& p, FileFormat format, detail::FaceLists& faces);

/// The writers behind write_off, write_obj, write_stl and write_ply.
void write_off_view(std::ostream& out, const SoupView& soup, Coordinates coordinates);
void write_obj_view(std::ostream& out, const SoupView& soup, Coordinates coordinates);
void write_stl_view(std::ostream& out, const SoupView& soup);
void write_ply_view(std::ostream& out, const SoupView& soup, Coordinates coordinates);

}  // namespace cvms::io_detail
