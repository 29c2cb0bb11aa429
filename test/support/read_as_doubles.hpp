// SPDX-License-Identifier: MIT
// Reading written files as floating-point pipelines read them: every
// coordinate token parsed as a double (strtod), the double then taken
// exactly. The oracle of the float output modes.
#pragma once

#include <string>

#include "cvms/polygon_soup.hpp"
#include "cvms/vec.hpp"

namespace cvms::test {

/// An OFF text (as cvms writes it: no comments) with its coordinates read as
/// doubles and taken exactly. Adds a test failure for a token that is not
/// the shortest text of its double (printing the double again must give it
/// back) and for text that is not such an OFF.
PolygonSoup read_off_as_doubles(const std::string& text);

/// Adds a test failure unless the soup is a valid convex set with exactly
/// its points as vertices and, a polyhedron, exactly its faces as facets
/// (none merged on reading: maximal, exactly planar facets). `label` names
/// the case in the message.
void expect_valid_convex_set(const PolygonSoup& soup, const std::string& label);

/// p in the closed convex set the soup describes, exactly. With two faces or
/// more, a polyhedron: on the inner side of every face's plane, spanned by
/// its first three corners (as in a written hull, whose facets have only
/// corners). Else a flat set: p adds no vertex to the hull of the points.
bool inside(const PolygonSoup& soup, const Vec3& p);

}  // namespace cvms::test
