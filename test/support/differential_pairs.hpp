// SPDX-License-Identifier: MIT
// The operand pairs of the CVMS differential suite (test/cvms_test.cpp), as
// one list, so that other operations can be checked on exactly those pairs
// (halfspaces_test: (A ⊕ B) ⊖ B == A), and the operands that suite builds
// by hand. A pair added to cvms_test.cpp belongs in differential_pairs()
// too.
#pragma once

#include <string>
#include <vector>

#include "cvms/convex_polyhedron.hpp"
#include "cvms/polygon_soup.hpp"

namespace cvms::test {

/// One pair of the suite, named after its test and operands.
struct NamedPair {
  std::string name;
  ConvexPolyhedron a;
  ConvexPolyhedron b;
};

/// Every hand-picked pair of cvms_test.cpp, test by test (its random pairs
/// are random_pair(1000 + i) of support/random_clouds.hpp).
std::vector<NamedPair> differential_pairs();

/// p scaled by s about the origin.
ConvexPolyhedron scaled(const ConvexPolyhedron& p, const Rational& s);

/// The rotation about z by the angle with cosine 3/5 and sine 4/5 (exact).
Mat3 rotation_z_3_4_5();

/// Thin operands: the slab [0, 1000]² × [0, 1/1000] and the same with y
/// thin, the needle [0, 1/1000]² × [0, 1000], both turned by the rational
/// rotation (1, 1, 2, 0), and a tetrahedron with a thin base and a far apex.
struct ThinOperands {
  ConvexPolyhedron slab, slab_y, needle, slab_rotated, needle_rotated, tetra_needle;
};
ThinOperands thin_operands();

/// A bipyramid over an integer hexagon in z = 0 with apexes (0, 0, ±h): for
/// small h its facet normals crowd the poles and the arcs of its six equator
/// edges run almost from pole to pole (nearly antipodal ends).
ConvexPolyhedron flat_bipyramid(const Rational& h);

/// The cube [−k, k]^3 given as a soup of 6 · 2 · k^2 coplanar triangles.
PolygonSoup triangulated_cube(int k);

/// The octagonal prism with normals (±1, 0, 0), (0, ±1, 0), (±1, ±1, 0) and
/// (0, 0, ±1): the arcs of the cube's vertical edges are each split by one
/// of its facet normals.
ConvexPolyhedron octagonal_prism();

}  // namespace cvms::test
