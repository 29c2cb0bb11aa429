// SPDX-License-Identifier: MIT
// A convex cell of the partition and a boundary fragment inside it, and
// their exact split by a plane.
//
// A cell is kept as its vertices, each with the sorted indices of the
// table's planes it lies on (its tight planes). Every plane of a cell's
// list bounds it (the cell lies in the half-space), so two vertices that
// share two tight planes span an edge: the planes meet the cell in faces
// whose intersection is a face of dimension at most one holding both, that
// is the segment between them; and every edge lies on two of the planes. A
// split therefore finds the crossing edges from the tight sets alone, and
// the new vertex on edge (u, v) lies exactly on the planes u and v share
// and the splitting plane (a plane through an inner point of an edge of a
// convex body that bounds the body holds the whole edge). Every vertex is
// the intersection of three table planes, so the exact numbers stay as
// small as such an intersection.
#pragma once

#include <cstdint>
#include <vector>

#include "boundary_planes.hpp"
#include "cvms/vec.hpp"

namespace cvms::decomposition {

struct CellVertex {
  Vec3 point;
  std::vector<std::uint32_t> planes;  // sorted indices of the planes through point
};

struct Cell {
  std::vector<CellVertex> vertices;  // empty: no volume
};

// A convex polygon on one plane of the table: part of a boundary triangle.
struct Fragment {
  std::vector<Vec3> points;  // in order around the polygon
  std::uint32_t plane = 0;
  std::int8_t side = 1;      // the outward normal is side * planes[plane].normal
};

// The box [lo, hi] (lo < hi in every coordinate) as a cell; its planes are
// found in or appended to the table (see plane_index).
Cell box_cell(const Vec3& lo, const Vec3& hi, std::vector<Plane>& planes, std::uint32_t sorted_count);

// The parts of a cell behind (oriented side <= 0) and in front (>= 0) of
// plane `index` with orientation `side`. A part with no vertex strictly on its
// side has no volume and comes back empty.
struct CellSplit {
  Cell back;
  Cell front;
};
// The cell is taken by value: a cell on one side moves whole into its part.
CellSplit split_cell(Cell cell, const std::vector<Plane>& planes, std::uint32_t index, int side);

// The parts of a fragment strictly behind and strictly in front of a plane
// (either may be absent). A fragment on the plane has neither part:
// coplanar says so.
struct FragmentSplit {
  bool coplanar = false;
  bool has_back = false;
  bool has_front = false;
  Fragment back;
  Fragment front;
};
// The fragment is taken by value: one on one side moves whole into its part.
FragmentSplit split_fragment(Fragment fragment, const Plane& plane, int side);

// The exact point where segment (u, v) meets the plane; \pre u and v lie
// strictly on opposite sides.
Vec3 segment_plane_point(const Vec3& u, const Vec3& v, const Plane& plane);

}  // namespace cvms::decomposition
