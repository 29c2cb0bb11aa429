// SPDX-License-Identifier: MIT
// The union's boundary as fragments (lib/boundary/boundary_fragments.hpp),
// checked against independent answers:
//  - the convex clipping underneath (plane_clip.hpp) on a square, by areas;
//  - the region one piece takes from a plane (covering_region.hpp) against
//    its definition, evaluated on every vertex by plain Rational arithmetic,
//    for planes through facets, edges and vertices and beside them;
//  - hand-computed areas per oriented plane for unions of boxes that share
//    facets, overlap, nest, coincide, or touch along an edge or at a vertex;
//  - exact points: random points of every piece's facets (exact rational
//    weights of the facet's corners, so off every line that matters) lie in
//    exactly one fragment iff they are on the union's boundary by brute
//    force: a point x of a facet with outward normal n is on the boundary
//    iff x + t n is outside the union for a t far below the inputs' feature
//    size (plain Rational containment, test/support/union_oracle.hpp);
//  - the fragments' own invariants, by plain Rational arithmetic: strictly
//    convex, counterclockwise from the normal's side, on their plane, the
//    planes distinct with primitive integer normals;
//  - the same fragments for one and two threads, cancellation and the
//    memory limit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <deque>
#include <limits>
#include <utility>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "boundary_fragments.hpp"
#include "covering_region.hpp"
#include "piece_geometry.hpp"
#include "plane_clip.hpp"
#include "cvms/convex_union.hpp"
#include "cvms/error.hpp"
#include "cvms/shapes.hpp"
#include "support/random_numbers.hpp"
#include "support/union_oracle.hpp"

namespace {

using cvms::ConvexPolyhedron;
using cvms::ConvexUnion;
using cvms::Rational;
using cvms::Vec3;
using cvms::detail::BoundaryFragment;
using cvms::detail::BoundaryFragments;
using cvms::detail::OrientedPlane;

BoundaryFragments fragments_of(const ConvexUnion& u, unsigned threads = 1) {
  cvms::Options options;
  options.threads = threads;
  return cvms::detail::union_boundary_fragments(u.pieces(), options);
}

ConvexPolyhedron box(Rational x0, Rational y0, Rational z0, Rational x1, Rational y1, Rational z1) {
  return cvms::shapes::box(Vec3{x0, y0, z0}, Vec3{x1, y1, z1});
}

// Twice the area of the fragment times |normal|: dot(normal, the sum of
// cross(c_i, c_{i+1})), positive for a counterclockwise polygon.
Rational scaled_area(const BoundaryFragment& f, const Vec3& normal) {
  Vec3 sum{0, 0, 0};
  for (std::size_t i = 0; i < f.corners.size(); ++i)
    sum += cross(f.corners[i], f.corners[(i + 1) % f.corners.size()]);
  return dot(sum, normal);
}

// The area on each oriented plane, for planes with axis-aligned unit normals,
// keyed by a name like "+x=2".
std::map<std::string, Rational> axis_areas(const BoundaryFragments& b) {
  std::map<std::string, Rational> areas;
  for (const BoundaryFragment& f : b.fragments) {
    const OrientedPlane& plane = b.planes[f.plane];
    std::string name;
    for (int k = 0; k < 3; ++k) {
      if (sgn(plane.normal[k]) != 0) {
        name = std::string(sgn(plane.normal[k]) > 0 ? "+" : "-") + "xyz"[k] + "=" +
               Rational(plane.normal[k] * plane.offset).get_str();
      }
    }
    areas[name] += scaled_area(f, plane.normal) / 2;
  }
  return areas;
}

Rational total_area(const std::map<std::string, Rational>& areas) {
  Rational total = 0;
  for (const auto& [name, area] : areas) total += area;
  return total;
}

// Is x strictly inside the fragment (x on its plane)?
bool fragment_interior_contains(const BoundaryFragment& f, const OrientedPlane& plane, const Vec3& x) {
  const std::size_t m = f.corners.size();
  for (std::size_t e = 0; e < m; ++e) {
    const Vec3& a = f.corners[e];
    if (sgn(dot(cross(f.corners[(e + 1) % m] - a, x - a), plane.normal)) <= 0) return false;
  }
  return true;
}

// No fragment's centroid lies inside another fragment of its plane or of
// the opposite plane (two fragments on one plane facing opposite ways never
// overlap either).
::testing::AssertionResult centroids_uncovered(const BoundaryFragments& b) {
  std::map<std::pair<Vec3, Rational>, std::vector<std::size_t>> by_plane;
  for (std::size_t i = 0; i < b.fragments.size(); ++i) {
    const OrientedPlane& plane = b.planes[b.fragments[i].plane];
    if (sgn(plane.normal.x) < 0 || (sgn(plane.normal.x) == 0 && (sgn(plane.normal.y) < 0 ||
                                                                  (sgn(plane.normal.y) == 0 && sgn(plane.normal.z) < 0))))
      by_plane[{-plane.normal, -plane.offset}].push_back(i);
    else
      by_plane[{plane.normal, plane.offset}].push_back(i);
  }
  for (const auto& [key, members] : by_plane) {
    for (const std::size_t i : members) {
      const BoundaryFragment& f = b.fragments[i];
      Vec3 centroid{0, 0, 0};
      for (const Vec3& c : f.corners) centroid += c;
      centroid = Rational(1, static_cast<long>(f.corners.size())) * centroid;
      for (const std::size_t j : members) {
        const BoundaryFragment& other = b.fragments[j];
        if (j != i && fragment_interior_contains(other, b.planes[other.plane], centroid))
          return ::testing::AssertionFailure() << "fragment " << i << " overlaps fragment " << j;
      }
    }
  }
  return ::testing::AssertionSuccess();
}

// Strictly convex and counterclockwise seen from the normal's side: every
// corner strictly left of every edge it is not on; all corners on the plane;
// the planes distinct, with primitive integer normals; no overlaps seen
// from the centroids.
::testing::AssertionResult fragment_invariants(const BoundaryFragments& b) {
  for (std::size_t i = 0; i < b.fragments.size(); ++i) {
    const BoundaryFragment& f = b.fragments[i];
    if (f.plane >= b.planes.size()) return ::testing::AssertionFailure() << "fragment " << i << ": bad plane";
    const OrientedPlane& plane = b.planes[f.plane];
    const std::size_t m = f.corners.size();
    if (m < 3) return ::testing::AssertionFailure() << "fragment " << i << " has " << m << " corners";
    for (const Vec3& c : f.corners) {
      if (dot(plane.normal, c) != plane.offset)
        return ::testing::AssertionFailure() << "fragment " << i << ": a corner off its plane";
    }
    for (std::size_t e = 0; e < m; ++e) {
      const Vec3& a = f.corners[e];
      const Vec3& c = f.corners[(e + 1) % m];
      for (std::size_t k = 0; k < m; ++k) {
        if (k == e || k == (e + 1) % m) continue;
        if (sgn(dot(cross(c - a, f.corners[k] - a), plane.normal)) <= 0)
          return ::testing::AssertionFailure() << "fragment " << i << ": not strictly convex counterclockwise";
      }
    }
  }
  for (std::size_t i = 0; i < b.planes.size(); ++i) {
    const Vec3& n = b.planes[i].normal;
    Rational g = 0;
    for (int k = 0; k < 3; ++k) {
      if (n[k].get_den() != 1) return ::testing::AssertionFailure() << "plane " << i << ": normal not integer";
      mpz_class gk;
      mpz_gcd(gk.get_mpz_t(), g.get_num_mpz_t(), n[k].get_num_mpz_t());
      g = Rational(gk);
    }
    if (g != 1) return ::testing::AssertionFailure() << "plane " << i << ": normal not primitive";
    for (std::size_t j = 0; j < i; ++j) {
      if (b.planes[j].normal == n && b.planes[j].offset == b.planes[i].offset)
        return ::testing::AssertionFailure() << "planes " << j << " and " << i << " are equal";
    }
  }
  return centroids_uncovered(b);
}

// Is x on the closed convex fragment (counterclockwise from its normal)?
bool fragment_contains(const BoundaryFragment& f, const OrientedPlane& plane, const Vec3& x) {
  if (dot(plane.normal, x) != plane.offset) return false;
  const std::size_t m = f.corners.size();
  for (std::size_t e = 0; e < m; ++e) {
    const Vec3& a = f.corners[e];
    if (sgn(dot(cross(f.corners[(e + 1) % m] - a, x - a), plane.normal)) < 0) return false;
  }
  return true;
}

// How many fragments contain x.
int fragments_containing(const BoundaryFragments& b, const Vec3& x) {
  int count = 0;
  for (const BoundaryFragment& f : b.fragments) count += fragment_contains(f, b.planes[f.plane], x) ? 1 : 0;
  return count;
}

// The facet's corners, counterclockwise from outside.
std::vector<Vec3> facet_corners(const ConvexPolyhedron& p, cvms::FaceId f) {
  std::vector<Vec3> corners;
  for (cvms::HalfedgeId h : p.mesh().face_halfedges(f)) corners.push_back(p.vertex(p.mesh().to(h)));
  return corners;
}

// A random point of the facet's relative interior: a combination of its
// corners with random positive weights up to 2^20.
Vec3 random_facet_point(std::mt19937_64& rng, const std::vector<Vec3>& corners) {
  std::uniform_int_distribution<std::int64_t> weight(1, std::int64_t{1} << 20);
  Vec3 sum{0, 0, 0};
  Rational total = 0;
  for (const Vec3& c : corners) {
    const Rational w(weight(rng));
    sum += w * c;
    total += w;
  }
  return (1 / total) * sum;
}

// For `samples` random points on each facet of each piece: exactly one
// fragment contains the point iff it is on the union's boundary (x + t n
// outside the union, t = 2^-40), none otherwise.
void expect_points_agree(const ConvexUnion& u, const BoundaryFragments& b, std::uint64_t seed, int samples) {
  std::mt19937_64 rng(seed);
  const Rational t(mpz_class(1), mpz_class(1) << 40);
  int on_boundary = 0;
  for (std::size_t p = 0; p < u.size(); ++p) {
    const ConvexPolyhedron& piece = u.pieces()[p];
    for (cvms::FaceId f : piece.mesh().faces()) {
      const std::vector<Vec3> corners = facet_corners(piece, f);
      for (int s = 0; s < samples; ++s) {
        const Vec3 x = random_facet_point(rng, corners);
        const bool boundary = !cvms::test::union_contains_brute_force(u, x + t * piece.normal(f));
        on_boundary += boundary ? 1 : 0;
        ASSERT_EQ(fragments_containing(b, x), boundary ? 1 : 0)
            << "seed " << seed << ", piece " << p << ", facet " << f.index() << ", sample " << s;
      }
    }
  }
  EXPECT_GT(on_boundary, 0) << "seed " << seed;
}

// The fragments of a union of boxes: their invariants, count and total area.
void expect_fragments(const ConvexUnion& u, std::size_t count, const Rational& area) {
  const BoundaryFragments b = fragments_of(u);
  EXPECT_TRUE(fragment_invariants(b));
  EXPECT_EQ(b.fragments.size(), count);
  EXPECT_EQ(total_area(axis_areas(b)), area);
}

// The half-space dot(normal, x) <= offset with its approximations, kept in
// a deque so that references to its members stay valid.
struct TestPlane {
  Vec3 normal;
  cvms::ApproxVec3 normal_approx;
  Rational offset;
};
cvms::detail::ClipPlane clip_plane(std::deque<TestPlane>& store, const Vec3& normal, const Rational& offset) {
  store.push_back({normal, cvms::ApproxVec3::of(normal), offset});
  const TestPlane& t = store.back();
  return {&t.normal, &t.normal_approx, &t.offset, cvms::Approx::of(t.offset)};
}

// The area of a polygon of the plane z = 0, counterclockwise seen from +z.
Rational polygon_area(const cvms::detail::ClipPoints& points, const cvms::detail::ClipPolygon& polygon) {
  Rational twice = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec3& a = points[polygon[i]].exact;
    const Vec3& b = points[polygon[(i + 1) % polygon.size()]].exact;
    twice += a.x * b.y - a.y * b.x;
  }
  return twice / 2;
}

// The corners of the square [0, 2]^2 of the plane z = 0, counterclockwise.
cvms::detail::ClipPoints square_corners() {
  cvms::detail::ClipPoints points;
  for (const auto& [x, y] : {std::pair{0, 0}, {2, 0}, {2, 2}, {0, 2}}) {
    const Vec3 p{x, y, 0};
    points.push_back({p, cvms::ApproxVec3::of(p)});
  }
  return points;
}

TEST(PlaneClip, SplitAndSubtractOnASquare) {
  cvms::detail::ClipPoints points = square_corners();
  const cvms::detail::ClipPolygon square = {0, 1, 2, 3};
  std::deque<TestPlane> store;
  // x <= 1/2 cuts it into 1 and 3; x <= 2 leaves it whole inside; x <= 0 has zero area inside.
  const auto halves = cvms::detail::split(points, square, clip_plane(store, {1, 0, 0}, Rational(1, 2)));
  EXPECT_EQ(polygon_area(points, halves.inside), 1);
  EXPECT_EQ(polygon_area(points, halves.outside), 3);
  EXPECT_TRUE(cvms::detail::split(points, square, clip_plane(store, {1, 0, 0}, 2)).outside.empty());
  EXPECT_TRUE(cvms::detail::split(points, square, clip_plane(store, {1, 0, 0}, 0)).inside.empty());
  // Minus [1, 3]^2: an L of area 3 in convex parts.
  const std::vector<cvms::detail::ClipPlane> region = {
      clip_plane(store, {-1, 0, 0}, -1), clip_plane(store, {1, 0, 0}, 3), clip_plane(store, {0, -1, 0}, -1),
      clip_plane(store, {0, 1, 0}, 3)};
  std::vector<cvms::detail::ClipPolygon> pieces = {square};
  cvms::detail::subtract_region(points, pieces, region);
  Rational area = 0;
  for (const cvms::detail::ClipPolygon& piece : pieces) {
    EXPECT_GE(piece.size(), 3U);
    EXPECT_GT(polygon_area(points, piece), 0);
    area += polygon_area(points, piece);
  }
  EXPECT_EQ(area, 3);
  // Minus a square that only touches it along the edge x = 2: unchanged.
  const std::vector<cvms::detail::ClipPlane> beside = {
      clip_plane(store, {-1, 0, 0}, -2), clip_plane(store, {1, 0, 0}, 3), clip_plane(store, {0, -1, 0}, 0),
      clip_plane(store, {0, 1, 0}, 2)};
  pieces = {square};
  cvms::detail::subtract_region(points, pieces, beside);
  ASSERT_EQ(pieces.size(), 1U);
  EXPECT_EQ(pieces[0], square);
  // Minus a square containing it: nothing left.
  const std::vector<cvms::detail::ClipPlane> around = {
      clip_plane(store, {-1, 0, 0}, 1), clip_plane(store, {1, 0, 0}, 3), clip_plane(store, {0, -1, 0}, 1),
      clip_plane(store, {0, 1, 0}, 3)};
  cvms::detail::subtract_region(points, pieces, around);
  EXPECT_TRUE(pieces.empty());
}

TEST(PlaneClip, RegionMeetingInZeroAreaLeavesThePieceWhole) {
  cvms::detail::ClipPoints points = square_corners();
  const cvms::detail::ClipPolygon square = {0, 1, 2, 3};
  std::deque<TestPlane> store;
  // x <= 1 and y <= 1 cut it, x >= 2 holds none of its interior: the piece
  // stays whole, and no crossing point is made.
  const std::vector<cvms::detail::ClipPlane> last_misses = {
      clip_plane(store, {1, 0, 0}, 1), clip_plane(store, {0, 1, 0}, 1), clip_plane(store, {-1, 0, 0}, -2)};
  std::vector<cvms::detail::ClipPolygon> pieces = {square};
  cvms::detail::subtract_region(points, pieces, last_misses);
  ASSERT_EQ(pieces.size(), 1U);
  EXPECT_EQ(pieces[0], square);
  EXPECT_EQ(points.size(), 4U);
  // x >= 1, y >= 1 and x + y <= 2 each cut it, but meet only in the point
  // (1, 1): the piece stays whole.
  const std::vector<cvms::detail::ClipPlane> point = {
      clip_plane(store, {-1, 0, 0}, -1), clip_plane(store, {0, -1, 0}, -1), clip_plane(store, {1, 1, 0}, 2)};
  cvms::detail::subtract_region(points, pieces, point);
  ASSERT_EQ(pieces.size(), 1U);
  EXPECT_EQ(pieces[0], square);
}

// The facets of Q that the region C_Q of covering_region.hpp is made of, by
// its definition with plain Rational arithmetic on every vertex: with Q
// crossing the plane, or with a facet on it (Q on the outer side, or on
// the inner side and before P), the facets with corners strictly on both
// sides or two or more corners, but not all, on the plane; else none
// (nothing when C_Q is empty).
std::optional<std::vector<std::uint32_t>> region_by_definition(const ConvexPolyhedron& q, const Vec3& normal,
                                                              const Rational& offset, bool q_before_p) {
  const cvms::Mesh& mesh = q.mesh();
  std::vector<int> sides;
  for (cvms::VertexId v : mesh.vertices()) sides.push_back(cmp(dot(normal, q.vertex(v)), offset));
  const bool outer = std::any_of(sides.begin(), sides.end(), [](int s) { return s > 0; });
  const bool inner = std::any_of(sides.begin(), sides.end(), [](int s) { return s < 0; });
  const auto on = static_cast<std::size_t>(std::count(sides.begin(), sides.end(), 0));
  if (!(outer && inner) && !(on >= 3 && (outer || q_before_p))) return std::nullopt;
  std::vector<std::uint32_t> facets;
  for (cvms::FaceId f : mesh.faces()) {
    bool out = false, in = false;
    std::size_t zeros = 0, corners = 0;
    for (cvms::HalfedgeId h : mesh.face_halfedges(f)) {
      const int s = sides[mesh.to(h).index()];
      out = out || s > 0;
      in = in || s < 0;
      zeros += s == 0 ? 1 : 0;
      ++corners;
    }
    if ((out && in) || (zeros >= 2 && zeros < corners)) facets.push_back(f.index());
  }
  return facets;
}

// The directions of Q's facets, edges and vertices: each facet's normal,
// and the sums of the normals of the facets at each edge and at each vertex
// (inside the edge's or vertex's normal cone, so the supporting plane in
// that direction touches Q in just that edge or vertex).
std::vector<Vec3> face_directions(const cvms::detail::PieceGeometry& geometry) {
  const cvms::Mesh& mesh = geometry.piece->mesh();
  auto normal = [&](cvms::HalfedgeId h) { return *geometry.planes[mesh.face(h).index()].normal; };
  std::vector<Vec3> directions;
  for (const cvms::detail::ClipPlane& plane : geometry.planes) directions.push_back(*plane.normal);
  for (cvms::FaceId f : mesh.faces())
    for (cvms::HalfedgeId h : mesh.face_halfedges(f)) directions.push_back(normal(h) + normal(cvms::Mesh::twin(h)));
  for (cvms::VertexId v : mesh.vertices()) {
    Vec3 sum{0, 0, 0};
    for (cvms::HalfedgeId h : mesh.outgoing_halfedges(v)) sum += normal(h);
    directions.push_back(sum);
  }
  return directions;
}

TEST(CoveringRegion, AgreesWithItsDefinition) {
  // Every facet, edge and vertex direction of Q, both ways, with the plane
  // through each vertex of Q (so through its facets, edges and vertices,
  // crossing Q or touching it) and, for facet normals, just beside it.
  for (const ConvexPolyhedron& q : {cvms::shapes::geodesic_sphere(1), cvms::shapes::truncated_cube(),
                                    cvms::shapes::random_hull(7, 30), cvms::shapes::prism(7, 2)}) {
    const cvms::detail::PieceGeometry geometry = cvms::detail::piece_geometry(q);
    const std::vector<Vec3> directions = face_directions(geometry);
    std::vector<cvms::Sign> sides;
    cvms::detail::SectionScratch section;
    section.start.assign(1, 0);
    std::vector<cvms::detail::ClipPlane> region;
    std::deque<TestPlane> store;
    for (std::size_t d = 0; d < directions.size(); ++d) {
      for (const int way : {1, -1}) {
        const Vec3 normal = directions[d] * Rational(way);
        for (cvms::VertexId v : q.mesh().vertices()) {
          for (const Rational& shift : {Rational(0), Rational(1, 1000)}) {
            if (shift != 0 && d >= geometry.planes.size()) continue;
            const Rational offset = dot(normal, q.vertex(v)) + shift;
            const cvms::detail::ClipPlane plane = clip_plane(store, normal, offset);
            for (const bool before : {false, true}) {
              const auto expected = region_by_definition(q, normal, offset, before);
              const bool found = cvms::detail::covering_region(geometry, 0, before, plane, sides, section, region);
              ASSERT_EQ(found, expected.has_value()) << "direction " << d << " way " << way << " vertex " << v.index();
              std::vector<std::uint32_t> facets;
              for (const cvms::detail::ClipPlane& r : region)
                facets.push_back(static_cast<std::uint32_t>(r.normal - geometry.planes[0].normal));
              if (expected) {
                EXPECT_EQ(facets, *expected) << "direction " << d << " way " << way << " vertex " << v.index();
              }
            }
          }
        }
      }
    }
  }
}

// section_through_vertex against the definition (region_by_definition) on
// planes through each vertex of Q that cut through Q: random small integer
// normals, which often run along Q's edges or hold other vertices (a grid
// polytope and a prism have many on one plane), and the directions of Q's
// own facets, edges and vertices.
TEST(CoveringRegion, SectionThroughAVertexFindsEveryFacetItMeets) {
  const std::uint64_t seed = 41;
  cvms::test::Rng rng(seed);
  for (const ConvexPolyhedron& q : {cvms::shapes::geodesic_sphere(1), cvms::shapes::truncated_cube(),
                                    cvms::shapes::random_hull(7, 30), cvms::shapes::prism(7, 2),
                                    box(0, 0, 0, 2, 3, 5)}) {
    const cvms::detail::PieceGeometry geometry = cvms::detail::piece_geometry(q);
    std::vector<Vec3> directions = face_directions(geometry);
    for (int i = 0; i < 60; ++i) {
      directions.push_back({static_cast<long>(rng() % 5) - 2, static_cast<long>(rng() % 5) - 2,
                            static_cast<long>(rng() % 5) - 2});
    }
    cvms::detail::SectionScratch section;
    section.start.assign(1, 0);
    std::deque<TestPlane> store;
    int crossings = 0;
    for (std::size_t d = 0; d < directions.size(); ++d) {
      if (directions[d] == Vec3{0, 0, 0}) continue;
      for (cvms::VertexId v : q.mesh().vertices()) {
        const Rational offset = dot(directions[d], q.vertex(v));
        const auto expected = region_by_definition(q, directions[d], offset, false);
        const cvms::detail::ClipPlane plane = clip_plane(store, directions[d], offset);
        (void)cvms::detail::walk_section(geometry, 0, plane, section);  // the walk the function follows
        bool outer = false;
        bool inner = false;
        for (cvms::VertexId u : q.mesh().vertices()) {
          const int c = cmp(dot(directions[d], q.vertex(u)), offset);
          outer = outer || c > 0;
          inner = inner || c < 0;
        }
        if (!(outer && inner)) continue;
        ++crossings;
        cvms::detail::section_through_vertex(geometry, v, plane, section);
        ASSERT_TRUE(expected.has_value());
        ASSERT_EQ(section.facets, *expected)
            << "seed " << seed << ", direction " << d << ", vertex " << v.index();
      }
    }
    EXPECT_GT(crossings, 50);
  }
}

// box_strictly_inside and box_strictly_outside against their definitions
// by plain Rational arithmetic: every
// point of the box strictly inside iff the greatest dot(normal, x) over the
// box's eight corners is below the offset, strictly outside iff the least
// is above it. They may answer false when it holds (the filter could not
// prove it), never true when it fails: planes through the box's farthest
// and nearest corners exactly (the degenerate cases), a hair beyond them
// (10^-30), and anywhere; boxes flat in some coordinate; small and long
// integer normals, some with zero coordinates. Planes well clear of a box
// of moderate size must be proven; a box infinite in one direction only on
// the planes that it lies inside.
TEST(CoveringRegion, BoxSidesOnlyWhenEveryPointIsThere) {
  for (const std::uint64_t seed : {31U, 32U, 33U}) {
    cvms::test::Rng rng(seed);
    std::deque<TestPlane> store;
    int proven = 0;
    for (int i = 0; i < 400; ++i) {
      cvms::unions::OutwardBox box;
      for (std::size_t k = 0; k < 3; ++k) {
        const double a = cvms::test::random_uniform(rng, -10, 10);
        const double b = rng() % 5 == 0 ? a : cvms::test::random_uniform(rng, -10, 10);
        box.lo[k] = std::min(a, b);
        box.hi[k] = std::max(a, b);
      }
      const unsigned bits = rng() % 2 == 0 ? 4 : 70;
      Vec3 normal;
      for (int k = 0; k < 3; ++k)
        normal[k] = rng() % 6 == 0 ? Rational(0) : Rational(cvms::test::random_integer(rng, bits));
      if (normal == Vec3{0, 0, 0}) continue;
      Rational highest;
      Rational lowest;
      for (unsigned c = 0; c < 8; ++c) {
        Vec3 corner;
        for (unsigned k = 0; k < 3; ++k)
          corner[static_cast<int>(k)] = Rational(((c >> k) & 1U) != 0 ? box.hi[k] : box.lo[k]);
        const Rational value = dot(normal, corner);
        if (c == 0 || value > highest) highest = value;
        if (c == 0 || value < lowest) lowest = value;
      }
      const Rational spread = abs(normal.x) + abs(normal.y) + abs(normal.z);
      const Rational hair = cvms::test::power_of_ten(-30);
      const std::vector<Rational> offsets = {highest, highest + hair, lowest, lowest - hair, highest + spread,
                                             lowest - spread,
                                             Rational(cvms::test::random_uniform(rng, -30, 30)) * spread};
      for (const Rational& offset : offsets) {
        const cvms::detail::ClipPlane plane = clip_plane(store, normal, offset);
        const bool inside = cvms::detail::box_strictly_inside(box, plane);
        const bool outside = cvms::detail::box_strictly_outside(box, plane);
        if (inside) {
          ASSERT_LT(highest, offset) << "seed " << seed << ", case " << i;
        }
        if (outside) {
          ASSERT_GT(lowest, offset) << "seed " << seed << ", case " << i;
        }
        if (offset == highest + spread) {
          ASSERT_TRUE(inside) << "seed " << seed << ", case " << i;
        }
        if (offset == lowest - spread) {
          ASSERT_TRUE(outside) << "seed " << seed << ", case " << i;
        }
        proven += (inside ? 1 : 0) + (outside ? 1 : 0);
      }
    }
    EXPECT_GT(proven, 800) << "seed " << seed;
  }
  cvms::unions::OutwardBox unbounded;
  unbounded.lo = {-std::numeric_limits<double>::infinity(), 0, 0};
  unbounded.hi = {0, 1, 1};
  std::deque<TestPlane> store;
  // x reaches -infinity: x <= 1 holds everywhere, -x <= 1 and x >= -1 do not.
  EXPECT_TRUE(cvms::detail::box_strictly_inside(unbounded, clip_plane(store, {1, 0, 0}, 1)));
  EXPECT_FALSE(cvms::detail::box_strictly_inside(unbounded, clip_plane(store, {-1, 0, 0}, 1)));
  EXPECT_FALSE(cvms::detail::box_strictly_outside(unbounded, clip_plane(store, {1, 0, 0}, -1)));
}

TEST(BoundaryFragments, CubeAlone) {
  const ConvexUnion u({box(0, 0, 0, 1, 2, 3)});
  const BoundaryFragments b = fragments_of(u);
  EXPECT_EQ(b.planes.size(), 6U);
  EXPECT_EQ(b.fragments.size(), 6U);
  EXPECT_TRUE(fragment_invariants(b));
  const auto areas = axis_areas(b);
  EXPECT_EQ(areas.at("-x=0"), 6);
  EXPECT_EQ(areas.at("+x=1"), 6);
  EXPECT_EQ(areas.at("-y=0"), 3);
  EXPECT_EQ(areas.at("+y=2"), 3);
  EXPECT_EQ(areas.at("-z=0"), 2);
  EXPECT_EQ(areas.at("+z=3"), 2);
}

TEST(BoundaryFragments, SharedFaceDisappears) {
  const ConvexUnion u({box(0, 0, 0, 1, 1, 1), box(1, 0, 0, 2, 1, 1)});
  const BoundaryFragments b = fragments_of(u);
  EXPECT_TRUE(fragment_invariants(b));
  const auto areas = axis_areas(b);
  const std::map<std::string, Rational> expected = {{"-x=0", 1}, {"+x=2", 1}, {"-y=0", 2}, {"+y=1", 2},
                                                    {"-z=0", 2}, {"+z=1", 2}};
  EXPECT_EQ(areas, expected);
  EXPECT_EQ(b.fragments.size(), 10U);
}

TEST(BoundaryFragments, OverlappingByHalf) {
  const ConvexUnion u({box(0, 0, 0, 2, 2, 2), box(1, 0, 0, 3, 2, 2)});
  const BoundaryFragments b = fragments_of(u);
  EXPECT_TRUE(fragment_invariants(b));
  const std::map<std::string, Rational> expected = {{"-x=0", 4}, {"+x=3", 4}, {"-y=0", 6}, {"+y=2", 6},
                                                    {"-z=0", 6}, {"+z=2", 6}};
  EXPECT_EQ(axis_areas(b), expected);
  expect_points_agree(u, b, 11, 5);
}

TEST(BoundaryFragments, NestedCubeLeavesNothing) {
  for (int order = 0; order < 2; ++order) {
    std::vector<ConvexPolyhedron> pieces = {box(0, 0, 0, 4, 4, 4), box(1, 1, 1, 2, 2, 2)};
    if (order == 1) std::swap(pieces[0], pieces[1]);
    expect_fragments(ConvexUnion(pieces), 6, 96);
  }
}

TEST(BoundaryFragments, NestedTouchingTheBoundary) {
  // The small cube shares a corner region of three faces with the big one.
  const ConvexUnion u({box(0, 0, 0, 1, 1, 1), box(0, 0, 0, 4, 4, 4)});
  const BoundaryFragments b = fragments_of(u);
  EXPECT_TRUE(fragment_invariants(b));
  EXPECT_EQ(total_area(axis_areas(b)), 96);
  expect_points_agree(u, b, 12, 5);
}

TEST(BoundaryFragments, EqualCubesKeptOnce) {
  expect_fragments(ConvexUnion({box(0, 0, 0, 1, 1, 1), box(0, 0, 0, 1, 1, 1), box(0, 0, 0, 1, 1, 1)}), 6, 6);
}

TEST(BoundaryFragments, TouchingAlongAnEdgeOrAtAVertex) {
  for (const int z : {0, 1}) {
    // z = 0: the cubes meet along the edge x = y = 1; z = 1: at the vertex (1, 1, 1).
    expect_fragments(ConvexUnion({box(0, 0, 0, 1, 1, 1), box(1, 1, z, 2, 2, z + 1)}), 12, 12);
  }
}

TEST(BoundaryFragments, CoplanarFacetsFacingTheSameWayKeptOnce) {
  const ConvexUnion u({box(0, 0, 0, 2, 2, 1), box(1, 1, 0, 3, 3, 1)});
  const BoundaryFragments b = fragments_of(u);
  EXPECT_TRUE(fragment_invariants(b));
  const std::map<std::string, Rational> expected = {
      {"-x=0", 2}, {"+x=2", 1}, {"-x=1", 1}, {"+x=3", 2}, {"-y=0", 2}, {"-y=1", 1},
      {"+y=2", 1}, {"+y=3", 2}, {"-z=0", 7}, {"+z=1", 7}};
  EXPECT_EQ(axis_areas(b), expected);
  expect_points_agree(u, b, 13, 8);
}

TEST(BoundaryFragments, FacingFacetsCancel) {
  // A slab on top of a plate, sharing part of a plane: the shared part is
  // inside, the rest of both facets stays.
  const ConvexUnion u({box(0, 0, 0, 3, 3, 1), box(1, 1, 1, 2, 2, 2)});
  const BoundaryFragments b = fragments_of(u);
  EXPECT_TRUE(fragment_invariants(b));
  const auto areas = axis_areas(b);
  EXPECT_EQ(areas.at("+z=1"), 8);
  EXPECT_EQ(areas.count("-z=1"), 0U);
  EXPECT_EQ(areas.at("+z=2"), 1);
  EXPECT_EQ(total_area(areas), 18 + 12 + 4 + 1 - 1);
  expect_points_agree(u, b, 14, 8);
}

TEST(BoundaryFragments, TiltedPiecesAgreeWithPoints) {
  // An octahedron through a cube: planes in general position.
  const ConvexUnion u({box(-1, -1, -1, 1, 1, 1), cvms::shapes::octahedron().transformed(
                                                      cvms::Mat3::identity(), Vec3{Rational(1, 2), 0, 1})});
  const BoundaryFragments b = fragments_of(u);
  EXPECT_TRUE(fragment_invariants(b));
  expect_points_agree(u, b, 15, 10);
}

TEST(BoundaryFragments, RandomUnionsAgreeWithPoints) {
  for (const std::uint64_t seed : {1U, 2U, 3U}) {
    const ConvexUnion u = cvms::test::random_union(seed, 12, 4, 6);
    const BoundaryFragments b = fragments_of(u);
    EXPECT_TRUE(fragment_invariants(b)) << "seed " << seed;
    expect_points_agree(u, b, seed, 3);
  }
}

TEST(BoundaryFragments, ShearedRandomUnionAgreesWithPoints) {
  // An affine image keeps every coincidence of the random union (shared
  // planes, touching edges) on planes of general direction with rational
  // offsets.
  cvms::Mat3 shear = cvms::Mat3::identity();
  shear.m[0][1] = Rational(1, 3);
  shear.m[1][2] = Rational(-2, 7);
  shear.m[2][0] = Rational(1, 5);
  const Vec3 shift{Rational(1, 10), Rational(-3, 4), Rational(2, 9)};
  for (const std::uint64_t seed : {6U, 7U}) {
    const ConvexUnion straight = cvms::test::random_union(seed, 10, 4, 6);
    std::vector<ConvexPolyhedron> pieces;
    for (const ConvexPolyhedron& p : straight.pieces())
      pieces.push_back(p.transformed(shear, shift));
    const ConvexUnion u(std::move(pieces));
    const BoundaryFragments b = fragments_of(u);
    EXPECT_TRUE(fragment_invariants(b)) << "seed " << seed;
    expect_points_agree(u, b, seed, 3);
  }
}

TEST(BoundaryFragments, SameForOneAndTwoThreads) {
  const ConvexUnion u = cvms::test::random_union(4, 40, 8, 6);
  const BoundaryFragments one = fragments_of(u, 1);
  const BoundaryFragments two = fragments_of(u, 2);
  ASSERT_EQ(one.planes.size(), two.planes.size());
  for (std::size_t i = 0; i < one.planes.size(); ++i) {
    EXPECT_EQ(one.planes[i].normal, two.planes[i].normal);
    EXPECT_EQ(one.planes[i].offset, two.planes[i].offset);
  }
  ASSERT_EQ(one.fragments.size(), two.fragments.size());
  for (std::size_t i = 0; i < one.fragments.size(); ++i) {
    EXPECT_EQ(one.fragments[i].plane, two.fragments[i].plane);
    EXPECT_EQ(one.fragments[i].corners, two.fragments[i].corners);
  }
}

TEST(BoundaryFragments, ReportsAndCancels) {
  const ConvexUnion u = cvms::test::random_union(5, 20, 8, 6);
  for (const unsigned threads : {1U, 2U}) {
    cvms::Options options;
    options.threads = threads;
    std::vector<std::string> stages;
    options.progress = [&](const cvms::Progress& p) {
      stages.emplace_back(p.stage);
      return true;
    };
    (void)cvms::detail::union_boundary_fragments(u.pieces(), options);
    ASSERT_FALSE(stages.empty());
    EXPECT_EQ(stages.front(), "union: boundary");
    int calls = 0;
    options.progress = [&](const cvms::Progress&) { return ++calls < 3; };
    try {
      (void)cvms::detail::union_boundary_fragments(u.pieces(), options);
      ADD_FAILURE() << "not cancelled, threads " << threads;
    } catch (const cvms::Error& e) {
      EXPECT_EQ(e.category(), cvms::ErrorCategory::cancelled);
    }
  }
}

TEST(BoundaryFragments, MemoryLimit) {
  // Six facets of four corners each already pass 20 corners' worth.
  const ConvexUnion u({box(0, 0, 0, 1, 1, 1), box(1, 0, 0, 2, 1, 1)});
  for (const unsigned threads : {1U, 2U}) {
    cvms::Options options;
    options.threads = threads;
    options.limits.max_memory_bytes = 20 * 256;
    try {
      (void)cvms::detail::union_boundary_fragments(u.pieces(), options);
      ADD_FAILURE() << "no limit error, threads " << threads;
    } catch (const cvms::Error& e) {
      EXPECT_EQ(e.category(), cvms::ErrorCategory::limit);
      EXPECT_NE(std::string(e.message()).find("max_memory_bytes"), std::string::npos) << e.message();
    }
    options.limits.max_memory_bytes = 1000 * 256;
    EXPECT_EQ(cvms::detail::union_boundary_fragments(u.pieces(), options).fragments.size(), 10U);
  }
}

TEST(BoundaryFragments, EmptyPieceIsRefused) {
  const std::vector<ConvexPolyhedron> pieces = {box(0, 0, 0, 1, 1, 1), ConvexPolyhedron()};
  try {
    (void)cvms::detail::union_boundary_fragments(pieces, cvms::Options{});
    ADD_FAILURE() << "accepted an empty piece";
  } catch (const cvms::Error& e) {
    EXPECT_EQ(e.category(), cvms::ErrorCategory::invalid_argument);
    EXPECT_NE(std::string(e.message()).find("piece 1"), std::string::npos) << e.message();
  }
}

}  // namespace
