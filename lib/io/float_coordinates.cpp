// SPDX-License-Identifier: MIT
// The double modes of the writers of convex sets (see float_coordinates.hpp).
#include "float_coordinates.hpp"

#include "cvms/error.hpp"

namespace cvms::io_detail {

namespace {

bool rounds_as_a_set(FileFormat format, Coordinates coordinates) {
  if (coordinates == Coordinates::exact) return false;
  if (format != FileFormat::stl) return true;
  if (coordinates == Coordinates::double_outer)
    throw Error(ErrorCategory::invalid_argument,
                "STL holds float32 coordinates: the outer rounding in doubles needs OFF, OBJ or PLY");
  return false;
}

}  // namespace

std::optional<PolygonSoup> rounded_soup(FileFormat format, Coordinates coordinates, const std::string& name,
                                        const std::function<ConvexSet(FloatMode)>& round) {
  try {
    if (!rounds_as_a_set(format, coordinates)) return std::nullopt;
    return round(coordinates == Coordinates::double_outer ? FloatMode::outer : FloatMode::nearest).to_soup();
  } catch (const Error& e) {
    if (name.empty()) throw;
    throw Error(e.category(), name + ": " + e.message());
  }
}

void check_soup_coordinates(Coordinates coordinates) {
  if (coordinates == Coordinates::double_outer)
    throw Error(ErrorCategory::invalid_argument,
                "the outer rounding applies to convex sets, not to a polygon soup (which need not be convex)");
}

}  // namespace cvms::io_detail
