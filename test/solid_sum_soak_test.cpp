// SPDX-License-Identifier: MIT
// Soak run of minkowski_sum of solids: random polycubes (cubes of a small
// grid kept at random, touching ones included) summed with
// random integer boxes (the one-convex road) and with other random
// polycubes (both decomposed), some turned by a rational rotation, each
// result checked against the voxel oracle, brute force over the pieces and
// the pieces' planes (solid_sum_fixtures.hpp). The seed is printed on
// failure.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>

#include "solid_sum_fixtures.hpp"

namespace cvms::test {
namespace {

// Random cubes of a 4 x 4 x 3 grid, not none: every such polycube is a
// solid, cubes meeting only along an edge or at a corner too.
Cubes random_polycube(std::mt19937_64& rng) {
  for (;;) {
    const Cubes cubes = cubes_where(4, 4, 3, [&](int, int, int) { return rng() % 3 == 0; });
    if (!cubes.empty()) return cubes;
  }
}

TEST(SolidSumSoak, RandomPolycubesPlusBoxes) {
  for (std::uint64_t seed = 1; seed <= 60; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937_64 rng(seed);
    const Cubes a = random_polycube(rng);
    const Cubes box = box_cubes(1 + static_cast<int>(rng() % 3), 1 + static_cast<int>(rng() % 3),
                                1 + static_cast<int>(rng() % 2));
    const Mapping m = seed % 4 == 0 ? Mapping{rational_rotation(), Vec3{Rational(1, 3), 0, 0}} : Mapping{};
    expect_polycube_sum(a, box, m, seed);
  }
}

TEST(SolidSumSoak, RandomPolycubesPlusPolycubes) {
  for (std::uint64_t seed = 100; seed <= 115; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937_64 rng(seed);
    const Cubes a = random_polycube(rng), b = random_polycube(rng);
    expect_polycube_sum(a, b, {}, seed);
  }
}

}  // namespace
}  // namespace cvms::test
