// SPDX-License-Identifier: MIT
// Tests of the facet constructions and the stitching by vertex pair, checked
// with plain rational arithmetic and hand-made sums.
#include "stitch.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <system_error>
#include <thread>

#include "cvms/convex_hull.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/shapes.hpp"
#include "cvms_algorithm.hpp"
#include "packed_vectors.hpp"
#include "polyhedron_builder.hpp"
#include "research_options.hpp"
#include "support/oracle.hpp"
#include "support/under_sanitizer.hpp"

namespace cvms::detail {
namespace {

Mat3 scaling(const Rational& s) {
  Mat3 m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m.m[i][j] = i == j ? s : Rational(0);
  return m;
}

Vec3 point(const ConvexPolyhedron& a, const ConvexPolyhedron& b, VertexPair p) {
  return a.vertex(VertexId(p.a)) + b.vertex(VertexId(p.b));
}

// The normal of a polygon by Newell's rule in rationals (its direction is the
// counterclockwise normal).
Vec3 polygon_normal(const std::vector<Vec3>& pts) {
  Vec3 n{0, 0, 0};
  for (std::size_t i = 0; i < pts.size(); ++i) n += cross(pts[i], pts[(i + 1) % pts.size()]);
  return n;
}

// The output's cached approximations (derived from the inputs' by TwoSum,
// not from the exact output) must bound the exact coordinates, and the plane
// data must be exact: checked in rationals on sums whose coordinates are
// doubles (TwoSum path), near-double and non-double (fallback paths).
TEST(Stitch, OutputApproximationsAndPlanesAreExact) {
  const ConvexPolyhedron third = shapes::cube().transformed(scaling(Rational(1, 3)), Vec3{0, 0, 0});
  const ConvexPolyhedron tiny = shapes::cube().transformed(
      scaling(Rational(mpz_class(1), mpz_class(1) << 1000)), Vec3{Rational(1), 0, 0});
  const std::pair<ConvexPolyhedron, ConvexPolyhedron> cases[] = {
      {shapes::geodesic_sphere(3), shapes::rotated_geodesic_sphere(3)},
      {shapes::geodesic_sphere(2), third},
      {shapes::geodesic_sphere(2), tiny}};
  for (const auto& [a, b] : cases) {
    const ConvexPolyhedron s = minkowski_sum(a, b).polyhedron;
    for (VertexId v : s.mesh().vertices()) {
      const Vec3& x = s.vertex(v);
      const ApproxVec3& ax = detail::vertex_approx(s, v);
      const Approx* parts[3] = {&ax.x, &ax.y, &ax.z};
      for (int i = 0; i < 3; ++i)
        ASSERT_LE(abs(Rational(parts[i]->value) - x[i]), Rational(parts[i]->error)) << "vertex " << v.index();
    }
    for (FaceId f : s.mesh().faces()) {
      const Vec3& n = s.normal(f);
      for (HalfedgeId h : s.mesh().face_halfedges(f))
        ASSERT_EQ(dot(n, s.vertex(s.mesh().from(h))), s.plane_offset(f)) << "facet " << f.index();
    }
    EXPECT_TRUE(s.is_convex()) << "case " << (&a - &cases[0].first);
  }
}

// Operands of decimals or small rationals give a sum whose vertices are
// integers over one denominator (scaled_points.hpp); operands of doubles
// keep the packed dyadic vertices. The values are the exact pairwise sums.
TEST(Stitch, DecimalOperandsGiveScaledVertices) {
  const ConvexPolyhedron third = shapes::cube().transformed(scaling(Rational(1, 3)), Vec3{0, 0, 0});
  std::vector<Vec3> six_digits;  // a sphere's vertices with 6 decimals, as scanners write them
  const ConvexPolyhedron round = shapes::geodesic_sphere(2);
  for (const Vec3& v : round.mesh().positions()) {
    Vec3& w = six_digits.emplace_back();
    for (int k = 0; k < 3; ++k) w[k] = Rational(std::lround(v[k].get_d() * 1e6), 1000000);
    for (int k = 0; k < 3; ++k) w[k].canonicalize();
  }
  const ConvexPolyhedron tenth = convex_hull(six_digits);
  const ConvexPolyhedron sphere = shapes::rotated_geodesic_sphere(2);
  const auto kept_scaled = [](const ConvexPolyhedron& p) {
    const MeshAccess::Storage* s = MeshAccess::storage(p.mesh());
    return s != nullptr && s->packed_positions != nullptr && s->packed_positions->is_scaled();
  };
  for (unsigned threads : {1u, 2u}) {
    SCOPED_TRACE(threads);
    Options options;
    options.threads = threads;
    EXPECT_TRUE(kept_scaled(minkowski_sum(third, tenth, options).polyhedron));
    EXPECT_TRUE(kept_scaled(minkowski_sum(tenth, sphere, options).polyhedron) ||
                PolyhedronAccess::scaled_vertices(sphere) == nullptr);
    EXPECT_FALSE(kept_scaled(minkowski_sum(sphere, shapes::geodesic_sphere(2), options).polyhedron));
    const ConvexPolyhedron s = minkowski_sum(third, tenth, options).polyhedron;
    const std::vector<Vec3> expected = test::pairwise_sums(third.mesh().positions(), tenth.mesh().positions());
    for (VertexId v : s.mesh().vertices())
      ASSERT_NE(std::find(expected.begin(), expected.end(), s.vertex(v)), expected.end()) << v.index();
  }
}

bool same_approximations(const ApproxVec3& x, const ApproxVec3& y) {
  const auto same = [](const Approx& a, const Approx& b) { return a.value == b.value && a.error == b.error; };
  return same(x.x, y.x) && same(x.y, y.y) && same(x.z, y.z);
}

// Options::threads = 2, 4, 8 build the same polyhedron (numbering and
// cached approximations included) on workers plus the caller as one thread,
// and it equals CHMS's, the independent oracle. The search runs 4 and 8
// threads whatever the cores (oversubscribe) and the size of the sum; the
// output build uses two.
void expect_threads_build_the_same(const ConvexPolyhedron& a, const ConvexPolyhedron& b) {
  const ConvexPolyhedron one_thread = minkowski_sum(a, b).polyhedron;
  const PolygonSoup one_soup = one_thread.to_soup();
  Options chms;
  chms.algorithm = Algorithm::chms;
  EXPECT_EQ(test::describe(one_thread), test::describe(minkowski_sum(a, b, chms).polyhedron));
  for (const unsigned n : {2u, 4u, 8u}) {
    SCOPED_TRACE(std::to_string(n) + " threads");
    Options options;
    options.threads = n;
    detail::ResearchOptions research;
    research.worker_minimums = {0, 0, true};  // workers however small the sum
    const ConvexPolyhedron threaded = detail::minkowski_sum(a, b, options, research).polyhedron;
    const PolygonSoup soup = threaded.to_soup();
    ASSERT_EQ(soup.points, one_soup.points);
    ASSERT_EQ(soup.face_offsets, one_soup.face_offsets);
    ASSERT_EQ(soup.face_indices, one_soup.face_indices);
    for (FaceId f : one_thread.mesh().faces()) {
      ASSERT_EQ(threaded.normal(f), one_thread.normal(f));
      ASSERT_EQ(threaded.plane_offset(f), one_thread.plane_offset(f));
      ASSERT_TRUE(same_approximations(normal_ref(threaded, f).approx, normal_ref(one_thread, f).approx))
          << "facet " << f.index();
    }
    // One thread's approximations bound the exact values
    // (OutputApproximationsAndPlanesAreExact); equal ones do too.
    for (VertexId v : one_thread.mesh().vertices())
      ASSERT_TRUE(same_approximations(vertex_approx(threaded, v), vertex_approx(one_thread, v)))
          << "vertex " << v.index();
    EXPECT_TRUE(threaded.is_convex());
  }
}

// These sums number their vertices with the dense pair table.
TEST(Stitch, ThreadsBuildTheSamePolyhedron) {
  const std::pair<ConvexPolyhedron, ConvexPolyhedron> cases[] = {
      {shapes::geodesic_sphere(3), shapes::rotated_geodesic_sphere(3)},
      {shapes::cube(), shapes::geodesic_sphere(3)},
      {shapes::truncated_cube(), shapes::tetrahedron()}};
  for (const auto& [a, b] : cases) expect_threads_build_the_same(a, b);
}

#ifndef CVMS_TEST_UNDER_SANITIZER
// Caps this process's address space a little above what it maps now: too
// little for a thread's stack (8 MiB by default), enough for a small sum.
void cap_address_space_below_a_thread_stack() {
  std::ifstream statm("/proc/self/statm");
  std::size_t pages = 0;
  statm >> pages;
  const auto cap =
      static_cast<rlim_t>(pages * static_cast<std::size_t>(sysconf(_SC_PAGESIZE)) + (std::size_t{7} << 20));
  const rlimit limit{cap, cap};
  if (setrlimit(RLIMIT_AS, &limit) != 0) _exit(3);
}

// Whether the system now refuses to start a thread.
bool threads_are_refused() {
  try {
    std::thread([] {}).join();
    return false;
  } catch (const std::system_error&) {
    return true;
  }
}
#endif

// When the system refuses a thread, a sum asked for two threads (its edge
// trace and its output build each start a worker) is found and built on
// one: the same polyhedron, not a std::system_error. A child process caps
// its address space so that no thread stack fits, checks that a thread is
// indeed refused, sums, and compares with the one-thread sum made before.
TEST(Stitch, RefusedThreadsBuildOnOneThread) {
#ifdef CVMS_TEST_UNDER_SANITIZER
  GTEST_SKIP() << "the sanitizers reserve address space of their own";
#else
  const ConvexPolyhedron a = shapes::geodesic_sphere(3);
  const ConvexPolyhedron b = shapes::rotated_geodesic_sphere(3);
  const PolygonSoup expected = minkowski_sum(a, b).polyhedron.to_soup();
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    cap_address_space_below_a_thread_stack();
    if (!threads_are_refused()) _exit(3);
    try {
      Options options;
      options.threads = 2;
      detail::ResearchOptions research;
      research.worker_minimums = {0, 0, true};  // workers however small the sum
      const PolygonSoup got = detail::minkowski_sum(a, b, options, research).polyhedron.to_soup();
      const bool same = got.points == expected.points && got.face_offsets == expected.face_offsets &&
                        got.face_indices == expected.face_indices;
      _exit(same ? 0 : 1);
    } catch (const std::system_error&) {
      _exit(2);
    } catch (...) {
      _exit(4);
    }
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << "the child did not exit (signal " << WTERMSIG(status) << ")";
  if (WEXITSTATUS(status) == 3) GTEST_SKIP() << "could not make the system refuse a thread";
  EXPECT_NE(WEXITSTATUS(status), 1) << "a different polyhedron on one thread";
  EXPECT_NE(WEXITSTATUS(status), 2) << "std::system_error escaped";
  EXPECT_NE(WEXITSTATUS(status), 4) << "another exception escaped (the cap too low for the sum?)";
  EXPECT_EQ(WEXITSTATUS(status), 0);
#endif
}

// Sphere4 + rotated Sphere4 has 642^2 vertex pairs, past the dense table's
// limit: the threads share vertices numbered by sorting.
TEST(Stitch, ThreadsBuildTheSamePolyhedronWithSortedNumbering) {
  expect_threads_build_the_same(shapes::geodesic_sphere(4), shapes::rotated_geodesic_sphere(4));
}

TEST(Stitch, FacetPlusFacetGivesTheDoubledShapeDenseAndHashed) {
  // Dense pair table for the cube, hash map for Sphere4 (642^2 pairs).
  for (const auto& p : {shapes::cube(), shapes::geodesic_sphere(4)}) {
    SumFacetBuilder out(p, p);
    for (FaceId f : p.mesh().faces()) out.add_facet_plus_facet(f, f);
    const ConvexPolyhedron s = out.build();
    EXPECT_EQ(test::check_invariants(s), "");
    EXPECT_TRUE(test::describe(s) == test::describe(p.transformed(scaling(2), {})));
  }
}

TEST(Stitch, FacetPlusEdgeIsTheCounterclockwiseHexagon) {
  // Top facet of the cube (z = 1) plus the octahedron edge from (1,0,0) to
  // (0,1,0), which is parallel to it: a hexagon.
  const auto c = shapes::cube();
  const auto o = shapes::octahedron();
  FaceId top;
  for (FaceId f : c.mesh().faces())
    if (c.normal(f) == Vec3{0, 0, 1}) top = f;
  VertexId x;
  VertexId y;
  for (VertexId v : o.mesh().vertices()) {
    if (o.vertex(v) == Vec3{1, 0, 0}) x = v;
    if (o.vertex(v) == Vec3{0, 1, 0}) y = v;
  }
  ASSERT_TRUE(top.is_valid() && x.is_valid() && y.is_valid());
  for (Operand which : {Operand::a, Operand::b}) {
    SumFacetBuilder out(which == Operand::a ? c : o, which == Operand::a ? o : c);
    const ConvexPolyhedron& a = which == Operand::a ? c : o;
    const ConvexPolyhedron& b = which == Operand::a ? o : c;
    out.add_facet_plus_edge(which, top, x, y);
    ASSERT_EQ(out.num_facets(), 1u);
    std::vector<Vec3> pts;
    for (VertexPair p : out.facet(0)) pts.push_back(point(a, b, p));
    const std::set<Vec3> expected = {{0, -1, 1}, {2, -1, 1}, {2, 1, 1}, {1, 2, 1}, {-1, 2, 1}, {-1, 0, 1}};
    EXPECT_EQ(std::set<Vec3>(pts.begin(), pts.end()), expected);
    ASSERT_EQ(pts.size(), 6u);
    const Vec3 n = polygon_normal(pts);
    EXPECT_GT(sgn(n.z), 0);
  }
}

TEST(Stitch, FacetPlusVertexAndEdgePlusEdgeOrientation) {
  const auto c = shapes::cube();
  const auto t = shapes::tetrahedron();
  SumFacetBuilder out(c, t);
  out.add_facet_plus_vertex(Operand::b, FaceId(0), VertexId(2));
  std::vector<Vec3> pts;
  for (VertexPair p : out.facet(0)) {
    EXPECT_EQ(p.a, 2u);
    pts.push_back(point(c, t, p));
  }
  EXPECT_GT(sgn(dot(polygon_normal(pts), t.normal(FaceId(0)))), 0);
  // e_A + e_B with both orientations.
  const HalfedgeId ha(0);
  const HalfedgeId hb(2);
  const Vec3 n = cross(c.edge_vector(ha), t.edge_vector(hb));
  ASSERT_FALSE(is_zero(n));
  out.add_edge_plus_edge(ha, hb, Sign::positive);
  out.add_edge_plus_edge(ha, hb, Sign::negative);
  for (std::size_t i : {1u, 2u}) {
    pts.clear();
    for (VertexPair p : out.facet(i)) pts.push_back(point(c, t, p));
    ASSERT_EQ(pts.size(), 4u);
    EXPECT_EQ(sgn(dot(polygon_normal(pts), n)), i == 1 ? 1 : -1);
  }
}

// Edge facets keep no corner pairs of their own (their corners follow from
// their halfedges): mixed with facets that do, appending a builder in pieces
// and building the soup must keep every facet's corners in place.
TEST(Stitch, EdgeFacetsKeepTheirCornersThroughAppendAndSoup) {
  const auto c = shapes::cube();
  const auto t = shapes::tetrahedron();
  SumFacetBuilder whole(c, t);
  whole.add_facet_plus_vertex(Operand::b, FaceId(0), VertexId(2));
  whole.add_edge_plus_edge(HalfedgeId(0), HalfedgeId(2), Sign::positive);
  whole.add_edge_plus_edge(HalfedgeId(4), HalfedgeId(3), Sign::negative);
  whole.add_facet_plus_vertex(Operand::a, FaceId(1), VertexId(0));
  whole.add_edge_plus_edge(HalfedgeId(6), HalfedgeId(1), Sign::positive);
  SumFacetBuilder pieces(c, t);
  pieces.append(whole, 0, 2);
  pieces.append(whole, 2, 5);
  ASSERT_EQ(pieces.num_facets(), whole.num_facets());
  const PolygonSoup soup = pieces.soup();
  ASSERT_EQ(soup.face_offsets.size(), whole.num_facets() + 1);
  for (std::size_t i = 0; i < whole.num_facets(); ++i) {
    const std::vector<VertexPair> expected = whole.facet(i);
    const std::vector<VertexPair> got = pieces.facet(i);
    ASSERT_EQ(got.size(), expected.size()) << "facet " << i;
    ASSERT_EQ(soup.face_offsets[i + 1] - soup.face_offsets[i], expected.size()) << "facet " << i;
    for (std::size_t k = 0; k < expected.size(); ++k) {
      EXPECT_EQ(got[k].a, expected[k].a);
      EXPECT_EQ(got[k].b, expected[k].b);
      // The soup's point is the exact sum of the pair's vertices.
      EXPECT_EQ(soup.points[soup.face_indices[soup.face_offsets[i] + k]], point(c, t, expected[k]))
          << "facet " << i << " corner " << k;
    }
  }
}

// build_mesh is the mesh build() makes, without planes: every facet's
// corners, up to where the cycle starts, must be the exact sums of its
// pairs' vertices (checked with plain rationals), on dyadic sums (packed
// points) and non-dyadic ones (the Vec3 fallback).
TEST(Stitch, BuildMeshHasTheFacetsCornersAsExactSums) {
  const ConvexPolyhedron third = shapes::cube().transformed(scaling(Rational(1, 3)), Vec3{0, 0, 0});
  const std::pair<ConvexPolyhedron, ConvexPolyhedron> cases[] = {
      {shapes::geodesic_sphere(3), shapes::rotated_geodesic_sphere(3)}, {shapes::geodesic_sphere(2), third}};
  for (const auto& [a, b] : cases) {
    SumCounters stats;
    const SumFacetBuilder facets = cvms_facets(a, b, Options{}, {}, stats);
    const PolygonSoup mesh = facets.build_mesh().to_soup();
    ASSERT_EQ(mesh.num_faces(), facets.num_facets());
    for (std::size_t i = 0; i < facets.num_facets(); ++i) {
      const std::vector<VertexPair> pairs = facets.facet(i);
      const std::uint32_t first = mesh.face_offsets[i];
      const std::size_t degree = mesh.face_offsets[i + 1] - first;
      ASSERT_EQ(degree, pairs.size()) << "facet " << i;
      std::size_t shift = 0;
      while (shift < degree && mesh.points[mesh.face_indices[first + shift]] != point(a, b, pairs[0])) ++shift;
      ASSERT_LT(shift, degree) << "facet " << i << " lacks its first corner";
      for (std::size_t k = 0; k < degree; ++k)
        EXPECT_EQ(mesh.points[mesh.face_indices[first + (shift + k) % degree]], point(a, b, pairs[k]))
            << "facet " << i << " corner " << k;
    }
  }
}

}  // namespace
}  // namespace cvms::detail
