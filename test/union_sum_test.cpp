// SPDX-License-Identifier: MIT
// Tests of the sum of two unions of convex pieces against the reference
// oracle: each piece (i, j) of the sum has the vertex set of chms(Ai, Bj),
// the exact hull of the pairwise vertex sums; the same pieces for every
// thread count and algorithm; the limits (per pair and in all) and the
// errors of a pair, named deterministically.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cvms/convex_union.hpp"
#include "cvms/error.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/shapes.hpp"
#include "support/union_oracle.hpp"

namespace cvms {
namespace {

using test::random_union;
using test::vertex_set;

Vec3 v(long x, long y, long z) { return {Rational(x), Rational(y), Rational(z)}; }

// Two boxes forming an L (in the xz plane), a cube and a tetrahedron.
ConvexUnion l_shape() {
  return ConvexUnion(std::vector<ConvexPolyhedron>{shapes::box(v(0, 0, 0), v(3, 1, 1)),
                                                   shapes::box(v(0, 0, 1), v(1, 1, 3))});
}
ConvexUnion cube_and_tetrahedron() {
  return ConvexUnion(std::vector<ConvexPolyhedron>{shapes::cube(), shapes::tetrahedron()});
}

// Every piece (i, j) of the sum against chms(Ai, Bj), as vertex sets.
std::string check_against_chms(const ConvexUnion& a, const ConvexUnion& b, const ConvexUnion& sum) {
  if (sum.size() != a.size() * b.size()) return "wrong piece count " + std::to_string(sum.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t j = 0; j < b.size(); ++j) {
      const ConvexPolyhedron& piece = sum.pieces()[i * b.size() + j];
      if (vertex_set(piece) != vertex_set(chms(a.pieces()[i], b.pieces()[j]))) {
        return "piece (" + std::to_string(i) + ", " + std::to_string(j) + ") differs from chms";
      }
      if (!piece.is_convex())
        return "piece (" + std::to_string(i) + ", " + std::to_string(j) + ") not convex";
    }
  }
  return "";
}

// The pieces' vertices in their own order: equal results, numbering included.
std::vector<std::vector<Vec3>> layout(const ConvexUnion& u) {
  std::vector<std::vector<Vec3>> out;
  for (const ConvexPolyhedron& piece : u.pieces()) {
    std::vector<Vec3> vertices;
    for (VertexId vertex : piece.mesh().vertices()) vertices.push_back(piece.vertex(vertex));
    out.push_back(std::move(vertices));
  }
  return out;
}

Options with_threads(unsigned threads, Algorithm algorithm = Algorithm::cvms) {
  Options options;
  options.threads = threads;
  options.algorithm = algorithm;
  return options;
}

TEST(UnionSum, HandMadePiecesMatchChmsForEveryAlgorithm) {
  const ConvexUnion pieces[] = {l_shape(), cube_and_tetrahedron(),
                                ConvexUnion(std::vector<ConvexPolyhedron>{shapes::octahedron()})};
  for (Algorithm algorithm : {Algorithm::cvms, Algorithm::essdms, Algorithm::chms}) {
    for (const ConvexUnion& a : pieces) {
      for (const ConvexUnion& b : pieces) {
        SCOPED_TRACE(to_string(algorithm));
        EXPECT_EQ(check_against_chms(a, b, minkowski_sum(a, b, with_threads(2, algorithm))), "");
      }
    }
  }
}

TEST(UnionSum, LShapePlusCubeIsAnLShapeGrown) {
  // [0,3]x[0,1]x[0,1] + [-1,1]^3 = [-1,4]x[-1,2]x[-1,2]; the upright box
  // grows to [-1,2]x[-1,2]x[0,4]: points of the sum, and one just outside.
  const ConvexUnion sum =
      minkowski_sum(l_shape(), ConvexUnion(std::vector<ConvexPolyhedron>{shapes::cube()}));
  ASSERT_EQ(sum.size(), 2U);
  EXPECT_TRUE(sum.contains(v(4, 2, 2)));
  EXPECT_TRUE(sum.contains(v(2, 2, 4)));
  EXPECT_TRUE(sum.contains(v(-1, -1, -1)));
  EXPECT_FALSE(sum.contains(v(3, 0, 3)));
  EXPECT_FALSE(sum.contains(Vec3{Rational(4), Rational(0), Rational(21, 10)}));
}

TEST(UnionSum, RandomUnionsMatchChmsAndThreadCounts) {
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const ConvexUnion a = random_union(seed, 1 + static_cast<int>(seed % 3));
    const ConvexUnion b = random_union(1000 + seed, 1 + static_cast<int>(seed % 4));
    const ConvexUnion one = minkowski_sum(a, b, with_threads(1));
    EXPECT_EQ(check_against_chms(a, b, one), "");
    for (unsigned threads : {2U, 4U}) {
      EXPECT_EQ(layout(minkowski_sum(a, b, with_threads(threads))), layout(one)) << threads << " threads";
    }
  }
}

TEST(UnionSum, EmptyOperandIsInvalid) {
  const ConvexUnion some = cube_and_tetrahedron();
  for (const auto& [a, b] : {std::pair(ConvexUnion(), some), std::pair(some, ConvexUnion()),
                             std::pair(ConvexUnion(std::vector<ConvexPolyhedron>{}), some)}) {
    try {
      (void)minkowski_sum(a, b);
      ADD_FAILURE() << "no error";
    } catch (const Error& e) {
      EXPECT_EQ(e.category(), ErrorCategory::invalid_argument);
      EXPECT_NE(std::string(e.message()).find("no pieces"), std::string::npos) << e.what();
    }
  }
}

// The message of the error the sum throws, or "" if none.
std::string error_of(const ConvexUnion& a, const ConvexUnion& b, const Options& options,
                     ErrorCategory expected = ErrorCategory::limit) {
  try {
    (void)minkowski_sum(a, b, options);
  } catch (const Error& e) {
    EXPECT_EQ(e.category(), expected) << e.what();
    return e.message();
  }
  return "";
}

TEST(UnionSum, APairBeyondItsLimitIsNamedTheSameForEveryThreadCount) {
  // Cube + cube has 6 facets; every pair with the sphere has many more. The
  // first of those in (i, j) order is (0, 1).
  const ConvexPolyhedron sphere = shapes::geodesic_sphere(1);
  const ConvexUnion a(std::vector<ConvexPolyhedron>{shapes::cube(), sphere, sphere});
  const ConvexUnion b(std::vector<ConvexPolyhedron>{shapes::cube(), sphere});
  for (unsigned threads : {1U, 2U, 4U}) {
    Options options = with_threads(threads);
    options.limits.max_output_facets = 24;
    const std::string message = error_of(a, b, options);
    EXPECT_NE(message.find("pair (0, 1)"), std::string::npos) << threads << " threads: " << message;
    EXPECT_NE(message.find("max_output_facets"), std::string::npos) << message;
  }
}

TEST(UnionSum, TheTotalIsLimitedAtTheFirstPairThatPassesIt) {
  // Three cube + cube pairs of 6 facets: 6, 12, 18 in all; each pair fits 13.
  const ConvexUnion a(std::vector<ConvexPolyhedron>{shapes::cube(), shapes::cube(), shapes::cube()});
  const ConvexUnion b(std::vector<ConvexPolyhedron>{shapes::cube()});
  for (unsigned threads : {1U, 2U, 4U}) {
    Options options = with_threads(threads);
    options.limits.max_output_facets = 13;
    const std::string message = error_of(a, b, options);
    EXPECT_NE(message.find("up to pair (2, 0) has 18 facets"), std::string::npos)
        << threads << ": " << message;
    options.limits.max_output_facets = 18;
    EXPECT_EQ(error_of(a, b, options), "");
  }
  // The memory limit, at bytes_per_output_facet a facet: 12 facets fit, not 18.
  Options options;
  options.limits.max_memory_bytes = 12 * SumLimits::bytes_per_output_facet;
  const std::string message = error_of(a, b, options);
  EXPECT_NE(message.find("max_memory_bytes"), std::string::npos) << message;
  EXPECT_NE(message.find("pair (2, 0)"), std::string::npos) << message;
}

TEST(UnionSum, TooManyPairsAreRefusedBeforeAnySum) {
  std::vector<ConvexPolyhedron> cubes(6, shapes::cube());
  const ConvexUnion a(cubes), b(cubes);
  Options options;
  options.limits.max_output_facets = 100;  // 36 pairs of at least 4 facets: 144
  const std::string message = error_of(a, b, options);
  EXPECT_NE(message.find("6 x 6 pieces"), std::string::npos) << message;
}

TEST(UnionSum, AnErrorInEveryPairReportsTheFirst) {
  const ConvexUnion a = cube_and_tetrahedron();
  for (unsigned threads : {1U, 2U, 4U}) {
    Options options = with_threads(threads);
    options.algorithm = static_cast<Algorithm>(99);
    const std::string message = error_of(a, a, options, ErrorCategory::invalid_argument);
    EXPECT_NE(message.find("pair (0, 0)"), std::string::npos) << message;
  }
}

TEST(UnionSum, DiagnosticsAreSummedOverPairs) {
  const ConvexUnion a = random_union(7, 3), b = random_union(8, 2);
  SumDiagnostics expected;
  for (const ConvexPolyhedron& ai : a.pieces()) {
    for (const ConvexPolyhedron& bj : b.pieces()) {
      SumDiagnostics one;
      Options options;
      options.diagnostics = &one;
      (void)minkowski_sum(ai, bj, options);
      expected.contributing_ties += one.contributing_ties;
      expected.edge_candidates += one.edge_candidates;
    }
  }
  for (unsigned threads : {1U, 2U}) {
    SumDiagnostics total;
    total.edge_candidates = 12345;  // overwritten, not added to
    Options options = with_threads(threads);
    options.diagnostics = &total;
    (void)minkowski_sum(a, b, options);
    EXPECT_EQ(total.contributing_ties, expected.contributing_ties);
    EXPECT_EQ(total.edge_candidates, expected.edge_candidates);
  }
}

}  // namespace
}  // namespace cvms
