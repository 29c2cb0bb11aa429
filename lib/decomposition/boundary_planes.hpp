// SPDX-License-Identifier: MIT
// The planes of a solid's boundary, as the decomposition needs them: each
// triangle's plane as one of a table of distinct geometric planes (a
// primitive integer normal whose first nonzero coordinate is positive, and
// the exact offset), with the side the triangle faces; the reflex edges and
// the shells. Derived from vertices() and triangles() alone, so that the
// decomposition depends on no other part of a solid's validation.
#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "cvms/rational.hpp"
#include "cvms/solid.hpp"
#include "cvms/vec.hpp"

namespace cvms::decomposition {

// {x : dot(normal, x) == offset}; normal primitive integer, first nonzero
// coordinate positive, so that one geometric plane has one representation.
struct Plane {
  Vec3 normal;
  Rational offset;
};

// The sign of dot(normal, p) - offset for plane `plane` of the table, taken
// with the orientation `side` (+1 or -1): negative means behind an outward
// facet of that orientation.
int oriented_side(const Plane& plane, int side, const Vec3& p);

// The order of BoundaryPlanes::planes: by normal, then by offset.
bool plane_less(const Plane& a, const Plane& b);
bool plane_equal(const Plane& a, const Plane& b);

// The plane through `point` orthogonal to `normal` (nonzero), in canonical
// form, with the sign (+1 or -1) that turns `normal`'s direction into the
// canonical normal's.
std::pair<Plane, int> canonical_plane(const Vec3& normal, const Vec3& point);

struct BoundaryPlanes {
  std::vector<Plane> planes;                 // distinct, sorted by (normal, offset)
  std::vector<std::uint32_t> triangle_plane;  // per triangle: index into planes
  std::vector<std::int8_t> triangle_side;     // +1 if the outward normal is planes[..].normal, else -1
  std::vector<std::uint8_t> reflex_plane;     // per plane: holds a triangle on a reflex edge
  // The solid's edges (vertex index pairs, low first, sorted): the triangle
  // edges between two facets, flat ones inside a facet left out; the
  // reflex ones are flagged in `edge_reflex`.
  std::vector<std::array<std::uint32_t, 2>> edges;
  std::vector<std::uint8_t> edge_reflex;
  std::vector<std::array<std::uint32_t, 2>> edge_planes;  // per edge: its two triangles' planes
  std::uint32_t reflex_edges = 0;
  std::uint32_t shells = 0;
};

// \pre the solid is valid (closed, 2-manifold, oriented outward).
BoundaryPlanes boundary_planes(const Solid& solid);

// The index of a plane in a table sorted as BoundaryPlanes::planes, appended
// at the end when the table does not hold it (the bounding box's planes).
std::uint32_t plane_index(std::vector<Plane>& planes, std::uint32_t sorted_count, const Plane& plane);

}  // namespace cvms::decomposition
