// SPDX-License-Identifier: MIT
// Example: the configuration-space obstacle of a translating robot.
//
// A robot B moves by translation: placed at t it occupies B + t. It overlaps
// an obstacle A iff a = b + t for some a in A, b in B, that is iff
//   t lies in  C = A + (-B)      (the configuration-space obstacle).
// Planning a collision-free motion of the robot among convex obstacles then
// reduces to moving a single point t around the polyhedra C.
//
// Here the obstacle is the box [2,4] x [0,2] x [0,2] and the robot a small
// tetrahedron whose reference point (its vertex at the origin) is where t
// puts it. Each query classifies t exactly against the facet planes of C:
// inside every plane strictly means the robot overlaps the obstacle, outside
// one plane means it is free, and otherwise it just touches the obstacle.
#include <cvms/convex_polyhedron.hpp>
#include <cvms/minkowski.hpp>
#include <cvms/polygon_soup.hpp>
#include <cvms/predicates.hpp>
#include <cvms/rational.hpp>
#include <cvms/shapes.hpp>
#include <iostream>
#include <string>

namespace {

enum class Contact { free, touching, overlapping };

// Every facet f of C satisfies dot(normal(f), x) <= plane_offset(f) on C.
// side_of_plane decides the sign of dot(t, n) - offset exactly.
Contact classify(const cvms::ConvexPolyhedron& c_obstacle, const cvms::Vec3& t) {
  bool on_boundary = false;
  for (cvms::FaceId f : c_obstacle.mesh().faces()) {
    const cvms::Sign side = cvms::side_of_plane(t, c_obstacle.normal(f), c_obstacle.plane_offset(f));
    if (side == cvms::Sign::positive) return Contact::free;
    if (side == cvms::Sign::zero) on_boundary = true;
  }
  return on_boundary ? Contact::touching : Contact::overlapping;
}

const char* to_string(Contact contact) {
  switch (contact) {
    case Contact::free:
      return "free";
    case Contact::touching:
      return "touching";
    case Contact::overlapping:
      return "collision";
  }
  return "?";
}

}  // namespace

int main() {
  using cvms::parse_rational;

  const cvms::ConvexPolyhedron obstacle = cvms::shapes::box({2, 0, 0}, {4, 2, 2});

  // The robot, from a hand-made mesh: faces counterclockwise seen from outside.
  cvms::PolygonSoup robot_mesh;
  robot_mesh.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  robot_mesh.add_face({0, 2, 1});
  robot_mesh.add_face({0, 1, 3});
  robot_mesh.add_face({0, 3, 2});
  robot_mesh.add_face({1, 2, 3});
  const cvms::ConvexPolyhedron robot = cvms::ConvexPolyhedron::from_soup(robot_mesh);

  // C = A + (-B): reflected() is -B = {-b : b in B}.
  const cvms::ConvexPolyhedron c_obstacle = cvms::minkowski_sum(obstacle, robot.reflected()).polyhedron;
  std::cout << "configuration-space obstacle: V=" << c_obstacle.num_vertices()
            << " E=" << c_obstacle.num_edges() << " F=" << c_obstacle.num_facets() << '\n';

  // Robot placements, as decimal text: parse_rational reads them exactly, so
  // 1.9 + 0.1 == 2 holds and contact is decided without tolerances.
  const char* placements[][3] = {
      {"0", "0", "0"},        // far from the box
      {"1", "0", "0"},        // the robot's tip (2,0,0) touches the box's corner
      {"1.5", "0.5", "0.5"},  // the tip (2.5,0.5,0.5) is inside the box
      {"1.9", "2", "0.5"},    // rests against the box's face y = 2
      {"1.9", "1.9", "0.5"},  // a little lower: overlaps
      // The robot's slanted face x+y+z = 1 against the box's edge x=2, y=0:
      // touching iff (2 - 1.3) + 0.3 == 1, which only exact arithmetic sees.
      {"1.3", "-0.3", "0.5"},   // touching
      {"1.3", "-0.31", "0.5"},  // 0.01 away: free
      {"1.31", "-0.3", "0.5"},  // 0.01 closer: collision
  };
  for (const auto& p : placements) {
    const cvms::Vec3 t{parse_rational(p[0]), parse_rational(p[1]), parse_rational(p[2])};
    std::cout << "robot at (" << p[0] << ", " << p[1] << ", " << p[2]
              << "): " << to_string(classify(c_obstacle, t)) << '\n';
  }
  return 0;
}
