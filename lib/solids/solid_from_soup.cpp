// SPDX-License-Identifier: MIT
// Solid::from_soup: the exact validation of cvms/solid.hpp, in this order,
// each step assuming the ones before:
//  1. the soup's shape (offsets, index range, 32-bit counts);
//  2. equal points merged into one vertex (by sorting, first_use.hpp);
//  3. each face planar, simple, of positive area, and triangulated
//     (face_triangulation.hpp);
//  4. every edge on as many faces one way as the other (surface_topology.hpp);
//  5. no two faces meet other than in shared edges and vertices
//     (self_intersection.hpp, pairs pruned by the hierarchy), shared meaning
//     at equal points: faces of parts that touch only share those;
//  6. where parts touch (four or more faces on an edge, several fans around
//     a vertex), the faces paired around the edge by their angular order and
//     each fan given its own copy of the vertex (manifold_split.hpp), so every
//     shell is a closed 2-manifold. This is sound: after step 5 the faces
//     around an edge are distinct half-planes, so the pairing exists iff
//     their directions alternate around it, and the solid near the edge is
//     then the union of the wedges between paired faces, with disjoint
//     interiors; the shells touch there but cannot cross;
//  7. facets, shells, genus and signed volumes (solid_properties.hpp);
//  8. orientation: shells are now closed surfaces meeting at most where
//     they touch, so those around a point are nested; a shell must face
//     outward at even depth (inside an even number of others) and inward at
//     odd depth, and then every point is inside at most one more outward
//     than inward shell: the set is regular and each face bounds its
//     interior on one side only. The depth's parity is that of the
//     crossings of a ray with the other shells from the centroid of a
//     triangle of the shell, a point in a face's relative interior and so on
//     no other shell (ray_parity.hpp);
//  9. positive total volume.
#include <algorithm>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "cvms/error.hpp"
#include "cvms/solid.hpp"
#include "element_names.hpp"
#include "face_triangulation.hpp"
#include "first_use.hpp"
#include "manifold_split.hpp"
#include "ray_parity.hpp"
#include "self_intersection.hpp"
#include "solid_access.hpp"
#include "solid_impl.hpp"
#include "solid_properties.hpp"
#include "surface_topology.hpp"
#include "triangle_tree.hpp"

namespace cvms {

namespace {

using detail::str;

[[noreturn]] void topology(const std::string& message) { throw Error(ErrorCategory::topology, message); }

void check_shape(const PolygonSoup& soup) {
  const auto& offsets = soup.face_offsets;
  if (offsets.empty() || offsets.front() != 0 || offsets.back() != soup.face_indices.size())
    throw Error(ErrorCategory::invalid_argument,
                "malformed polygon soup: face_offsets must start at 0 and end at face_indices.size()");
  for (std::size_t f = 0; f + 1 < offsets.size(); ++f)
    if (offsets[f + 1] < offsets[f])
      throw Error(ErrorCategory::invalid_argument,
                  "malformed polygon soup: face_offsets decrease at face " + std::to_string(f));
  if (soup.num_faces() == 0) topology("empty solid: the soup has no faces");
  // Half-edge numbers of the triangles go up to three times the corners.
  constexpr std::size_t max_corners = std::size_t{1} << 30;
  if (soup.face_indices.size() >= max_corners || soup.points.size() >= max_corners)
    throw Error(ErrorCategory::limit, "solid too large: " + std::to_string(soup.points.size()) + " points, " +
                                          std::to_string(soup.face_indices.size()) +
                                          " face corners (at most " + std::to_string(max_corners - 1) +
                                          " each)");
  const std::size_t n = soup.points.size();
  for (std::size_t f = 0; f < soup.num_faces(); ++f)
    for (std::uint32_t v : soup.face(f))
      if (v >= n)
        topology("face " + std::to_string(f) + ": vertex index " + str(v) + " out of range (" +
                 std::to_string(n) + " points)");
}

struct Merged {
  std::vector<Vec3> vertices;
  std::vector<std::uint32_t> names;    // the smallest input index of each vertex
  std::vector<std::uint32_t> corners;  // the faces' corners as vertex ids
};

// The points of the faces with equal points made one vertex, numbered in
// order of their smallest input index.
Merged merge_points(const PolygonSoup& soup) {
  std::vector<bool> is_used(soup.points.size(), false);
  for (std::uint32_t v : soup.face_indices) is_used[v] = true;
  std::vector<std::uint32_t> used;
  for (std::uint32_t v = 0; v < is_used.size(); ++v)
    if (is_used[v]) used.push_back(v);
  struct UsedPoints {
    const PolygonSoup* soup;
    const std::vector<std::uint32_t>* used;
    [[nodiscard]] std::size_t size() const { return used->size(); }
    const Vec3& operator[](std::size_t i) const { return soup->points[(*used)[i]]; }
  };
  const detail::FirstUse numbering = detail::first_use_by_comparison(UsedPoints{&soup, &used}, std::less<>{});
  Merged m;
  m.vertices.reserve(numbering.first.size());
  m.names.reserve(numbering.first.size());
  for (std::size_t position : numbering.first) {
    m.vertices.push_back(soup.points[used[position]]);
    m.names.push_back(used[position]);
  }
  std::vector<std::uint32_t> id_of(soup.points.size(), 0);
  for (std::size_t i = 0; i < used.size(); ++i) id_of[used[i]] = numbering.index[i];
  m.corners.reserve(soup.face_indices.size());
  for (std::uint32_t v : soup.face_indices) m.corners.push_back(id_of[v]);
  return m;
}

// The box of each shell, rounded outward.
std::vector<detail::Box> shell_boxes(const SolidAccess::Impl& impl, const detail::Shells& shells) {
  std::vector<detail::Box> boxes(shells.signed_volumes.size());
  std::vector<bool> started(boxes.size(), false);
  for (std::uint32_t t = 0; t < impl.triangles.size(); ++t) {
    const std::uint32_t s = shells.of_triangle[t];
    for (std::uint32_t v : impl.triangles[t]) {
      const detail::Box b = detail::point_box(impl.vertices[v]);
      if (started[s]) {
        detail::extend(boxes[s], b);
      } else {
        boxes[s] = b;
        started[s] = true;
      }
    }
  }
  return boxes;
}

// Whether each shell lies inside an odd number of the others. Only a shell
// whose box holds the starting point can hold the point, so a shell that is
// in no other's box needs no ray (the many parts of an assembly), and the
// ray counts only the triangles of shells whose boxes do.
std::vector<bool> odd_depths(const SolidAccess::Impl& impl, const detail::Shells& shells) {
  const auto count = static_cast<std::uint32_t>(shells.signed_volumes.size());
  std::vector<bool> odd(count, false);
  if (count < 2) return odd;
  const detail::TriangleTree shell_tree(shell_boxes(impl, shells));
  std::vector<std::uint32_t> around(count, count);  // around[t] == s: t's box holds s's starting point
  for (std::uint32_t s = 0; s < count; ++s) {
    const auto& tri = impl.triangles[shells.first_triangle[s]];
    const Vec3 p = Rational(1, 3) * (impl.vertices[tri[0]] + impl.vertices[tri[1]] + impl.vertices[tri[2]]);
    bool any = false;
    shell_tree.for_each_overlapping(detail::point_box(p), [&](std::uint32_t t) {
      if (t == s) return;
      around[t] = s;
      any = true;
    });
    if (any)
      odd[s] = detail::odd_crossings(impl.tree(), impl.vertices, impl.triangles, p,
                                     [&](std::uint32_t t) { return around[shells.of_triangle[t]] == s; });
  }
  return odd;
}

void check_orientation(const SolidAccess::Impl& impl, const detail::Shells& shells,
                       std::span<const std::uint32_t> face_of) {
  const std::vector<bool> odd_depth = odd_depths(impl, shells);
  for (std::uint32_t s = 0; s < odd_depth.size(); ++s) {
    const std::string shell = "the shell of face " + str(face_of[shells.first_triangle[s]]);
    const int orientation = sgn(shells.signed_volumes[s]);
    if (orientation == 0) throw Error(ErrorCategory::degenerate, shell + " encloses zero volume");
    if (orientation < 0 && !odd_depth[s])
      topology("inverted orientation: " + shell +
               " faces inward but is not a cavity (it lies inside an even number of other shells)");
    if (orientation > 0 && odd_depth[s])
      topology("inconsistent orientation: " + shell +
               " lies inside an odd number of other shells, so it bounds a cavity, but faces outward");
  }
}

// Steps 5 and 6 on the triangles (of merged points): the copies of split
// vertices are appended to impl.vertices. The hierarchy built for step 5
// stays the solid's: the split renumbers corners only, so every triangle
// keeps its index and its box.
void split_touching_parts(SolidAccess::Impl& impl, std::span<const std::uint32_t> face_of,
                          std::span<const std::uint32_t> names) {
  const detail::SelfIntersection crossing =
      detail::find_self_intersection(impl.tree(), impl.vertices, impl.triangles, face_of);
  if (crossing.faces)
    topology("faces " + str(crossing.faces->first) + " and " + str(crossing.faces->second) +
             " intersect (self-intersecting surface)");
  const auto merged_count = static_cast<std::uint32_t>(names.size());
  const auto bad = detail::try_split_non_manifold(impl.vertices, impl.triangles);
  if (!bad) return;
  // A copy made before the failure is named by the merged vertex at its point.
  const auto name = [&](std::uint32_t v) {
    if (v >= merged_count)
      v = static_cast<std::uint32_t>(
          std::find(impl.vertices.begin(), impl.vertices.end(), impl.vertices[v]) - impl.vertices.begin());
    return names[v];
  };
  topology("the faces on " + detail::edge_name(name(bad->first), name(bad->second)) +
           " do not alternate in direction around it, so the parts they bound overlap or do not close");
}

}  // namespace

Solid Solid::from_soup(PolygonSoup soup) {
  check_shape(soup);
  Merged merged = merge_points(soup);
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<Vec3> areas;
  std::vector<std::uint32_t> face_of;
  triangles.reserve(soup.face_indices.size());
  face_of.reserve(soup.face_indices.size());
  for (std::uint32_t f = 0; f < soup.num_faces(); ++f) {
    const std::span<const std::uint32_t> ids(merged.corners.data() + soup.face_offsets[f],
                                             soup.face_offsets[f + 1] - soup.face_offsets[f]);
    detail::triangulate_face(merged.vertices, ids, merged.names, f, triangles, areas);
    face_of.resize(triangles.size(), f);
  }
  detail::check_closed_surface(
      {soup.face_offsets, merged.corners, static_cast<std::uint32_t>(merged.vertices.size())}, merged.names);
  auto impl = std::make_shared<Impl>();
  impl->vertices = std::move(merged.vertices);
  impl->triangles = std::move(triangles);
  split_touching_parts(*impl, face_of, merged.names);
  const detail::Shells shells = detail::derive_properties(*impl, std::move(areas));
  check_orientation(*impl, shells, face_of);
  if (sgn(impl->volume) <= 0) throw Error(ErrorCategory::degenerate, "the solid has zero volume");
  Solid solid;
  solid.impl_ = std::move(impl);
  return solid;
}

}  // namespace cvms
