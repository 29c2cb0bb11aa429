// SPDX-License-Identifier: MIT
// A numbering of a soup's points and faces that depends on the set alone,
// not on how it was computed, made without copying a coordinate: so that
// equal polyhedra are written as equal bytes (`cvms sum A B` and
// `cvms sum B A`) at the cost of integer work and one sort.
//
// The points are in lexicographic order of their exact coordinates (x, then
// y, then z), each face starts at its smallest number (a rotation keeps its
// orientation), and the faces are sorted as sequences of numbers. The sort
// compares doubles first: truncation toward zero (mpq_get_d, mpz_get_d_2exp)
// is monotone, so different doubles order their exact values the same way,
// and only equal doubles need an exact comparison.
#pragma once

#include <cstdint>
#include <vector>

#include "soup_view.hpp"

namespace cvms::io_detail {

/// What a canonical view reads besides the soup's points.
struct CanonicalNumbering {
  std::vector<std::uint32_t> order;         ///< position -> index of the point
  std::vector<std::uint32_t> face_offsets;  ///< of the renumbered, sorted faces
  std::vector<std::uint32_t> face_indices;
};

/// `soup` in the canonical numbering above, reading its points in place and
/// its renumbered faces from `numbering` (which it fills). The points must
/// be distinct (a polyhedron's vertices).
/// \pre soup has no order of its own, its faces are valid.
/// Complexity: O(n log n) comparisons for n points, mostly of doubles,
/// plus sorting the faces.
SoupView canonical_view(const SoupView& soup, CanonicalNumbering& numbering);

}  // namespace cvms::io_detail
