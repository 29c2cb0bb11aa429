// SPDX-License-Identifier: MIT
// How the mesh layer's error messages name elements: indices in decimal, an
// undirected edge by its two vertex indices with the smaller first, so that a
// message does not depend on the direction in which the edge was met.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>

namespace cvms::detail {

inline std::string str(std::uint32_t i) { return std::to_string(i); }

inline std::string edge_name(std::uint32_t a, std::uint32_t b) {
  return "edge (" + str(std::min(a, b)) + ", " + str(std::max(a, b)) + ")";
}

}  // namespace cvms::detail
