// SPDX-License-Identifier: MIT
// The differential suite of minkowski_sum, written for CVMS (paper Section 4)
// and run for every algorithm (CVMS in its output-sensitive default mode and
// in the paper-faithful reference mode, ESSDMS, CHMS: TEST_P over Variant):
// exact equality with independent oracles (CHMS, brute-force hulls,
// hand-checked sums such as A + A = 2A and box + box), the invariants of every
// result, the paper's degenerate cases, arc geometry that stresses the slope
// diagrams of Section 5.2, and seeded random pairs. Every algorithm is
// compared with the same oracle, so all agree exactly on every case; on top
// of that, every CVMS case also checks that the two CVMS modes build the
// identical polyhedron (same vertices, same facets, same numbering, same
// facet counts). The pairs of this suite are also listed in
// support/differential_pairs.cpp, where other operations are checked on
// them (halfspaces_test): add a new pair there too.
#include "research_options.hpp"

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <ostream>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "cvms/error.hpp"
#include "cvms/minkowski.hpp"
#include "filtered_predicates.hpp"
#include "cvms/convex_hull.hpp"
#include "cvms/shapes.hpp"
#include "support/differential_pairs.hpp"
#include "support/hand_solids.hpp"
#include "support/minkowski_check.hpp"
#include "support/oracle.hpp"
#include "support/prism_attack.hpp"
#include "support/random_clouds.hpp"

namespace cvms {

namespace test {
// The user's options and CVMS's research switches (lib/minkowski/research_options.hpp).
struct SumOptions {
  Options options;
  detail::ResearchOptions research;
};

// check_sum of the support library with the research switches set.
std::string check_sum(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const Shape& expected,
                      const SumOptions& o, bool check_origins = true) {
  return check_sum(a, b, expected, o.options, check_origins, [&o](const ConvexPolyhedron& x, const ConvexPolyhedron& y) {
    return detail::minkowski_sum(x, y, o.options, o.research);
  });
}
}  // namespace test

// How gtest prints the parameter of a failing test (found by ADL).
void PrintTo(Algorithm a, std::ostream* os) { *os << to_string(a); }

namespace {

// An algorithm and, for CVMS, its mode: `reference` is the paper-faithful
// search (linear scans, horizon edges), otherwise the default walks.
struct Variant {
  Algorithm algorithm;
  bool reference = false;
};

std::string variant_name(Variant v) {
  return std::string(to_string(v.algorithm)) + (v.reference ? "_paper" : "");
}

test::SumOptions variant_options(Variant v) {
  test::SumOptions o;
  o.options.algorithm = v.algorithm;
  if (v.reference) o.research = detail::paper_search();
  return o;
}

// A sum with its diagnostic counters (Options::diagnostics).
struct CountedSum : MinkowskiResult {
  SumDiagnostics diagnostics;
};

CountedSum counted(const ConvexPolyhedron& a, const ConvexPolyhedron& b, Options options,
                   const detail::ResearchOptions& research = {}) {
  CountedSum r;
  options.diagnostics = &r.diagnostics;
  static_cast<MinkowskiResult&>(r) = detail::minkowski_sum(a, b, options, research);
  return r;
}

CountedSum sum_with(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const test::SumOptions& o) {
  return counted(a, b, o.options, o.research);
}

// "" iff x and y are the identical polyhedron (soup equality: positions,
// facet cycles, numbering; and planes) with the same facet counts.
std::string same_result(const CountedSum& x, const CountedSum& y, const std::string& what) {
  const PolygonSoup sx = x.polyhedron.to_soup();
  const PolygonSoup sy = y.polyhedron.to_soup();
  if (sx.points != sy.points) return what + " give different vertices";
  if (sx.face_offsets != sy.face_offsets || sx.face_indices != sy.face_indices)
    return what + " give different facets";
  for (FaceId f : x.polyhedron.mesh().faces())
    if (x.polyhedron.normal(f) != y.polyhedron.normal(f) ||
        x.polyhedron.plane_offset(f) != y.polyhedron.plane_offset(f))
      return what + " give different planes at facet " + std::to_string(f.index());
  const Stats &r = x.stats, &s = y.stats;
  if (r.translated_facets != s.translated_facets || r.corner_facets != s.corner_facets ||
      r.edge_facets != s.edge_facets || x.diagnostics.contributing_ties != y.diagnostics.contributing_ties)
    return what + " count facets differently";
  return "";
}

// CVMS (default mode) with Options::threads = n and the workers started
// however small the sum (minkowski_sum keeps small sums on one thread).
CountedSum with_workers_always(const ConvexPolyhedron& a, const ConvexPolyhedron& b, unsigned n) {
  Options options;
  options.threads = n;
  detail::ResearchOptions research;
  research.worker_minimums = {0, 0, true};
  return counted(a, b, options, research);
}

// Every counter, the search work included.
bool same_stats(const CountedSum& x, const CountedSum& y) {
  const auto fields = [](const CountedSum& r) {
    const Stats& s = r.stats;
    const SumDiagnostics& d = r.diagnostics;
    return std::array{s.translated_facets, s.corner_facets,         s.edge_facets,        d.contributing_ties,
                      d.edge_candidates,   d.edge_paper_rejections, d.predicate_filtered, d.predicate_exact};
  };
  return fields(x) == fields(y);
}

// The thread counts of the differential suite: 2 on this machine's cores,
// 4 and 8 oversubscribed, which shuffles the interleavings further.
constexpr unsigned thread_counts[] = {2, 4, 8};

// "" iff CVMS in the reference mode, in the default mode, and in the default
// mode with workers (Options::threads = each of `threads`) build the
// identical polyhedron with the same facet counts, for a + b. The threaded
// runs must also report the same search work (steps and predicate
// evaluations).
std::string cvms_modes_agree(const ConvexPolyhedron& a, const ConvexPolyhedron& b,
                             std::span<const unsigned> threads) {
  const CountedSum ref = sum_with(a, b, variant_options({Algorithm::cvms, true}));
  const CountedSum fast = sum_with(a, b, variant_options({Algorithm::cvms, false}));
  std::string why = same_result(ref, fast, "the two CVMS modes");
  for (const unsigned n : threads) {
    if (!why.empty()) break;
    const CountedSum threaded = with_workers_always(a, b, n);
    const std::string what = "one and " + std::to_string(n) + " threads";
    why = same_result(fast, threaded, what);
    if (why.empty() && !same_stats(fast, threaded)) why = what + " report different Stats";
  }
  return why;
}

Vec3 v3(const Rational& x, const Rational& y, const Rational& z) { return {x, y, z}; }

using test::flat_bipyramid;
using test::rotation_z_3_4_5;
using test::scaled;
using test::triangulated_cube;

ConvexPolyhedron hull(const std::vector<Vec3>& pts) { return convex_hull(pts); }

test::Shape shape_of(const ConvexPolyhedron& p) { return test::describe(p); }

std::vector<Vec3> points_of(const ConvexPolyhedron& p) { return p.mesh().positions(); }

// Brute-force oracle for small operands (independent of quickhull and CHMS).
test::Shape brute_force_sum(const ConvexPolyhedron& a, const ConvexPolyhedron& b) {
  const auto pa = points_of(a);
  const auto pb = points_of(b);
  return test::brute_force_hull(test::pairwise_sums(pa, pb));
}

CountedSum cvms_sum(const ConvexPolyhedron& a, const ConvexPolyhedron& b) { return counted(a, b, {}); }

// The suite keeps the name Cvms; the parameter is the algorithm under test.
class Cvms : public ::testing::TestWithParam<Variant> {
 protected:
  [[nodiscard]] static Algorithm algorithm() { return GetParam().algorithm; }
  [[nodiscard]] static test::SumOptions options() { return variant_options(GetParam()); }
  // The differential check between the CVMS modes runs once per case, in the
  // default-mode instance, with every thread count unless `threads` says.
  [[nodiscard]] static std::string modes_agree(const ConvexPolyhedron& a, const ConvexPolyhedron& b,
                                               std::span<const unsigned> threads = thread_counts) {
    if (algorithm() != Algorithm::cvms || GetParam().reference) return "";
    const std::string ab = cvms_modes_agree(a, b, threads);
    return ab.empty() ? cvms_modes_agree(b, a, threads) : ab;
  }
  // Shadows the free function: the algorithm under test.
  [[nodiscard]] static CountedSum cvms_sum(const ConvexPolyhedron& a, const ConvexPolyhedron& b) {
    return sum_with(a, b, options());
  }
  // CVMS and ESSDMS classify facets alike (translated, corner, edge) and
  // count ties alike; CHMS reports no such stats.
  [[nodiscard]] static bool counts_facets() { return algorithm() != Algorithm::chms; }
};

std::string param_name(const ::testing::TestParamInfo<Variant>& info) { return variant_name(info.param); }

INSTANTIATE_TEST_SUITE_P(AllAlgorithms, Cvms,
                         ::testing::Values(Variant{Algorithm::cvms, false}, Variant{Algorithm::cvms, true},
                                           Variant{Algorithm::essdms}, Variant{Algorithm::chms}),
                         param_name);

#define EXPECT_SUM(a, b, expected)                                   \
  do {                                                               \
    EXPECT_EQ(test::check_sum((a), (b), (expected), options()), ""); \
    EXPECT_EQ(modes_agree((a), (b)), "");                            \
  } while (false)

// The rhombic dodecahedron: 12 rhombi with normals (+-1, +-1, 0) and
// permutations. Every Gaussian arc of the cube passes through one of its
// facet normals.
ConvexPolyhedron rhombic_dodecahedron() { return hull(test::rhombic_dodecahedron_points()); }

// ---------------------------------------------------------------------------
// Hand-checked sums.

TEST_P(Cvms, CubePlusCubeIsTheDoubledCube) {
  const auto c = shapes::cube();
  EXPECT_SUM(c, c, shape_of(shapes::box(v3(-2, -2, -2), v3(2, 2, 2))));
  if (!counts_facets()) return;
  const auto r = cvms_sum(c, c);
  EXPECT_EQ(r.stats.translated_facets, 6u);
  EXPECT_EQ(r.stats.corner_facets, 0u);  // every facet of B is used with its partner (Property 2)
  EXPECT_EQ(r.stats.edge_facets, 0u);
  EXPECT_EQ(r.diagnostics.contributing_ties, 12u);
}

TEST_P(Cvms, CubePlusAxisAlignedBox) {
  const auto c = shapes::cube();
  const auto b = shapes::box(v3(0, 0, 0), v3(1, 2, Rational(7, 3)));
  EXPECT_SUM(c, b, shape_of(shapes::box(v3(-1, -1, -1), v3(2, 3, Rational(10, 3)))));
}

TEST_P(Cvms, SmallSumsAgreeWithBruteForce) {
  const auto t = shapes::tetrahedron();
  const auto c = shapes::cube();
  const auto o = shapes::octahedron();
  EXPECT_SUM(t, c, brute_force_sum(t, c));
  EXPECT_SUM(t, o, brute_force_sum(t, o));
  EXPECT_SUM(c, o, brute_force_sum(c, o));
  EXPECT_SUM(t, t, brute_force_sum(t, t));
  EXPECT_SUM(t, t.reflected(), brute_force_sum(t, t.reflected()));
}

TEST_P(Cvms, SumWithItselfIsTheDoubledShape) {
  // A + A = 2A for every convex A: the paper's "extreme" case, where every
  // facet of B has a parallel facet of A.
  for (int k = 1; k <= 3; ++k) {
    SCOPED_TRACE("Sphere" + std::to_string(k));
    const auto s = shapes::geodesic_sphere(k);
    EXPECT_SUM(s, s, shape_of(scaled(s, 2)));
    if (!counts_facets()) continue;
    const auto r = cvms_sum(s, s);
    EXPECT_EQ(r.stats.edge_facets, 0u);
    EXPECT_EQ(r.stats.corner_facets, 0u);
    EXPECT_EQ(r.diagnostics.contributing_ties, 2u * s.num_facets());
  }
  const auto tc = shapes::truncated_cube();
  EXPECT_SUM(tc, tc, shape_of(scaled(tc, 2)));
}

TEST_P(Cvms, HomotheticCopies) {
  // A + sA = (1 + s)A: all facets parallel, no edge facets.
  const auto tc = shapes::truncated_cube();
  EXPECT_SUM(tc, scaled(tc, Rational(1, 3)), shape_of(scaled(tc, Rational(4, 3))));
  const auto s2 = shapes::geodesic_sphere(2);
  EXPECT_SUM(s2, scaled(s2, 5), shape_of(scaled(s2, 6)));
}

// ---------------------------------------------------------------------------
// The paper's shapes, every pair in both orders (check_sum runs both).

TEST_P(Cvms, PaperShapesEveryPairAgreesWithChms) {
  std::vector<std::pair<std::string, ConvexPolyhedron>> shapes_list = {
      {"Tetra", shapes::tetrahedron()},        {"Cube", shapes::cube()},
      {"Hedra", shapes::octahedron()},         {"TruncatedCube", shapes::truncated_cube()},
      {"Sphere1", shapes::geodesic_sphere(1)}, {"Sphere2", shapes::geodesic_sphere(2)},
      {"Sphere3", shapes::geodesic_sphere(3)},
  };
  for (std::size_t i = 0; i < shapes_list.size(); ++i) {
    for (std::size_t j = i; j < shapes_list.size(); ++j) {
      const auto& [na, a] = shapes_list[i];
      const auto& [nb, b] = shapes_list[j];
      SCOPED_TRACE(na + " + " + nb);
      EXPECT_EQ(
          test::check_sum(a, b, test::chms_shape(a, b), options(), a.num_facets() * b.num_facets() < 20000),
          "");
      EXPECT_EQ(modes_agree(a, b), "");
    }
  }
}

TEST_P(Cvms, RotatedSpheresInGeneralPosition) {
  const auto a = shapes::geodesic_sphere(2);
  const auto b = shapes::rotated_geodesic_sphere(2);
  EXPECT_SUM(a, b, test::chms_shape(a, b));
}

// ---------------------------------------------------------------------------
// Degenerate configurations.

TEST_P(Cvms, CubePlusTruncatedCubeHasParallelFacets) {
  const auto c = shapes::cube();
  const auto t = shapes::truncated_cube();
  EXPECT_SUM(c, t, test::chms_shape(c, t));
  if (counts_facets()) {
    EXPECT_EQ(cvms_sum(c, t).stats.corner_facets, 8u);  // the 8 triangles; the 6 octagons are used
  }
}

TEST_P(Cvms, PrismPlusPrismHasParallelEdges) {
  const auto p6 = shapes::prism(6, 1);
  const auto p8 = shapes::prism(8, Rational(5, 2));
  const auto p5 = shapes::prism(5, 3);
  EXPECT_SUM(p6, p8, test::chms_shape(p6, p8));
  EXPECT_SUM(p5, p8, test::chms_shape(p5, p8));
  EXPECT_SUM(p6, p6, shape_of(scaled(p6, 2)));
  // A prism lying on its side: its axis is parallel to facets of the other.
  Mat3 quarter_turn_x;  // (x, y, z) -> (x, -z, y)
  quarter_turn_x.m[0][0] = 1;
  quarter_turn_x.m[1][2] = -1;
  quarter_turn_x.m[2][1] = 1;
  const auto side = p5.transformed(quarter_turn_x, {});
  EXPECT_SUM(p6, side, test::chms_shape(p6, side));
  EXPECT_SUM(side, p8, test::chms_shape(side, p8));
}

TEST_P(Cvms, FacetOfAParallelToAnEdgeOfB) {
  // Each edge of the tetrahedron is parallel to two facets of the cube: those
  // cube facets have two contributing vertices (f_A + e_B).
  const auto c = shapes::cube();
  const auto t = shapes::tetrahedron();
  EXPECT_SUM(c, t, brute_force_sum(c, t));
  if (counts_facets()) {
    EXPECT_EQ(cvms_sum(c, t).diagnostics.contributing_ties, 6u);
  }
}

TEST_P(Cvms, GaussianArcThroughAFacetNormal) {
  // Every arc of the cube passes exactly through a facet normal (+-1, +-1, 0)
  // (and permutations) of the rhombic dodecahedron: those facets become
  // f_B + e_A corner facets, never edge facets.
  const auto c = shapes::cube();
  const auto r = rhombic_dodecahedron();
  ASSERT_EQ(r.num_facets(), 12u);
  EXPECT_SUM(c, r, brute_force_sum(c, r));
  if (counts_facets()) {
    const auto s = cvms_sum(c, r);
    EXPECT_EQ(s.stats.corner_facets, 12u);
    EXPECT_EQ(s.stats.edge_facets, 0u);
  }
  const auto t = shapes::truncated_cube();
  EXPECT_SUM(t, r, test::chms_shape(t, r));
}

TEST_P(Cvms, PaperCriterionAloneWouldDuplicateACornerFacet) {
  // B is the tetrahedron {-y+z <= 1, x+y+z <= 1, -x <= 1, -z <= 1} (scaled by
  // 2). Its facet (0,-1,1) is parallel to the cube edge e_A = {y=-1, z=1}
  // and its normal is strictly inside that edge's arc; its neighbour (1,1,1)
  // is invisible from the edge direction and has contributing vertex (1,1,1),
  // disjoint from e_A. The paper's horizon (invisible vs not invisible) and
  // Eq. 5 accept e_A + e_B, a piece of the corner facet f_B + e_A.
  const auto c = shapes::cube();
  const auto b = hull({v3(-2, 1, 3), v3(8, -4, -2), v3(-2, -4, -2), v3(-2, 6, -2)});
  EXPECT_SUM(c, b, brute_force_sum(c, b));
  if (algorithm() == Algorithm::cvms && GetParam().reference) {
    EXPECT_GT(cvms_sum(c, b).diagnostics.edge_paper_rejections, 0u);
  }
}

TEST_P(Cvms, TiesOfContributingVertices) {
  // Integer boxes and octahedra: many facets with edge or facet ties.
  const auto o = shapes::octahedron();
  const auto box = shapes::box(v3(0, 0, 0), v3(1, 1, 2));
  const auto wedge = hull({v3(0, 0, 0), v3(2, 0, 0), v3(0, 2, 0), v3(0, 0, 2), v3(2, 0, 2), v3(0, 2, 2)});
  EXPECT_SUM(o, box, brute_force_sum(o, box));
  EXPECT_SUM(wedge, box, brute_force_sum(wedge, box));
  EXPECT_SUM(wedge, o, brute_force_sum(wedge, o));
  EXPECT_SUM(wedge, wedge.reflected(), brute_force_sum(wedge, wedge.reflected()));
  if (counts_facets()) {
    EXPECT_GT(cvms_sum(wedge, box).diagnostics.contributing_ties, 0u);
  }
}

TEST_P(Cvms, OperandsFarFromTheOrigin) {
  const Rational g("1000000000");
  const auto a = shapes::truncated_cube().translated(v3(g, 2 * g, -g));
  const auto b = shapes::geodesic_sphere(2).translated(v3(-3 * g, g + Rational(1, 3), 7 * g));
  EXPECT_SUM(a, b, test::chms_shape(a, b));
  const auto c = shapes::cube().translated(v3(g, g, g));
  EXPECT_SUM(c, c,
             shape_of(shapes::box(v3(2 * g - 2, 2 * g - 2, 2 * g - 2), v3(2 * g + 2, 2 * g + 2, 2 * g + 2))));
}

TEST_P(Cvms, HugeAndTinyCoordinates) {
  const Rational huge("1000000000000");
  const Rational tiny("1/1000000000000");
  const auto s = shapes::geodesic_sphere(2);
  const auto t = shapes::truncated_cube();
  for (const Rational& k : {huge, tiny}) {
    SCOPED_TRACE(to_string(k));
    const auto a = scaled(s, k);
    EXPECT_SUM(a, t, test::chms_shape(a, t));
    const auto b = scaled(t, k);
    EXPECT_SUM(a, b, test::chms_shape(a, b));
  }
  const auto a = scaled(s, huge);
  const auto b = scaled(t, tiny);
  EXPECT_SUM(a, b, test::chms_shape(a, b));
}

TEST_P(Cvms, ExactRationalRotations) {
  const auto r1 = shapes::rational_rotation(1, 2, 3, 4);
  const auto r2 = shapes::rational_rotation(2, -1, 0, 3);
  const auto c = shapes::cube();
  const auto t = shapes::truncated_cube();
  const auto o = shapes::octahedron();
  const auto cr = c.transformed(r1, {});
  const auto tr = t.transformed(r1, {});
  const auto or2 = o.transformed(r2, {});
  EXPECT_SUM(cr, tr, test::chms_shape(cr, tr));  // same rotation: parallel facets kept
  EXPECT_SUM(cr, t, test::chms_shape(cr, t));
  EXPECT_SUM(tr, or2, test::chms_shape(tr, or2));
  EXPECT_SUM(cr, cr, shape_of(scaled(cr, 2)));
}

TEST_P(Cvms, ThinSlabsAndNeedles) {
  const test::ThinOperands t = test::thin_operands();
  const auto& [slab, slab_y, needle, slab_r, needle_r, tetra_needle] = t;
  const auto s = shapes::geodesic_sphere(1);
  EXPECT_SUM(slab, slab_y, brute_force_sum(slab, slab_y));
  EXPECT_SUM(slab, needle, brute_force_sum(slab, needle));
  EXPECT_SUM(needle, needle_r, brute_force_sum(needle, needle_r));
  EXPECT_SUM(slab, slab_r, brute_force_sum(slab, slab_r));
  EXPECT_SUM(slab_r, s, test::chms_shape(slab_r, s));
  EXPECT_SUM(needle_r, s, test::chms_shape(needle_r, s));
  EXPECT_SUM(tetra_needle, needle_r, brute_force_sum(tetra_needle, needle_r));
}

TEST_P(Cvms, InputTriangulatedWithManyCoplanarTriangles) {
  const auto cube3 = ConvexPolyhedron::from_soup(triangulated_cube(3));
  ASSERT_EQ(cube3.num_facets(), 6u);
  const auto t = shapes::truncated_cube();
  EXPECT_SUM(cube3, t, test::chms_shape(cube3, t));
  EXPECT_SUM(cube3, shapes::cube(), shape_of(shapes::box(v3(-4, -4, -4), v3(4, 4, 4))));
}

// ---------------------------------------------------------------------------
// Conventions the algorithm relies on, checked with plain rationals.

TEST(Conventions, GaussianArcRunsCounterclockwiseAboutTheEdge) {
  // cross(n(face(h)), n(face(twin(h)))) is a positive multiple of
  // to(h) - from(h): lib/minkowski/cvms_algorithm.cpp uses the edge vector as the arc's pole.
  for (const auto& p : {shapes::cube(), shapes::truncated_cube(), shapes::geodesic_sphere(2),
                        rhombic_dodecahedron(), shapes::random_hull(7, 30)}) {
    const Mesh& m = p.mesh();
    for (HalfedgeId h : m.halfedges()) {
      const Vec3 pole = cross(p.normal(m.face(h)), p.normal(m.face(Mesh::twin(h))));
      const Vec3 d = p.vertex(m.to(h)) - p.vertex(m.from(h));
      ASSERT_TRUE(is_zero(cross(pole, d)));
      ASSERT_GT(sgn(dot(pole, d)), 0);
    }
  }
}

// ---------------------------------------------------------------------------
// Arc geometry: configurations of Gaussian arcs that stress the slope-diagram
// merge of ESSDMS (paper Section 5.2); every algorithm must agree on them.

TEST_P(Cvms, ArcsOverlappingOnOneGreatCircle) {
  // The arcs of the vertical edges of a cube lie on the equator. Against a
  // box they coincide; against an octagonal prism (normals (+-1, 0, 0),
  // (0, +-1, 0), (+-1, +-1, 0)) each is split by a facet point; against a
  // rotated cube they overlap partly, each arc having one end strictly
  // inside an arc of the other. Parallel edges: no edge facet from them.
  const auto c = shapes::cube();
  const auto octagonal_prism = test::octagonal_prism();
  ASSERT_EQ(octagonal_prism.num_facets(), 10u);
  const auto rotated = c.transformed(rotation_z_3_4_5(), {});
  const auto box = shapes::box(v3(0, 0, 0), v3(3, 1, Rational(1, 2)));
  EXPECT_SUM(c, octagonal_prism, test::chms_shape(c, octagonal_prism));
  EXPECT_SUM(c, rotated, brute_force_sum(c, rotated));
  EXPECT_SUM(box, rotated, brute_force_sum(box, rotated));
  const auto p6 = shapes::prism(6, 2);
  const auto p6r = p6.transformed(rotation_z_3_4_5(), {});
  EXPECT_SUM(p6, p6r, test::chms_shape(p6, p6r));
  if (counts_facets()) {
    // Each of the 4 side facets of the octagonal prism lying on an arc of
    // the cube is f_B + e_A; its 6 other facets pair with the cube's.
    const auto r = cvms_sum(c, octagonal_prism);
    EXPECT_EQ(r.stats.corner_facets, 4u);
    EXPECT_EQ(r.stats.edge_facets, 0u);
    // Two rotated cubes: the vertical arcs overlap (no edge facet), only the
    // arcs of the horizontal edges can cross.
    const auto s = cvms_sum(c, rotated);
    EXPECT_EQ(s.stats.translated_facets, 6u);
    EXPECT_EQ(s.stats.corner_facets, 4u);  // the rotated cube's top and bottom pair with the cube's
  }
}

TEST_P(Cvms, ArcEndingOnAnotherArc) {
  // B has the facet x + y = 1 with normal (1, 1, 0), strictly inside the arc
  // of the cube edge {x = 1, y = 1}; B's other facet normals (3, 3, -8),
  // (7, -9, 8) and (-15, 1, 8) lie on no great circle of the cube, so B's
  // arcs from (1, 1, 0) end on the cube's arc without crossing it.
  const auto c = shapes::cube();
  const auto b = hull({v3(1, 0, 0), v3(0, 1, 0), v3(Rational(1, 2), Rational(1, 2), 1), v3(-2, -5, -3)});
  EXPECT_SUM(c, b, brute_force_sum(c, b));
  // B2 has two facets, x + y = 1 and x - y = 1, strictly inside cube arcs;
  // the B2 arc joining them runs along the equator, overlapping two cube
  // arcs, through the cube's facet point (1, 0, 0).
  const auto b2 = hull({v3(1, 0, 0), v3(0, 1, 0), v3(1, 0, 1), v3(-1, -2, -3)});
  EXPECT_SUM(c, b2, brute_force_sum(c, b2));
  // The same after one exact rotation of both (no axis-aligned coordinates
  // left for the double filter).
  const auto rot = shapes::rational_rotation(1, 2, 3, 4);
  const auto cr = c.transformed(rot, {});
  const auto br = b.transformed(rot, {});
  EXPECT_SUM(cr, br, brute_force_sum(cr, br));
  // Against a shape with many arcs parallel to the cube's.
  const auto t = shapes::truncated_cube();
  EXPECT_SUM(t, b, test::chms_shape(t, b));
  EXPECT_SUM(t, b2, test::chms_shape(t, b2));
  if (counts_facets()) {
    // (1, 1, 0) on the cube's arc: the corner facet f_B + e_A, the only
    // facet of either operand with two contributing vertices.
    const auto r = cvms_sum(c, b);
    EXPECT_EQ(r.stats.corner_facets, 4u);
    EXPECT_EQ(r.diagnostics.contributing_ties, 1u);
    // B2: (1, 1, 0) and (1, -1, 0) on cube arcs, and the cube's (1, 0, 0) on
    // B2's arc.
    EXPECT_EQ(cvms_sum(c, b2).diagnostics.contributing_ties, 3u);
  }
}

TEST_P(Cvms, FlatPolyhedraWithNearlyAntipodalArcs) {
  const Rational h(1, 1000000);
  const auto flat = flat_bipyramid(h);
  ASSERT_EQ(flat.num_facets(), 12u);
  const auto c = shapes::cube();
  const auto flat_rotated = flat.transformed(shapes::rational_rotation(1, 1, 2, 0), {});
  const auto tilted = flat.transformed(shapes::rational_rotation(100, 1, 0, 0), {});  // a slight tilt
  const auto flat_tetra =
      hull({v3(0, 0, 0), v3(1, 0, 0), v3(0, 1, 0), v3(Rational(1, 3), Rational(1, 3), h)});
  const auto slab = shapes::box(v3(0, 0, 0), v3(1000, 1000, Rational(1, 1000)));
  EXPECT_SUM(flat, c, brute_force_sum(flat, c));
  EXPECT_SUM(flat, flat.reflected(), shape_of(scaled(flat, 2)));  // centrally symmetric: -P = P
  EXPECT_SUM(flat, flat_rotated, test::chms_shape(flat, flat_rotated));
  EXPECT_SUM(flat, tilted, test::chms_shape(flat, tilted));
  EXPECT_SUM(flat_tetra, flat_tetra.reflected(), brute_force_sum(flat_tetra, flat_tetra.reflected()));
  EXPECT_SUM(flat_tetra, flat, test::chms_shape(flat_tetra, flat));
  EXPECT_SUM(slab, tilted, test::chms_shape(slab, tilted));
  const auto s = shapes::geodesic_sphere(2);
  EXPECT_SUM(tilted, s, test::chms_shape(tilted, s));
}

// ---------------------------------------------------------------------------
// Random pairs.

TEST_P(Cvms, RandomPairsAgreeWithChms) {
  if (algorithm() == Algorithm::chms) GTEST_SKIP() << "CHMS is the oracle of this test (see chms_test.cpp)";
  // The default-mode instance already checks every pair in both CVMS modes
  // (modes_agree); only the paper-criterion counts below need this one.
  const bool counts_only = algorithm() == Algorithm::cvms && GetParam().reference;
  // 2000 pairs per algorithm in the default run (the cost is in the checks,
  // not the sums); the sanitizer preset lowers it with CVMS_RANDOM_PAIRS, and
  // cvms_soak_test runs 100,000.
  const int pairs = std::getenv("CVMS_RANDOM_PAIRS") ? std::atoi(std::getenv("CVMS_RANDOM_PAIRS")) : 2000;
  // How many pairs exercised each degenerate path (the generator is meant to
  // produce them; the counts make sure it keeps doing so).
  int with_edge_ties = 0, with_parallel_facets = 0, with_rejections = 0, with_edge_facets = 0;
  for (int i = 0; i < pairs; ++i) {
    const std::uint64_t seed = 1000 + static_cast<std::uint64_t>(i);
    const test::RandomPair p = test::random_pair(seed);
    SCOPED_TRACE("seed " + std::to_string(seed) + " (" + p.description + ")");
    if (!counts_only) {
      const std::string msg = test::check_sum(p.a, p.b, test::chms_shape(p.a, p.b), options());
      ASSERT_EQ(msg, "");
    }
    // One thread count per pair, in turn: the threaded runs cost what one did.
    ASSERT_EQ(modes_agree(p.a, p.b, {&thread_counts[i % std::size(thread_counts)], 1}), "");
    const CountedSum r = cvms_sum(p.a, p.b);
    const Stats& s = r.stats;
    with_edge_ties += r.diagnostics.contributing_ties > 0;
    with_parallel_facets += s.corner_facets < p.b.num_facets();
    with_rejections += r.diagnostics.edge_paper_rejections > 0;
    with_edge_facets += s.edge_facets > 0;
  }
  std::printf(
      "random pairs: %d with ties, %d with parallel facets, %d with paper-criterion rejections, %d with edge "
      "facets\n",
      with_edge_ties, with_parallel_facets, with_rejections, with_edge_facets);
  if (pairs >= 1000) {
    EXPECT_GT(with_edge_ties, pairs / 10);
    EXPECT_GT(with_parallel_facets, pairs / 20);
    if (algorithm() == Algorithm::cvms && GetParam().reference) {
      EXPECT_GT(with_rejections, 10);
    }
    EXPECT_GT(with_edge_facets, pairs / 2);
  }
}

// ---------------------------------------------------------------------------
// The entry point.

TEST(MinkowskiSum, EmptyOperandIsRejected) {
  for (bool first : {true, false}) {
    try {
      (void)(first ? minkowski_sum(ConvexPolyhedron{}, shapes::cube())
                   : minkowski_sum(shapes::cube(), ConvexPolyhedron{}));
      FAIL() << "no exception";
    } catch (const Error& e) {
      EXPECT_EQ(e.category(), ErrorCategory::invalid_argument);
      EXPECT_NE(std::string(e.what()).find(first ? "operand A" : "operand B"), std::string::npos) << e.what();
    }
  }
}

TEST(MinkowskiSum, UnknownOptionsAreRejected) {
  for (int which = 0; which < 2; ++which) {
    detail::ResearchOptions o;
    if (which == 0) o.edge_facet_search = static_cast<detail::EdgeFacetSearch>(42);
    if (which == 1) o.contributing_vertex_search = static_cast<detail::ContributingVertexSearch>(42);
    try {
      (void)detail::minkowski_sum(shapes::cube(), shapes::octahedron(), {}, o);
      FAIL() << "no exception";
    } catch (const Error& e) {
      EXPECT_EQ(e.category(), ErrorCategory::invalid_argument);
    }
  }
}

TEST(MinkowskiSum, ThreadsComputeIndependently) {
  // No shared mutable state: concurrent sums give the same results as
  // sequential ones, and each thread's stats count only its own predicates.
  const auto a = shapes::geodesic_sphere(2);
  const auto b = shapes::truncated_cube();
  const auto c = shapes::rotated_geodesic_sphere(1);
  const auto expected_ab = cvms_sum(a, b);
  const auto expected_ac = cvms_sum(a, c);
  CountedSum ab;
  CountedSum ac;
  std::thread t1([&] { ab = cvms_sum(a, b); });
  std::thread t2([&] { ac = cvms_sum(a, c); });
  t1.join();
  t2.join();
  EXPECT_TRUE(shape_of(ab.polyhedron) == shape_of(expected_ab.polyhedron));
  EXPECT_TRUE(shape_of(ac.polyhedron) == shape_of(expected_ac.polyhedron));
  EXPECT_EQ(ab.diagnostics.predicate_exact + ab.diagnostics.predicate_filtered,
            expected_ab.diagnostics.predicate_exact + expected_ab.diagnostics.predicate_filtered);
}

// A's contributing-vertex walk cut into pieces (here one per 16 facets, at
// most 8; the default cuts only operands of 16,384 facets or more) on 1, 2,
// 4 and 8 threads: the same polyhedron as the default one-piece walk, and
// the same Stats on every thread count for the same pieces.
TEST(MinkowskiSum, WalkPiecesOnThreadsGiveTheSameSum) {
  std::vector<std::pair<ConvexPolyhedron, ConvexPolyhedron>> pairs;
  pairs.emplace_back(shapes::geodesic_sphere(3), shapes::rotated_geodesic_sphere(3));
  pairs.emplace_back(shapes::geodesic_sphere(3), shapes::geodesic_sphere(2));
  pairs.emplace_back(shapes::prism(40, 3), shapes::truncated_cube());
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    test::RandomPair p = test::random_pair(seed);
    pairs.emplace_back(std::move(p.a), std::move(p.b));
  }
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    SCOPED_TRACE("pair " + std::to_string(i));
    const auto& [a, b] = pairs[i];
    const CountedSum one_piece = counted(a, b, {});
    CountedSum first;
    for (const unsigned n : {1u, 2u, 4u, 8u}) {
      Options options;
      options.threads = n;
      detail::ResearchOptions research;
      research.worker_minimums = {0, 0, true};
      research.walk_piece_facets = 16;
      const CountedSum pieces = counted(a, b, options, research);
      const std::string what = "pieces on " + std::to_string(n) + " threads";
      EXPECT_EQ(same_result(one_piece, pieces, what), "");
      if (n == 1) first = pieces;
      EXPECT_TRUE(same_stats(first, pieces)) << what;
    }
  }
}

// The threaded edge-facet search stops where one thread stops: it traces
// chunks of edges on every thread and replays one thread's budget checks when
// it merges them, so the error (with the count where the search stopped) is
// the same for every limit, including limits inside a chunk.
TEST(MinkowskiSum, ThreadedSearchStopsWhereOneThreadStops) {
  const test::PrismPair pair = test::prism_attack(40);
  const std::uint64_t facets = minkowski_sum(pair.a, pair.b).polyhedron.num_facets();
  auto message = [&](std::uint64_t limit, unsigned threads) -> std::string {
    Options options;
    options.threads = threads;
    options.limits.max_output_facets = limit;
    detail::ResearchOptions research;
    research.worker_minimums = {0, 0, true};
    try {
      (void)detail::minkowski_sum(pair.a, pair.b, options, research);
    } catch (const Error& e) {
      return e.message();
    }
    return "no error";
  };
  for (std::uint64_t limit = pair.a.num_facets() + 40; limit <= facets; limit += facets / 7) {
    const std::string one = message(limit, 1);
    for (const unsigned n : {2u, 4u, 8u})
      EXPECT_EQ(message(limit, n), one) << "limit " << limit << ", " << n << " threads";
  }
  EXPECT_EQ(message(facets, 8), "no error");
}

}  // namespace
}  // namespace cvms
