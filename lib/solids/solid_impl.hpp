// SPDX-License-Identifier: MIT
// The data of a validated solid, shared by its copies.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "cvms/rational.hpp"
#include "cvms/solid.hpp"
#include "cvms/vec.hpp"

namespace cvms {

struct Solid::Impl {
  std::vector<Vec3> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;  // outward (inside on the back)
  std::vector<std::uint32_t> triangle_facets;           // facet of each triangle
  std::vector<Vec3> facet_normals;                      // primitive integer, outward
  std::vector<Rational> facet_offsets;
  std::uint32_t shells = 0;
  std::uint32_t cavities = 0;
  std::uint32_t genus = 0;
  std::uint32_t reflex_edges = 0;
  Rational volume;
};

}  // namespace cvms
