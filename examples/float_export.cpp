// SPDX-License-Identifier: MIT
// Example: handing an exact sum to a physics engine, in doubles, safely.
//
// A collision margin must never be smaller than the exact shape: a convex
// hull in doubles that misses a sliver of the exact sum lets objects
// interpenetrate by that sliver. FloatMode::outer gives a double polyhedron
// that contains the exact set (certified, not estimated), and to_float_mesh
// gives it as the flat arrays an engine takes: x, y, z per vertex and three
// 32-bit indices per triangle.
//
// The robot is a cube rotated by the rational quaternion (1, 2, 3, 4), whose
// coordinates have denominator 30 (not doubles), swept by a small
// tetrahedron. The program checks what it hands over, in exact arithmetic:
// every exact vertex of the sum lies inside every triangle's plane of the
// double mesh (its doubles taken exactly).
#include <cvms/float_mesh.hpp>
#include <cvms/minkowski.hpp>
#include <cvms/predicates.hpp>
#include <cvms/rational.hpp>
#include <cvms/shapes.hpp>
#include <cstddef>
#include <cstdint>
#include <iostream>
#include <vector>

namespace {

cvms::Vec3 position(const cvms::FloatMesh& mesh, std::uint32_t i) {
  return {cvms::rational_from_double(mesh.positions[3 * i]), cvms::rational_from_double(mesh.positions[3 * i + 1]),
          cvms::rational_from_double(mesh.positions[3 * i + 2])};
}

// p on the inner side of (or on) every triangle's plane, exactly.
bool inside(const cvms::FloatMesh& mesh, const cvms::Vec3& p) {
  for (std::size_t t = 0; t < mesh.num_triangles(); ++t) {
    const cvms::Vec3 a = position(mesh, mesh.triangles[3 * t]);
    const cvms::Vec3 b = position(mesh, mesh.triangles[3 * t + 1]);
    const cvms::Vec3 c = position(mesh, mesh.triangles[3 * t + 2]);
    // cross(b - a, c - a) points outward: positive is beyond the plane, outside.
    if (cvms::orient3d(a, b, c, p) == cvms::Sign::positive) return false;
  }
  return true;
}

}  // namespace

int main() {
  const cvms::ConvexPolyhedron robot =
      cvms::shapes::cube().transformed(cvms::shapes::rational_rotation(1, 2, 3, 4), cvms::Vec3{});
  const cvms::ConvexPolyhedron sweep = cvms::shapes::tetrahedron().transformed(
      cvms::shapes::scaling(cvms::Rational(1, 10), cvms::Rational(1, 10), cvms::Rational(1, 10)), cvms::Vec3{});
  const cvms::ConvexPolyhedron exact = cvms::minkowski_sum(robot, sweep).polyhedron;

  const cvms::FloatMesh mesh = cvms::to_float_mesh(exact, cvms::FloatMode::outer);
  // engine.add_convex_mesh(mesh.positions.data(), mesh.num_vertices(),
  //                        mesh.triangles.data(), mesh.num_triangles());
  std::cout << "exact sum: V=" << exact.num_vertices() << " F=" << exact.num_facets() << "\n";
  std::cout << "outer float mesh: V=" << mesh.num_vertices() << " faces=" << mesh.num_faces()
            << " triangles=" << mesh.num_triangles() << "\n";

  bool contained = true;
  for (cvms::VertexId v : exact.mesh().vertices()) contained = contained && inside(mesh, exact.vertex(v));
  std::cout << "every exact vertex inside: " << (contained ? "yes" : "no") << "\n";
  return contained ? 0 : 1;
}
