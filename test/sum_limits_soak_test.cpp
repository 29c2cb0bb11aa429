// SPDX-License-Identifier: MIT
// Soak (label "soak"): SumLimits at their defaults on full-size inputs whose
// output is quadratic in the input. Two 10,000-gon prisms with non-parallel
// axes (3 MB as OFF, 5 x 10^7 output facets, tens of GB unguarded) must
// be refused by the default limits within seconds; Sphere7 + rotated
// Sphere7, an honest large sum, must pass them.
#include <gtest/gtest.h>

#include <string>

#include "cvms/error.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/shapes.hpp"
#include "support/cpu_time.hpp"
#include "support/prism_attack.hpp"

namespace cvms {
namespace {

double seconds_since(double start) {
  return test::cpu_seconds() - start;
}

TEST(SumLimitsSoak, PrismAttackIsRefusedAtTheDefaults) {
  const test::PrismPair pair = test::prism_attack(10000);
  const ConvexPolyhedron& a = pair.a;
  const ConvexPolyhedron& b = pair.b;
  for (Algorithm algorithm : {Algorithm::cvms, Algorithm::chms}) {
    SCOPED_TRACE(to_string(algorithm));
    Options options;
    options.algorithm = algorithm;
    const auto start = test::cpu_seconds();
    try {
      (void)minkowski_sum(a, b, options);
      ADD_FAILURE() << "no limit error";
    } catch (const Error& e) {
      EXPECT_EQ(e.category(), ErrorCategory::limit) << e.what();
      EXPECT_NE(std::string(e.message()).find("SumLimits::max_memory_bytes"), std::string::npos) << e.what();
    }
    // The full sum would run for minutes; the search stops at about 4.2
    // million facets (CVMS), CHMS before its first sum.
    EXPECT_LT(seconds_since(start), 20.0);
  }
}

TEST(SumLimitsSoak, Sphere7PairPassesTheDefaults) {
  const ConvexPolyhedron s7 = shapes::geodesic_sphere(7);
  const ConvexPolyhedron r7 = shapes::rotated_geodesic_sphere(7);
  const MinkowskiResult sum = minkowski_sum(s7, r7);
  // docs/performance.md, Sphere_k + rotated Sphere_k, k = 7 (also computed by the
  // paper-faithful search and by two threads there).
  EXPECT_EQ(sum.polyhedron.num_facets(), 255898u);
  EXPECT_EQ(sum.stats.translated_facets + sum.stats.corner_facets + sum.stats.edge_facets, 255898u);
}

}  // namespace
}  // namespace cvms
