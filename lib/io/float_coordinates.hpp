// SPDX-License-Identifier: MIT
// How the writers of convex sets honour the double modes of Coordinates: a
// convex set is rounded as a whole (round_to_doubles: the exact hull of
// double points, so that the doubles written form a valid convex set), and
// the soup of the rounded set is written with Coordinates::double_, which
// prints its coordinates unchanged since every one is a double.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "cvms/float_mesh.hpp"
#include "cvms/io.hpp"
#include "cvms/polygon_soup.hpp"

namespace cvms::io_detail {

/// The soup to write for a convex set: none when `coordinates` keep it as it
/// is (exact, or STL's float32 for Coordinates::double_), else the soup of
/// round(mode), which calls round_to_doubles. Errors name `name` when it is
/// not empty ("<name>: ...", as the file writers do).
/// \throw Error(invalid_argument) for Coordinates::double_outer in STL,
///   whose float32 coordinates cannot hold the rounded doubles, and as
///   round_to_doubles.
std::optional<PolygonSoup> rounded_soup(FileFormat format, Coordinates coordinates, const std::string& name,
                                        const std::function<ConvexSet(FloatMode)>& round);

/// \throw Error(invalid_argument) for Coordinates::double_outer: a soup
/// need not be convex, and only a convex set has a certified outer rounding.
void check_soup_coordinates(Coordinates coordinates);

}  // namespace cvms::io_detail
