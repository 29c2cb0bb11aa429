// SPDX-License-Identifier: MIT
// A numbering of a polyhedron's vertices and facets that depends on the set
// alone, not on how it was computed: `cvms sum A B C` and `cvms sum C B A`
// write the same bytes. (Sets of lower dimension have a canonical form of
// their own: cvms/convex_set.hpp.)
#pragma once

#include "cvms/convex_polyhedron.hpp"
#include "cvms/polygon_soup.hpp"

namespace cvms::cli {

/// The polyhedron's facets (as p.to_soup()) with its vertices in
/// lexicographic order of their exact coordinates (x, then y, then z) and
/// each facet starting at its smallest vertex number (orientation kept), the
/// facets sorted by their vertex numbers. Equal polyhedra give equal soups
/// whatever their numbering; written, it reads back as the same polyhedron.
PolygonSoup canonical_soup(const ConvexPolyhedron& p);

}  // namespace cvms::cli
