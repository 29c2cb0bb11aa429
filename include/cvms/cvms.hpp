// SPDX-License-Identifier: MIT
/// \file
/// The whole public API of cvms in one include: exact numbers and vectors,
/// meshes and convex polyhedra, the convex hull, the planar and the 3D
/// Minkowski sums, proximity (support, distance, penetration), file I/O and
/// the built-in shapes. A sum of two files:
/// \code
/// #include <cvms/cvms.hpp>
///
/// int main() {
///   auto a = cvms::read_polyhedron("a.off");  // read and check: cvms::Error if not convex
///   auto b = cvms::read_polyhedron("b.obj");
///   cvms::write_file("sum.off", cvms::minkowski_sum(a, b).polyhedron);  // exact coordinates
/// }
/// \endcode
/// Each header can also be included on its own (README.md lists them by
/// layer). This one includes every header directly in include/cvms/ and
/// nothing from its subfolders: scripts/check-docs.sh checks that the list
/// below is complete.
#pragma once

#include "cvms/convex_hull.hpp"
#include "cvms/convex_polyhedron.hpp"
#include "cvms/convex_set.hpp"
#include "cvms/convex_union.hpp"
#include "cvms/decomposition.hpp"
#include "cvms/diagnostics.hpp"
#include "cvms/error.hpp"
#include "cvms/float_mesh.hpp"
#include "cvms/halfspace_io.hpp"
#include "cvms/halfspaces.hpp"
#include "cvms/io.hpp"
#include "cvms/mesh.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/planar_sum.hpp"
#include "cvms/polygon_soup.hpp"
#include "cvms/predicates.hpp"
#include "cvms/progress.hpp"
#include "cvms/proximity.hpp"
#include "cvms/rational.hpp"
#include "cvms/set_io.hpp"
#include "cvms/set_sum.hpp"
#include "cvms/shapes.hpp"
#include "cvms/sign.hpp"
#include "cvms/solid.hpp"
#include "cvms/solid_sum.hpp"
#include "cvms/union_io.hpp"
#include "cvms/vec.hpp"
