// SPDX-License-Identifier: MIT
// Random convex sets (see the header).
#include "support/random_sets.hpp"

#include <vector>

#include "cvms/convex_hull.hpp"
#include "support/random_numbers.hpp"

namespace cvms::test {

ConvexSet random_set(std::mt19937_64& rng, int dimension, const Vec3& origin, int radius, int max_extra) {
  std::uniform_int_distribution<int> small(-radius, radius);
  auto grid = [&] { return Vec3{Rational(small(rng)), Rational(small(rng)), Rational(small(rng))}; };
  auto coefficient = [&] { return fraction(small(rng), 1 + static_cast<long>(rng() % 2)); };
  for (;;) {
    Vec3 basis[3];
    for (int k = 0; k < 3; ++k)
      basis[k] = rng() % 3 == 0 ? grid() : Vec3{Rational(k == 0), Rational(k == 1), Rational(k == 2)};
    std::vector<Vec3> points;
    const int n = dimension == 0 ? 1 : dimension + 1 + static_cast<int>(rng() % static_cast<unsigned>(max_extra));
    for (int i = 0; i < n; ++i) {
      Vec3 p = origin;
      for (int k = 0; k < dimension; ++k) p += coefficient() * basis[k];
      points.push_back(p);
    }
    ConvexSet s = convex_hull_set(points);
    if (s.dimension() == dimension) return s;
  }
}

}  // namespace cvms::test
