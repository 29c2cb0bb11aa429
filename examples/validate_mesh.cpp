// SPDX-License-Identifier: MIT
// Example: read a user's mesh, check that it is a convex polyhedron, and say
// what is wrong if it is not.
//
//   validate_mesh MESH.(off|obj|stl)
//
// Exit code 0 and the counts for a valid convex polyhedron; exit code 1 and
// one line on stderr naming the problem otherwise; 2 for a bad command line.
#include <cvms/convex_polyhedron.hpp>
#include <cvms/error.hpp>
#include <cvms/io.hpp>
#include <iostream>
#include <map>

namespace {

// The category tells a program what kind of problem it is, for example to
// decide whether to repair the input (taking the convex hull of its points
// with cvms::convex_hull, say) or to give up.
const char* hint(cvms::ErrorCategory category) {
  switch (category) {
    case cvms::ErrorCategory::parse:
      return "the file is not valid OFF, OBJ or STL";
    case cvms::ErrorCategory::topology:
      return "the faces do not form one closed, consistently oriented surface";
    case cvms::ErrorCategory::not_convex:
      return "the shape is not convex; its convex hull may be what you want";
    case cvms::ErrorCategory::degenerate:
      return "the shape is flat or has a face of zero area";
    case cvms::ErrorCategory::limit:
      return "the file exceeds a size limit (cvms::ReadLimits)";
    case cvms::ErrorCategory::io:
      return "the file cannot be read";
    default:
      return "see the message";
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: validate_mesh MESH.(off|obj|stl)\n";
    return 2;
  }
  const char* path = argv[1];
  try {
    // Reading checks the syntax (Error parse / limit / io); from_soup checks
    // the topology (closed 2-manifold, Error topology) and the geometry
    // (convex, Error not_convex; not flat, Error degenerate).
    cvms::PolygonSoup soup = cvms::read_file(path);
    const std::size_t input_points = soup.points.size();
    const std::size_t input_faces = soup.num_faces();
    const auto polyhedron = cvms::ConvexPolyhedron::from_soup(std::move(soup));

    std::cout << path << ": convex polyhedron with V=" << polyhedron.num_vertices()
              << " E=" << polyhedron.num_edges() << " F=" << polyhedron.num_facets() << '\n';
    if (input_points != polyhedron.num_vertices() || input_faces != polyhedron.num_facets())
      std::cout << "  read " << input_points << " points and " << input_faces
                << " faces: coplanar faces were merged into facets and"
                   " vertices that are not corners dropped\n";

    std::map<std::uint32_t, std::uint32_t> facets_by_degree;
    for (cvms::FaceId f : polyhedron.mesh().faces()) ++facets_by_degree[polyhedron.mesh().degree(f)];
    for (auto [degree, count] : facets_by_degree)
      std::cout << "  " << count << " facets with " << degree << " vertices\n";
    return 0;
  } catch (const cvms::Error& e) {
    // what() is "<category>: <message>"; the message says where the problem
    // is (file and line, or vertex/edge/face index of the input).
    std::cerr << path << ": " << e.what() << '\n';
    std::cerr << "  hint: " << hint(e.category()) << '\n';
    return 1;
  }
}
