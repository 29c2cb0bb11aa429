// SPDX-License-Identifier: MIT
// SumLimits: a sum's output size can be quadratic in its input. Two n-gon
// prisms with non-parallel axes have about n^2 / 2 output facets
// (n = 10,000: 3 MB of input, 5 x 10^7 facets, and unguarded the sum grows
// to tens of GB until the kernel kills it). Every algorithm must refuse
// such a sum with Error(limit) from counts it knows before it builds the
// output, and stop its search once the count passes the limit; a sum within
// the limits must be unaffected. The attack inputs are generated here.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "cvms/error.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/shapes.hpp"
#include "support/cpu_time.hpp"
#include "support/oracle.hpp"
#include "support/prism_attack.hpp"

namespace cvms {
namespace {

using test::describe;
using test::prism_attack;
using test::PrismPair;
using test::difference;
using test::Shape;

// "" if the shapes are equal, else what differs.
std::string mismatch(const Shape& expected, const Shape& actual) {
  return expected == actual ? std::string() : difference(expected, actual);
}

Options with(Algorithm algorithm, unsigned threads = 1) {
  Options options;
  options.algorithm = algorithm;
  options.threads = threads;
  return options;
}

// The message of the Error(limit) that minkowski_sum throws, or a failure.
std::string limit_message(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const Options& options) {
  try {
    (void)minkowski_sum(a, b, options);
  } catch (const Error& e) {
    EXPECT_EQ(e.category(), ErrorCategory::limit) << e.what();
    return e.message();
  }
  ADD_FAILURE() << "no limit error";
  return {};
}

// N of "the sum has at least N facets".
std::uint64_t facets_at_least(const std::string& message) {
  const std::string key = "has at least ";
  const std::size_t at = message.find(key);
  if (at == std::string::npos) {
    ADD_FAILURE() << "no count in: " << message;
    return 0;
  }
  return std::stoull(message.substr(at + key.size()));
}

// The exact facet count of the attack sum for n = 60, from CHMS (which has
// no facet limit and builds the hull of all pairwise sums): the oracle the
// limit boundaries below are checked against.
class PrismAttack : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    pair_ = new PrismPair(prism_attack(60));
    facets_ = chms(pair_->a, pair_->b).num_facets();
  }
  static void TearDownTestSuite() {
    delete pair_;
    pair_ = nullptr;
  }
  static PrismPair* pair_;
  static std::uint64_t facets_;
};
PrismPair* PrismAttack::pair_ = nullptr;
std::uint64_t PrismAttack::facets_ = 0;

// The prism pair's output is quadratic: the premise of the attack.
TEST_F(PrismAttack, OutputIsQuadraticInTheInput) {
  EXPECT_GT(facets_, 60u * 60u / 4) << "the attack sum is not quadratic: " << facets_ << " facets";
}

// At exactly the sum's facet count every algorithm succeeds (with the
// oracle's result); one below, CVMS and ESSDMS refuse, naming the limit.
TEST_F(PrismAttack, FacetLimitIsExactAtTheBoundary) {
  const test::Shape expected = describe(chms(pair_->a, pair_->b));
  for (Algorithm algorithm : {Algorithm::cvms, Algorithm::essdms}) {
    for (unsigned threads : {1u, 2u, 4u, 8u}) {
      SCOPED_TRACE(std::string(to_string(algorithm)) + " threads " + std::to_string(threads));
      Options options = with(algorithm, threads);
      options.limits.max_output_facets = facets_;
      const MinkowskiResult result = minkowski_sum(pair_->a, pair_->b, options);
      EXPECT_EQ(mismatch(expected, describe(result.polyhedron)), "");
      options.limits.max_output_facets = facets_ - 1;
      const std::string message = limit_message(pair_->a, pair_->b, options);
      EXPECT_NE(message.find("beyond the limit of " + std::to_string(facets_ - 1) +
                             " facets (SumLimits::max_output_facets)"),
                std::string::npos)
          << message;
      EXPECT_NE(message.find(std::string("minkowski_sum (") + to_string(algorithm) + ")"), std::string::npos)
          << message;
    }
  }
}

// The memory limit is facets x bytes_per_output_facet, exact at the boundary.
TEST_F(PrismAttack, MemoryLimitIsFacetsTimesBytesPerFacet) {
  Options options;
  options.limits.max_memory_bytes = facets_ * SumLimits::bytes_per_output_facet;
  EXPECT_EQ(minkowski_sum(pair_->a, pair_->b, options).polyhedron.num_facets(), facets_);
  options.limits.max_memory_bytes -= 1;
  const std::string message = limit_message(pair_->a, pair_->b, options);
  EXPECT_NE(message.find("bytes (SumLimits::max_memory_bytes)"), std::string::npos) << message;
  EXPECT_NE(message.find(std::to_string(SumLimits::bytes_per_output_facet) + " per facet"), std::string::npos)
      << message;
}

// The search stops once its running count passes the limit: it holds at
// most one edge's facets (e_B) beyond it, whatever the size of the sum, and
// the count it reports is the same with one thread or more.
TEST(SumLimits, PrismAttackStopsTheSearchNearTheLimit) {
  const PrismPair pair = prism_attack(1200);  // about 700,000 output facets
  Options options;
  options.limits.max_output_facets = 20000;
  const auto start = test::cpu_seconds();
  const std::string one_thread = limit_message(pair.a, pair.b, options);
  const double seconds = test::cpu_seconds() - start;
  const std::uint64_t found = facets_at_least(one_thread);
  EXPECT_GT(found, 20000u);
  EXPECT_LE(found, 20000u + pair.b.num_edges()) << one_thread;
  // A sum of 700,000 facets takes seconds; stopping at 20,000 a small part.
  EXPECT_LT(seconds, 2.0) << one_thread;
  for (const unsigned n : {2u, 4u, 8u}) {
    options.threads = n;
    EXPECT_EQ(limit_message(pair.a, pair.b, options), one_thread) << n << " threads";
  }
  // ESSDMS stops alike (its arc loop checks per arc of A).
  options.algorithm = Algorithm::essdms;
  const std::uint64_t essdms_found = facets_at_least(limit_message(pair.a, pair.b, options));
  EXPECT_GT(essdms_found, 20000u);
  EXPECT_LE(essdms_found, 20000u + pair.b.num_edges());
}

// With the translated and corner facets alone beyond the limit, the sum is
// refused before any edge facet is searched.
TEST(SumLimits, TranslatedAndCornerFacetsAreCheckedFirst) {
  const PrismPair pair = prism_attack(100);
  for (Algorithm algorithm : {Algorithm::cvms, Algorithm::essdms}) {
    Options options = with(algorithm);
    options.limits.max_output_facets = 150;
    const std::string message = limit_message(pair.a, pair.b, options);
    EXPECT_NE(message.find("and 0 edge facets"), std::string::npos) << message;
  }
}

// ESSDMS's quadratic loops are bounded before they start: the location
// pairs (f_A f_B + f_A e_B + f_B e_A + f_A v_B + f_B v_A), then the arc
// pairs that pass the pre-check.
TEST(SumLimits, EssdmsPairTestsAreBoundedBeforeTheLoops) {
  const PrismPair pair = prism_attack(40);
  const ConvexPolyhedron& a = pair.a;
  const ConvexPolyhedron& b = pair.b;
  const std::uint64_t locations = std::uint64_t{a.num_facets()} * b.num_facets() +
                                  std::uint64_t{a.num_facets()} * b.num_edges() +
                                  std::uint64_t{b.num_facets()} * a.num_edges() +
                                  std::uint64_t{a.num_facets()} * b.num_vertices() +
                                  std::uint64_t{b.num_facets()} * a.num_vertices();
  Options options = with(Algorithm::essdms);
  options.limits.max_pair_tests = locations - 1;
  std::string message = limit_message(a, b, options);
  EXPECT_NE(message.find("facet point locations"), std::string::npos) << message;
  EXPECT_NE(message.find(std::to_string(locations)), std::string::npos) << message;
  options.limits.max_pair_tests = locations;
  message = limit_message(a, b, options);
  EXPECT_NE(message.find("arc pairs that pass the pre-check"), std::string::npos) << message;
  EXPECT_NE(message.find("(SumLimits::max_pair_tests)"), std::string::npos) << message;
  // CVMS ignores max_pair_tests: its searches are output-sensitive.
  options.algorithm = Algorithm::cvms;
  EXPECT_EQ(mismatch(describe(chms(a, b)), describe(minkowski_sum(a, b, options).polyhedron)), "");
}

// CHMS's pair limit in memory: v_A v_B x bytes_per_pairwise_sum against
// max_memory_bytes, exact at the boundary, checked before any sum is made.
TEST(SumLimits, ChmsPairwiseSumsAreBoundedByMemory) {
  const ConvexPolyhedron cube = shapes::cube();
  const ConvexPolyhedron octa = shapes::octahedron();
  SumLimits limits;
  limits.max_memory_bytes = 8 * 6 * SumLimits::bytes_per_pairwise_sum;
  EXPECT_EQ(chms(cube, octa, limits).num_facets(), 26u);  // the rhombicuboctahedron-like sum
  limits.max_memory_bytes -= 1;
  try {
    (void)chms(cube, octa, limits);
    ADD_FAILURE() << "no limit error";
  } catch (const Error& e) {
    EXPECT_EQ(e.category(), ErrorCategory::limit);
    EXPECT_NE(std::string(e.message()).find("8 x 6 pairwise vertex sums need about 6144 bytes"),
              std::string::npos)
        << e.what();
  }
  // minkowski_sum passes its limits to CHMS.
  Options options = with(Algorithm::chms);
  options.limits = limits;
  EXPECT_NE(limit_message(cube, octa, options).find("SumLimits::max_memory_bytes"), std::string::npos);
}

// The default CHMS limit refuses what the old 2^32 limit let through: two
// 3,000-gon prisms are 3.6 x 10^7 pairwise sums, beyond the 2^25 that 4 GiB
// allow (Sphere6 + rotated Sphere6, 10^8 sums, would need about 13 GB).
TEST(SumLimits, ChmsDefaultRefusesSumsBeyondMemory) {
  const PrismPair pair = prism_attack(3000);
  try {
    (void)chms(pair.a, pair.b);
    ADD_FAILURE() << "no limit error";
  } catch (const Error& e) {
    EXPECT_EQ(e.category(), ErrorCategory::limit);
    EXPECT_NE(std::string(e.message()).find("6000 x 6000 pairwise vertex sums"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.message()).find("beyond the limit of 4294967296 bytes"), std::string::npos)
        << e.what();
  }
}

// The defaults admit honest sums: Cube + Sphere4 and Sphere3 + rotated
// Sphere3 agree with CHMS under every algorithm's default limits.
TEST(SumLimits, DefaultsAdmitHonestSums) {
  const ConvexPolyhedron cube = shapes::cube();
  const ConvexPolyhedron s4 = shapes::geodesic_sphere(4);
  const ConvexPolyhedron s3 = shapes::geodesic_sphere(3);
  const ConvexPolyhedron r3 = shapes::rotated_geodesic_sphere(3);
  for (Algorithm algorithm : {Algorithm::cvms, Algorithm::essdms, Algorithm::chms}) {
    SCOPED_TRACE(to_string(algorithm));
    EXPECT_EQ(mismatch(describe(chms(cube, s4)), describe(minkowski_sum(cube, s4, with(algorithm)).polyhedron)),
              "");
    EXPECT_EQ(mismatch(describe(chms(s3, r3)), describe(minkowski_sum(s3, r3, with(algorithm)).polyhedron)),
              "");
  }
}

TEST(SumLimits, DefaultsAreDocumentedValues) {
  const SumLimits limits;
  EXPECT_EQ(limits.max_output_facets, std::uint64_t{1} << 26);
  EXPECT_EQ(limits.max_memory_bytes, std::uint64_t{4} << 30);
  EXPECT_EQ(limits.max_pair_tests, std::uint64_t{1} << 34);
  EXPECT_EQ(Options{}.limits.max_memory_bytes, limits.max_memory_bytes);
}

}  // namespace
}  // namespace cvms
