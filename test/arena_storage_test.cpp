// SPDX-License-Identifier: MIT
// Sums keep their exact values in arenas (lib/numeric/limb_arena.hpp): the
// result, a copy, a move and a copy that outlives its original read
// back the same exact values, on one thread and on several, and operations
// on such a result make values of their own. The expected values are heap
// copies made before anything is moved; that they are the right sums is what
// the differential suites check against the hull of the pairwise sums.
#include <gtest/gtest.h>

#include <algorithm>
#include <latch>
#include <thread>
#include <utility>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/shapes.hpp"
#include "facet_planes.hpp"
#include "limb_arena.hpp"
#include "polyhedron_builder.hpp"
#include "research_options.hpp"
#include "result_slab.hpp"
#include "support/hand_solids.hpp"
#include "support/minkowski_check.hpp"
#include "support/oracle.hpp"

namespace cvms {
namespace {

struct ExactValues {
  std::vector<Vec3> vertices;
  std::vector<Vec3> normals;
  std::vector<Rational> offsets;
};

ExactValues copies_of(const ConvexPolyhedron& p) {
  ExactValues out;
  for (VertexId v : p.mesh().vertices()) out.vertices.push_back(p.vertex(v));
  for (FaceId f : p.mesh().faces()) {
    out.normals.push_back(p.normal(f));
    out.offsets.push_back(p.plane_offset(f));
  }
  return out;
}

// Which of a polyhedron's exact values a check reads: the offsets may be
// made after the rest (on first use, into the polyhedron's own arena).
enum class Offsets { included, excluded };
// Whether a check reads the vertices and normals: a sum's are packed
// (dyadic_points.hpp) and shared by its copies, which read the same views.
enum class Packed { included, excluded };

// Whether every nonzero numerator of p's values is a view (owns no limb) or
// every one owns its limbs: a sum's are views, a copy's are its own.
bool numerators_are_views(const ConvexPolyhedron& p, bool views, Offsets offsets = Offsets::included,
                          Packed packed = Packed::included) {
  auto matches = [views](const Rational& q) {
    return sgn(q) == 0 || (mpq_numref(q.get_mpq_t())->_mp_alloc == 0) == views;
  };
  if (packed == Packed::included)
    for (VertexId v : p.mesh().vertices())
      for (int i = 0; i < 3; ++i)
        if (!matches(p.vertex(v)[i])) return false;
  for (FaceId f : p.mesh().faces()) {
    for (int i = 0; packed == Packed::included && i < 3; ++i)
      if (!matches(p.normal(f)[i])) return false;
    if (offsets == Offsets::included && !matches(p.plane_offset(f))) return false;
  }
  return true;
}

// Whether every denominator of p's normals is a view (owns no limb), or
// every one owns its limb.
bool normal_denominators_are_views(const ConvexPolyhedron& p, bool views) {
  auto matches = [views](const Rational& q) { return (mpq_denref(q.get_mpq_t())->_mp_alloc == 0) == views; };
  for (FaceId f : p.mesh().faces())
    for (int i = 0; i < 3; ++i)
      if (!matches(p.normal(f)[i])) return false;
  return true;
}

// The same for the offsets.
bool offset_denominators_are_views(const ConvexPolyhedron& p, bool views) {
  for (FaceId f : p.mesh().faces())
    if ((mpq_denref(p.plane_offset(f).get_mpq_t())->_mp_alloc == 0) != views) return false;
  return true;
}

bool plane_denominators_are_views(const ConvexPolyhedron& p, bool views) {
  return normal_denominators_are_views(p, views) && offset_denominators_are_views(p, views);
}

void expect_values(const ConvexPolyhedron& p, const ExactValues& expected) {
  ASSERT_EQ(p.num_vertices(), expected.vertices.size());
  ASSERT_EQ(p.num_facets(), expected.normals.size());
  for (VertexId v : p.mesh().vertices()) ASSERT_EQ(p.vertex(v), expected.vertices[v.index()]);
  for (FaceId f : p.mesh().faces()) {
    ASSERT_EQ(p.normal(f), expected.normals[f.index()]);
    ASSERT_EQ(p.plane_offset(f), expected.offsets[f.index()]);
  }
}

class ArenaStorage : public ::testing::TestWithParam<unsigned> {};

TEST_P(ArenaStorage, SumsCopiesAndMovesKeepTheirValues) {
  const ConvexPolyhedron a = shapes::geodesic_sphere(3);  // 1,020 output facets: enough for a worker
  const ConvexPolyhedron b = shapes::rotated_geodesic_sphere(3);
  Options options;
  options.threads = GetParam();
  detail::ResearchOptions research;  // the worker runs even on a one-core machine
  research.worker_minimums.oversubscribe = true;
  auto sum_of = [&](const ConvexPolyhedron& x, const ConvexPolyhedron& y) {
    return detail::minkowski_sum(x, y, options, research).polyhedron;
  };
  const ConvexPolyhedron sum = sum_of(a, b);
  const ExactValues expected = copies_of(sum);
  if (detail::LimbArena::holds_limbs()) {
    EXPECT_TRUE(numerators_are_views(sum, true));
    // The normals' denominators (1): the normals are packed and made into
    // Vec3s on first request, each heap limb given back, so they are views
    // on any number of threads. The offsets' (powers of two) are made on
    // first use, once per polyhedron, and give theirs back always.
    EXPECT_TRUE(normal_denominators_are_views(sum, true));
    EXPECT_TRUE(offset_denominators_are_views(sum, true));
  }

  ConvexPolyhedron copy;
  {
    ConvexPolyhedron original = sum_of(a, b);
    copy = original;
    // Taken before the original made its offsets: the copy makes its own
    // when first asked (into its own arena), after the original is gone. Its
    // vertices and normals are the original's packed ones, shared (immutable).
    EXPECT_TRUE(numerators_are_views(copy, false, Offsets::excluded, Packed::excluded));
    ConvexPolyhedron moved = std::move(original);
    expect_values(moved, expected);
    ConvexPolyhedron assigned;
    assigned = std::move(moved);
    expect_values(assigned, expected);
  }
  expect_values(copy, expected);
  EXPECT_TRUE(copy.is_convex());
  EXPECT_TRUE(sum.is_convex());

  const Vec3 shift{1, Rational(1, 3), -2};
  const ConvexPolyhedron shifted = sum.translated(shift);
  for (VertexId v : shifted.mesh().vertices())
    ASSERT_EQ(shifted.vertex(v), expected.vertices[v.index()] + shift);
  // A sum of sums reads the first sum's values as operands.
  const ConvexPolyhedron twice = sum_of(sum, sum.reflected());
  EXPECT_TRUE(twice.is_convex());
  const PolygonSoup soup = twice.to_soup();
  EXPECT_EQ(soup.points.size(), twice.num_vertices());
}

// Operands moved by offsets over 3^45 and 7^30, so that the sum's vertices
// and offsets have denominators of several limbs, which the arena holds too
// (views, like the numerators). Translation commutes with the sum, so the
// values must be those of the sum of the unmoved operands, moved by the sum
// of the offsets (made by translated(), which computes its own values), and
// a copy, a move and a copy that outlives the original keep them. Cube ⊕
// tetrahedron moved the same way is checked against the exact hull of its
// pairwise vertex sums.
TEST_P(ArenaStorage, LongDenominatorsLiveInTheArenaToo) {
  mpz_class p3, p7;
  mpz_ui_pow_ui(p3.get_mpz_t(), 3, 45);
  mpz_ui_pow_ui(p7.get_mpz_t(), 7, 30);
  const Vec3 t{Rational(mpz_class(1), p3), Rational(mpz_class(2), p7), 0};
  const Vec3 u{Rational(mpz_class(1), p7), 0, Rational(mpz_class(-1), p3)};
  Options options;
  options.threads = GetParam();
  detail::ResearchOptions research;
  research.worker_minimums.oversubscribe = true;
  auto sum_of = [&](const ConvexPolyhedron& x, const ConvexPolyhedron& y) {
    return detail::minkowski_sum(x, y, options, research).polyhedron;
  };
  const ConvexPolyhedron a = shapes::geodesic_sphere(3), b = shapes::rotated_geodesic_sphere(3);
  const ExactValues expected = copies_of(sum_of(a, b).translated(t + u));
  ConvexPolyhedron copy;
  {
    ConvexPolyhedron sum = sum_of(a.translated(t), b.translated(u));
    expect_values(sum, expected);
    std::size_t long_denominators = 0;
    for (VertexId v : sum.mesh().vertices())
      for (int i = 0; i < 3; ++i) {
        mpz_srcptr den = mpq_denref(sum.vertex(v)[i].get_mpq_t());
        if (mpz_size(den) < 2) continue;
        ++long_denominators;
        if (detail::LimbArena::holds_limbs()) {
          ASSERT_EQ(den->_mp_alloc, 0) << "vertex " << v.index();
        }
      }
    EXPECT_GT(long_denominators, sum.num_vertices());
    copy = sum;
    ConvexPolyhedron moved = std::move(sum);
    expect_values(moved, expected);
  }
  expect_values(copy, expected);
  EXPECT_TRUE(copy.is_convex());

  const ConvexPolyhedron cube = ConvexPolyhedron::from_soup(test::cube_quads()).translated(t);
  const ConvexPolyhedron tetra = ConvexPolyhedron::from_soup(test::tetrahedron()).translated(u);
  std::vector<Vec3> pairwise;
  for (VertexId v : cube.mesh().vertices())
    for (VertexId w : tetra.mesh().vertices()) pairwise.push_back(cube.vertex(v) + tetra.vertex(w));
  const ConvexPolyhedron hull = convex_hull(pairwise);
  const ConvexPolyhedron small_sum = sum_of(cube, tetra);
  std::vector<Vec3> got = small_sum.mesh().positions(), want = hull.mesh().positions();
  std::sort(got.begin(), got.end());
  std::sort(want.begin(), want.end());
  EXPECT_EQ(got, want);
  EXPECT_EQ(small_sum.num_facets(), hull.num_facets());
}

INSTANTIATE_TEST_SUITE_P(Threads, ArenaStorage, ::testing::Values(1u, 2u, 4u));

// Whether every nonzero numerator of p's normals and offsets is a view.
bool plane_numerators_are_views(const ConvexPolyhedron& p, bool views) {
  auto matches = [views](const Rational& q) {
    return sgn(q) == 0 || (mpq_numref(q.get_mpq_t())->_mp_alloc == 0) == views;
  };
  for (FaceId f : p.mesh().faces()) {
    for (int i = 0; i < 3; ++i)
      if (!matches(p.normal(f)[i])) return false;
    if (!matches(p.plane_offset(f))) return false;
  }
  return true;
}

// The plane of facet f worked out here from its first three corners: the
// primitive cross product, turned outward by a vertex off the facet.
std::pair<Vec3, Rational> outward_plane(const ConvexPolyhedron& p, FaceId f) {
  const HalfedgeId h = p.mesh().halfedge(f);
  const Vec3& a = p.vertex(p.mesh().from(h));
  Vec3 n = primitive_direction(cross(p.vertex(p.mesh().to(h)) - a, p.vertex(p.mesh().to(p.mesh().next(h))) - a));
  const Rational offset = dot(n, a);
  for (VertexId v : p.mesh().vertices())
    if (dot(n, p.vertex(v)) > offset) return {-n, -offset};  // every vertex is at or below an outward plane
  return {n, offset};
}

// The planes from_soup stores in its arena, against planes worked out here
// from each facet's first three corners (the primitive cross product, turned
// outward by a vertex off the facet), for a mesh given outward and inward
// (flipped on reading) and for a copy.
TEST(ArenaStorage, FromSoupKeepsExactPlanesInItsArena) {
  const PolygonSoup outward = shapes::rotated_geodesic_sphere(2).to_soup();
  const PolygonSoup inward = test::reversed(outward);
  // Faces that merge into facets (the kept normals move to a fresh arena),
  // outward and inward: a subdivided cube under a shear with large entries,
  // so that the normals are large integers, not the constants 0 and +-1.
  const PolygonSoup merging = [] {
    PolygonSoup soup = test::subdivided(test::cube_quads(), 2);
    for (Vec3& q : soup.points)
      q = Vec3{1000003 * q.x + 7 * q.y + 11 * q.z, 13 * q.x + 999983 * q.y + 17 * q.z,
               19 * q.x + 23 * q.y + 1000033 * q.z};
    return soup;
  }();
  const PolygonSoup merging_inward = test::reversed(merging);
  // Non-dyadic coordinates (thirds and sevenths): offsets with denominators
  // that are not powers of two, stored into denominators given back.
  const PolygonSoup rational = [&] {
    PolygonSoup soup = outward;
    for (Vec3& q : soup.points) q = Vec3{q.x + q.y / 3, q.y - q.z / 7, q.z + Rational(1, 3)};
    return soup;
  }();
  for (const PolygonSoup* soup : {&outward, &inward, &merging, &merging_inward, &rational}) {
    const ConvexPolyhedron p = ConvexPolyhedron::from_soup(*soup);
    ASSERT_EQ(p.num_facets(), soup == &merging || soup == &merging_inward ? 6u : outward.num_faces());
    for (FaceId f : p.mesh().faces()) {
      const auto [n, offset] = outward_plane(p, f);
      ASSERT_EQ(p.normal(f), n) << "facet " << f.index() << (soup == &inward || soup == &merging_inward ? " (inward input)" : "");
      ASSERT_EQ(p.plane_offset(f), offset) << "facet " << f.index();
    }
    if (detail::LimbArena::holds_limbs()) {
      EXPECT_TRUE(plane_numerators_are_views(p, true));
      // Made once per polyhedron, the planes gave their denominators'
      // limbs back (limb_arena.hpp): views of the constant powers of two
      // (a denominator of 3 or 7 gets a limb of its own again).
      if (soup != &rational) {
        EXPECT_TRUE(plane_denominators_are_views(p, true));
      }
    }
    const ConvexPolyhedron copy = p;
    EXPECT_TRUE(plane_numerators_are_views(copy, false));
    EXPECT_TRUE(plane_denominators_are_views(copy, false));
    for (FaceId f : p.mesh().faces()) {
      ASSERT_EQ(copy.normal(f), p.normal(f));
      ASSERT_EQ(copy.plane_offset(f), p.plane_offset(f));
    }
  }
}

// What readers on several threads, started at once so that they race for
// one computation, read through read(p, f) for every facet f (each reader
// starting elsewhere): the addresses, sorted, per reader.
template <class Read>
std::vector<std::vector<const void*>> addresses_read_at_once(const ConvexPolyhedron& p, int num_readers,
                                                             Read read) {
  std::vector<std::vector<const void*>> seen(static_cast<std::size_t>(num_readers));
  std::vector<std::thread> readers;
  std::latch start(num_readers);
  for (int t = 0; t < num_readers; ++t)
    readers.emplace_back([&, t] {
      start.arrive_and_wait();
      const std::uint32_t n = p.num_facets();
      for (std::uint32_t i = 0; i < n; ++i) {
        const FaceId f((i + static_cast<std::uint32_t>(t) * n / static_cast<std::uint32_t>(num_readers)) % n);
        seen[static_cast<std::size_t>(t)].push_back(read(p, f));
      }
    });
  for (std::thread& r : readers) r.join();
  for (std::vector<const void*>& addresses : seen) std::sort(addresses.begin(), addresses.end());
  return seen;
}

// A loaded polyhedron makes its planes when one is first asked for
// (lib/mesh/facet_planes.hpp). Readers on several threads that ask at once
// all get the one set made (the same addresses), and it is the right one; a
// copy taken before that makes its own, equal set. Under TSan this is the
// test of the once-only construction.
TEST(ArenaStorage, LoadedPlanesAreMadeOnceForConcurrentReaders) {
  const PolygonSoup soup = shapes::rotated_geodesic_sphere(3).to_soup();
  constexpr int num_readers = 4;
  for (int round = 0; round < 3; ++round) {
    const ConvexPolyhedron p = ConvexPolyhedron::from_soup(soup);
    const ConvexPolyhedron copy_before = p;
    const auto seen = addresses_read_at_once(p, num_readers, [](const ConvexPolyhedron& q, FaceId f) {
      (void)q.plane_offset(f);
      return static_cast<const void*>(&q.normal(f));
    });
    for (int t = 1; t < num_readers; ++t)
      ASSERT_EQ(seen[0], seen[static_cast<std::size_t>(t)])
          << "reader " << t << " read another set of planes (round " << round << ")";
    for (FaceId f : p.mesh().faces()) {
      const auto [n, offset] = outward_plane(p, f);
      ASSERT_EQ(p.normal(f), n) << "facet " << f.index();
      ASSERT_EQ(p.plane_offset(f), offset) << "facet " << f.index();
      ASSERT_EQ(copy_before.normal(f), n) << "facet " << f.index() << " of the copy";
      ASSERT_EQ(copy_before.plane_offset(f), offset) << "facet " << f.index() << " of the copy";
    }
    EXPECT_NE(&copy_before.normal(FaceId(0)), &p.normal(FaceId(0)));
  }
}

// A sum on `threads` threads read at once by several threads: each reader
// gets the one set of vertices and normals made (the same addresses), which
// a copy shares when packed; the values are the hull of the pairwise sums'.
void expect_made_once_for_concurrent_readers(const ConvexPolyhedron& a, const ConvexPolyhedron& b,
                                             unsigned threads, bool dyadic, const test::Shape& expected) {
  constexpr int num_readers = 4;
  Options options;
  options.threads = threads;
  detail::ResearchOptions research;
  research.worker_minimums = {0, 0, true};
  const ConvexPolyhedron p = detail::minkowski_sum(a, b, options, research).polyhedron;
  EXPECT_EQ(MeshAccess::packed_positions(p.mesh()) != nullptr, dyadic);
  EXPECT_NE(PolyhedronAccess::planes(p).packed_normals, nullptr);
  const ConvexPolyhedron copy = p;
  const auto seen = addresses_read_at_once(p, num_readers, [](const ConvexPolyhedron& q, FaceId f) {
    (void)q.vertex(q.mesh().from(q.mesh().halfedge(f)));
    return static_cast<const void*>(&q.normal(f));
  });
  for (int t = 1; t < num_readers; ++t)
    ASSERT_EQ(seen[0], seen[static_cast<std::size_t>(t)]) << "reader " << t << " read another set of normals";
  if (dyadic) {
    for (VertexId v : p.mesh().vertices()) ASSERT_EQ(&copy.vertex(v), &p.vertex(v)) << "vertex " << v.index();
  }
  for (FaceId f : p.mesh().faces()) ASSERT_EQ(&copy.normal(f), &p.normal(f)) << "facet " << f.index();
  const test::Shape actual = test::describe(p);
  EXPECT_TRUE(actual == expected) << test::difference(expected, actual);
  EXPECT_EQ(test::check_invariants(p), "");
}

// A sum keeps its vertices and normals packed and makes their Vec3s when one
// is first asked for (lib/mesh/packed_vectors.hpp); with a vertex that is
// not dyadic (an operand shifted by 1/3) its vertices are Vec3s from the
// start. Under TSan this is the check that making them once is race-free.
TEST(ArenaStorage, SumVerticesAndNormalsAreMadeOnceForConcurrentReaders) {
  const ConvexPolyhedron a = shapes::geodesic_sphere(2);
  for (const bool dyadic : {true, false}) {
    const ConvexPolyhedron b =
        shapes::rotated_geodesic_sphere(2).translated(Vec3{dyadic ? Rational(1, 8) : Rational(1, 3), 0, 0});
    const test::Shape expected = test::chms_shape(a, b);
    for (const unsigned threads : {1u, 2u}) {
      SCOPED_TRACE(std::to_string(threads) + (dyadic ? " threads, dyadic" : " threads, not dyadic"));
      expect_made_once_for_concurrent_readers(a, b, threads, dyadic, expected);
    }
  }
}

// A sum's packed vertices, their approximations and its mesh's connectivity
// are carved from one slab, its packed normals and their approximations from another
// (result_slab.hpp: two blocks on huge pages instead of a dozen that fault
// in 4 KiB at a time), each sized exactly by its plan: every byte planned is
// carved, nothing falls back. The mesh's arrays are not visible here; had
// the mesh not carved its part, its slab would not be full, and had it
// carved more, a refusal would say so.
TEST(ArenaStorage, ASumsArraysAreCarvedFromTwoSlabsSizedExactly) {
  const ConvexPolyhedron a = shapes::geodesic_sphere(3);
  const ConvexPolyhedron b = shapes::rotated_geodesic_sphere(3).translated(Vec3{Rational(1, 8), 0, 5});
  for (const unsigned threads : {1u, 2u}) {
    SCOPED_TRACE(std::to_string(threads) + " threads");
    Options options;
    options.threads = threads;
    detail::ResearchOptions research;
    research.worker_minimums = {0, 0, true};
    const ConvexPolyhedron p = detail::minkowski_sum(a, b, options, research).polyhedron;
    ASSERT_NE(MeshAccess::packed_positions(p.mesh()), nullptr);
    ASSERT_NE(PolyhedronAccess::planes(p).packed_normals, nullptr);
    const detail::ResultSlab* slab = MeshAccess::packed_positions(p.mesh())->slab();
    ASSERT_NE(slab, nullptr);
    const detail::ResultSlab* planes_slab = PolyhedronAccess::planes(p).packed_normals->packed().slab();
    ASSERT_NE(planes_slab, nullptr);
    EXPECT_NE(planes_slab, slab);
    EXPECT_TRUE(slab->holds(&MeshAccess::packed_positions(p.mesh())->coordinate(0, 0)));
    EXPECT_TRUE(slab->holds(PolyhedronAccess::approximations(p).vertices.data()));
    EXPECT_TRUE(planes_slab->holds(&PolyhedronAccess::planes(p).packed_normals->packed().coordinate(0, 0)));
    EXPECT_TRUE(planes_slab->holds(&PolyhedronAccess::planes(p).normal_approx[0]));
    for (const detail::ResultSlab* s : {slab, planes_slab}) {
      EXPECT_FALSE(s->refused()) << "an array did not fit: the plan fell short";
      EXPECT_EQ(s->carved(), s->size()) << "the plan and what was carved differ";
    }
    const ConvexPolyhedron copy = p;  // shares the packed values, and the slab with them
    EXPECT_EQ(MeshAccess::packed_positions(copy.mesh())->slab(), slab);
  }
}

// A sum's output has its normals from its builder and makes its offsets when
// one is first asked for (lib/mesh/facet_planes.hpp). Readers on several
// threads that ask at once all read the one set made (the same addresses),
// and every offset is dot(normal, x) for every vertex x of its facet, worked
// out here in rationals; a copy taken before makes its own equal set, one
// taken after copies it (and owns its limbs). Under TSan this is the test of
// the once-only construction of the offsets.
TEST(ArenaStorage, SumOffsetsAreMadeOnceForConcurrentReaders) {
  const ConvexPolyhedron a = shapes::geodesic_sphere(3);
  const ConvexPolyhedron b = shapes::rotated_geodesic_sphere(3).translated(Vec3{Rational(1, 3), 0, 5});
  constexpr int num_readers = 4;
  for (const unsigned threads : {1u, 2u}) {
    Options options;
    options.threads = threads;
    detail::ResearchOptions research;
    research.worker_minimums.oversubscribe = true;
    const ConvexPolyhedron p = detail::minkowski_sum(a, b, options, research).polyhedron;
    const ConvexPolyhedron copy_before = p;
    // Translated before any offset is made: the image makes its own.
    const Vec3 shift{Rational(-2, 3), 7, Rational(1, 1024)};
    const ConvexPolyhedron shifted = p.translated(shift);
    const auto seen = addresses_read_at_once(p, num_readers, [](const ConvexPolyhedron& q, FaceId f) {
      return static_cast<const void*>(&q.plane_offset(f));
    });
    for (int t = 1; t < num_readers; ++t)
      ASSERT_EQ(seen[0], seen[static_cast<std::size_t>(t)])
          << "reader " << t << " read another set of offsets (" << threads << " threads)";
    const ConvexPolyhedron copy_after = p;
    for (FaceId f : p.mesh().faces()) {
      for (HalfedgeId h : p.mesh().face_halfedges(f))
        ASSERT_EQ(p.plane_offset(f), dot(p.normal(f), p.vertex(p.mesh().from(h)))) << "facet " << f.index();
      ASSERT_EQ(copy_before.plane_offset(f), p.plane_offset(f))
          << "facet " << f.index() << " of the copy before";
      ASSERT_EQ(copy_after.plane_offset(f), p.plane_offset(f))
          << "facet " << f.index() << " of the copy after";
    }
    for (FaceId f : shifted.mesh().faces())
      ASSERT_EQ(shifted.plane_offset(f), p.plane_offset(f) + dot(p.normal(f), shift))
          << "facet " << f.index();
    EXPECT_TRUE(numerators_are_views(copy_after, false, Offsets::included, Packed::excluded));  // copied, not made again
    if (detail::LimbArena::holds_limbs()) {
      EXPECT_TRUE(numerators_are_views(p, true));
      // Made by the copy itself, into its own arena: views.
      EXPECT_TRUE(numerators_are_views(copy_before, false, Offsets::excluded, Packed::excluded));
      for (FaceId f : copy_before.mesh().faces())
        ASSERT_TRUE(sgn(copy_before.plane_offset(f)) == 0 ||
                    mpq_numref(copy_before.plane_offset(f).get_mpq_t())->_mp_alloc == 0)
            << "facet " << f.index() << " of the copy before";
    }
  }
}

}  // namespace
}  // namespace cvms
