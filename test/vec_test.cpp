// SPDX-License-Identifier: MIT
// Exact vectors and 3x3 matrices: operations against hand-computed values
// and algebraic identities, hashing of equal values, determinants against
// the Leibniz formula.
#include "cvms/vec.hpp"

#include <gtest/gtest.h>

#include <array>
#include <set>
#include <string>
#include <unordered_set>

#include "support/random_numbers.hpp"

namespace cvms {
namespace {

using test::fraction;

Vec3 random_vec3(test::Rng& rng) {
  return {test::random_rational(rng), test::random_rational(rng), test::random_rational(rng)};
}
Vec3 small_vec3(test::Rng& rng) {
  auto r = [&] { return fraction(static_cast<long>(rng() % 21) - 10, static_cast<long>(rng() % 4) + 1); };
  return {r(), r(), r()};
}

TEST(Vec, Vec2Operations) {
  Vec2 a{1, fraction(1, 2)}, b{fraction(-1, 3), 4};
  EXPECT_EQ(a + b, (Vec2{fraction(2, 3), fraction(9, 2)}));
  EXPECT_EQ(a - b, (Vec2{fraction(4, 3), fraction(-7, 2)}));
  EXPECT_EQ(-a, (Vec2{-1, fraction(-1, 2)}));
  EXPECT_EQ(Rational(2) * a, (Vec2{2, 1}));
  EXPECT_EQ(a * Rational(2), (Vec2{2, 1}));
  EXPECT_EQ(dot(a, b), fraction(-1, 3) + 2);
  EXPECT_EQ(cross(a, b), Rational(4) + fraction(1, 6));  // 1*4 - (1/2)(-1/3)
  EXPECT_GT(sgn(cross(Vec2{1, 0}, Vec2{0, 1})), 0);      // counterclockwise is positive
  Vec2 c = a;
  c += b;
  EXPECT_EQ(c, a + b);
  c -= b;
  EXPECT_EQ(c, a);
  EXPECT_NE(a, b);
  EXPECT_TRUE((Vec2{1, 5}) < (Vec2{2, 0}));
  EXPECT_TRUE((Vec2{1, 0}) < (Vec2{1, 5}));
  EXPECT_FALSE((Vec2{1, 5}) < (Vec2{1, 5}));
}

TEST(Vec, Vec3Operations) {
  Vec3 a{1, 2, 3}, b{fraction(1, 2), -1, 0};
  EXPECT_EQ(a + b, (Vec3{fraction(3, 2), 1, 3}));
  EXPECT_EQ(a - b, (Vec3{fraction(1, 2), 3, 3}));
  EXPECT_EQ(-b, (Vec3{fraction(-1, 2), 1, 0}));
  EXPECT_EQ(fraction(1, 3) * a, (Vec3{fraction(1, 3), fraction(2, 3), 1}));
  EXPECT_EQ(a * fraction(1, 3), fraction(1, 3) * a);
  EXPECT_EQ(dot(a, b), fraction(-3, 2));
  // cross = (2*0 - 3*(-1), 3*(1/2) - 1*0, 1*(-1) - 2*(1/2)) = (3, 3/2, -2).
  EXPECT_EQ(cross(a, b), (Vec3{3, fraction(3, 2), -2}));
  EXPECT_EQ(cross(Vec3{1, 0, 0}, Vec3{0, 1, 0}), (Vec3{0, 0, 1}));  // right-handed
  EXPECT_EQ(a[0], 1);
  EXPECT_EQ(a[1], 2);
  EXPECT_EQ(a[2], 3);
  Vec3 c = a;
  c[1] = 7;
  EXPECT_EQ(c, (Vec3{1, 7, 3}));
  c += b;
  c -= b;
  EXPECT_EQ(c, (Vec3{1, 7, 3}));
  EXPECT_TRUE(is_zero(Vec3{}));
  EXPECT_FALSE(is_zero(Vec3{0, 0, fraction(1, 1000)}));
  EXPECT_TRUE((Vec3{1, 2, 3}) < (Vec3{1, 2, 4}));
  EXPECT_TRUE((Vec3{1, 2, 9}) < (Vec3{1, 3, 0}));
  EXPECT_FALSE((Vec3{1, 2, 3}) < (Vec3{1, 2, 3}));
}

TEST(Vec, CrossAndDotIdentities) {
  test::Rng rng(1);
  for (int i = 0; i < 500; ++i) {
    SCOPED_TRACE("case " + std::to_string(i));
    Vec3 a = i % 2 ? random_vec3(rng) : small_vec3(rng), b = small_vec3(rng), c = small_vec3(rng);
    Vec3 n = cross(a, b);
    ASSERT_EQ(dot(n, a), 0);
    ASSERT_EQ(dot(n, b), 0);
    ASSERT_EQ(cross(b, a), -n);
    // Lagrange: |a x b|^2 = |a|^2 |b|^2 - (a.b)^2.
    ASSERT_EQ(dot(n, n), dot(a, a) * dot(b, b) - dot(a, b) * dot(a, b));
    // Triple product is cyclic; bilinearity.
    ASSERT_EQ(dot(a, cross(b, c)), dot(b, cross(c, a)));
    ASSERT_EQ(cross(a + c, b), cross(a, b) + cross(c, b));
    ASSERT_EQ(dot(Rational(3) * a, b), 3 * dot(a, b));
    ASSERT_EQ(a + b - b, a);
  }
}

TEST(Vec, EqualValuesHashEqual) {
  // Same value built in different ways: gmpxx keeps rationals canonical.
  Rational half_a = fraction(2, 4), half_b = parse_rational("0.5"), half_c = Rational(1) / 2;
  EXPECT_EQ(hash_value(half_a), hash_value(half_b));
  EXPECT_EQ(hash_value(half_a), hash_value(half_c));
  EXPECT_EQ(hash_value(parse_rational("-0")), hash_value(Rational(0)));
  EXPECT_EQ(hash_value(Rational(3) - Rational(3)), hash_value(Rational(0)));
  Vec3 v{half_a, parse_rational("1e-30"), -7};
  Vec3 w{half_b, Rational(1) / test::power_of_ten(30), parse_rational("-14/2")};
  EXPECT_EQ(std::hash<Vec3>{}(v), std::hash<Vec3>{}(w));
  EXPECT_EQ(std::hash<Vec2>{}(Vec2{half_a, 3}), std::hash<Vec2>{}(Vec2{half_c, fraction(9, 3)}));

  std::unordered_set<Vec3> set;
  test::Rng rng(2);
  std::vector<Vec3> values;
  for (int i = 0; i < 2000; ++i) values.push_back(small_vec3(rng));
  for (const Vec3& p : values) set.insert(p);
  for (const Vec3& p : values) set.insert(p + Vec3{} * Rational(5));  // equal values, new objects
  std::set<Vec3> ordered(values.begin(), values.end());
  EXPECT_EQ(set.size(), ordered.size());

  // Different values rarely collide.
  std::unordered_set<std::size_t> hashes;
  for (const Vec3& p : ordered) hashes.insert(hash_value(p));
  EXPECT_EQ(hashes.size(), ordered.size());  // 64-bit hashes of ~2000 values: no collision expected
  EXPECT_NE(hash_value(Vec3{1, 2, 3}), hash_value(Vec3{3, 2, 1}));
  EXPECT_NE(hash_value(Rational(1, 2)), hash_value(Rational(2)));
  EXPECT_NE(hash_value(Rational(-2)), hash_value(Rational(2)));
}

Mat3 random_mat(test::Rng& rng) {
  Mat3 m;
  for (auto& row : m.m)
    for (auto& x : row) x = fraction(static_cast<long>(rng() % 11) - 5, static_cast<long>(rng() % 3) + 1);
  return m;
}

// Leibniz: sum over the six permutations of sign * product.
Rational leibniz(const Mat3& a) {
  const std::array<std::array<int, 3>, 6> perms = {
      {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}}};
  Rational det = 0;
  for (int p = 0; p < 6; ++p) {
    Rational term = a.m[0][perms[p][0]] * a.m[1][perms[p][1]] * a.m[2][perms[p][2]];
    det += p < 3 ? term : Rational(-term);
  }
  return det;
}

TEST(Vec, Mat3) {
  Mat3 id = Mat3::identity();
  EXPECT_EQ(id.determinant(), 1);
  Vec3 v{1, fraction(-2, 3), 5};
  EXPECT_EQ(id * v, v);
  Mat3 diag;
  diag.m[0][0] = 2;
  diag.m[1][1] = fraction(1, 3);
  diag.m[2][2] = -5;
  EXPECT_EQ(diag.determinant(), fraction(-10, 3));
  EXPECT_EQ(diag * v, (Vec3{2, fraction(-2, 9), -25}));
  Mat3 swap;  // a permutation: determinant -1
  swap.m[0][1] = swap.m[1][0] = swap.m[2][2] = 1;
  EXPECT_EQ(swap.determinant(), -1);
  EXPECT_EQ(swap * v, (Vec3{fraction(-2, 3), 1, 5}));
  Mat3 singular = id;
  for (int j = 0; j < 3; ++j) singular.m[2][j] = singular.m[0][j] + 2 * singular.m[1][j];
  EXPECT_EQ(singular.determinant(), 0);

  test::Rng rng(3);
  for (int i = 0; i < 300; ++i) {
    SCOPED_TRACE("case " + std::to_string(i));
    Mat3 a = random_mat(rng), b = random_mat(rng);
    Vec3 x = small_vec3(rng);
    ASSERT_EQ(a.determinant(), leibniz(a));
    Mat3 ab = a * b;
    ASSERT_EQ(ab * x, a * (b * x));
    ASSERT_EQ(ab.determinant(), a.determinant() * b.determinant());
    ASSERT_EQ((a * id).determinant(), a.determinant());
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(ab.m[r][c], a.m[r][0] * b.m[0][c] + a.m[r][1] * b.m[1][c] + a.m[r][2] * b.m[2][c]);
  }
}

}  // namespace
}  // namespace cvms
