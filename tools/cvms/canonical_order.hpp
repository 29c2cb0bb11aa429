// SPDX-License-Identifier: MIT
// A numbering of a set's vertices and faces that depends on the set alone,
// not on how it was computed: `cvms sum A B C` and `cvms sum C B A` write
// the same bytes.
#pragma once

#include "cvms/convex_set.hpp"

namespace cvms::cli {

/// The same set with its vertices in lexicographic order of their exact
/// coordinates (x, then y, then z) and its faces each starting at its
/// smallest vertex number (orientation kept), sorted by their vertex
/// numbers. Two equal sets give identical results whatever their numbering.
ConvexSet in_canonical_order(const ConvexSet& set);

}  // namespace cvms::cli
