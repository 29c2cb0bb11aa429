// SPDX-License-Identifier: MIT
// README.md's "C++ usage" example. Below these comment lines, this file is
// that block byte for byte (the test example.readme_is_readme_md compares
// them); example.readme runs it on copies of examples/data/cube.off (a.off)
// and tetrahedron.obj (b.obj), writing sum.off and cspace.off.
#include <cvms/cvms.hpp>

int main() {
  auto a = cvms::read_polyhedron("a.off");  // read and check: cvms::Error if not a convex polyhedron
  auto b = cvms::read_polyhedron("b.obj");  // the format is the extension's: .off, .obj, .stl, .ply
  cvms::write_file("sum.off", cvms::minkowski_sum(a, b).polyhedron);  // exact coordinates

  // A robot b translated by t overlaps the obstacle a iff t lies in a ⊕ (−b).
  cvms::ConvexSet obstacle = cvms::minkowski_difference(a, b);
  cvms::write_file("cspace.off", obstacle);
}
