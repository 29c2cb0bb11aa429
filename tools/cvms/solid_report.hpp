// SPDX-License-Identifier: MIT
// What `cvms check` and `cvms decompose` print about a solid that need not
// be convex: its shells, cavities, genus, sizes, reflex edges, exact volume
// and the number of convex pieces of its decomposition, as text lines or as
// members of one JSON object.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <string>

#include "cvms/solid.hpp"
#include "json.hpp"

namespace cvms::cli {

/// "<name>: solid (convex|not convex)" and the facts above, one line each.
void report_solid(const std::string& name, const Solid& solid, std::size_t pieces, std::ostream& report);

/// The same facts as JSON members ("kind": "solid", "convex", "shells", ...).
void add_solid_members(JsonObject& o, const std::string& name, const Solid& solid, std::size_t pieces);

}  // namespace cvms::cli
