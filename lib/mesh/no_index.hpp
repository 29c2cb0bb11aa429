// SPDX-License-Identifier: MIT
// The raw index that names no element, for the 32-bit index arrays that the
// mesh, polyhedron and hull builders keep beside the typed handles (face
// stamps, region ids, renumberings, lazy slots). It is the index of an invalid
// handle, so a count below it fits every handle and Handle(no_index) is
// invalid.
#pragma once

#include <cstdint>

#include "cvms/mesh.hpp"

namespace cvms::detail {

inline constexpr std::uint32_t no_index = HalfedgeId::invalid_index;

}  // namespace cvms::detail
