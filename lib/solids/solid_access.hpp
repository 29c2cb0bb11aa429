// SPDX-License-Identifier: MIT
// The library's own way to make a solid from a boundary it already knows to
// be valid (a convex polyhedron's, a decomposition's test fixtures), without
// the exact self-intersection test.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "cvms/solid.hpp"
#include "cvms/vec.hpp"

namespace cvms {

struct SolidAccess {
  // The data, by a name the library's own code may use.
  using Impl = Solid::Impl;

  // A solid from closed, outward-oriented, non-self-intersecting triangles;
  // facets, planes, shells, reflex edges and volume are derived, not checked.
  // \pre the triangles bound a valid solid (as Solid::from_soup would accept).
  static Solid assume_valid(std::vector<Vec3> vertices,
                            std::vector<std::array<std::uint32_t, 3>> triangles);
  static const Solid::Impl& impl(const Solid& solid) { return *solid.impl_; }
};

}  // namespace cvms
