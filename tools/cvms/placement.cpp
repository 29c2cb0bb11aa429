// SPDX-License-Identifier: MIT
// See placement.hpp. The quaternion q = (w, x, y, z) turns x into
// q x q* / |q|^2, whose matrix is
//   1/n [w²+x²−y²−z²   2(xy−wz)      2(xz+wy)    ]
//       [2(xy+wz)      w²−x²+y²−z²   2(yz−wx)    ]
//       [2(xz−wy)      2(yz+wx)      w²−x²−y²+z² ]
// with n = w²+x²+y²+z²: rational for rational w, x, y, z, and a rotation
// for every nonzero q (no square root of n is needed, so it stays exact).
#include "placement.hpp"

#include <algorithm>

#include "cvms/convex_hull.hpp"
#include "cvms/rational.hpp"
#include "cvms/vec.hpp"
#include "usage_error.hpp"

namespace cvms::cli {
namespace {

std::vector<Rational> numbers(const std::vector<std::string>& texts, const std::string& option) {
  std::vector<Rational> values;
  for (const std::string& text : texts) {
    const std::optional<Rational> value = try_parse_rational(text);
    if (!value) throw UsageError(option + ": '" + text + "' is not a number (integer, decimal or p/q)");
    values.push_back(*value);
  }
  return values;
}

Mat3 matrix(const std::vector<Rational>& v) {
  Mat3 m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m.m[i][j] = v[static_cast<std::size_t>(3 * i + j)];
  return m;
}

Mat3 quaternion_matrix(const std::vector<Rational>& q, const std::string& option) {
  const Rational &w = q[0], &x = q[1], &y = q[2], &z = q[3];
  const Rational n = w * w + x * x + y * y + z * z;
  if (sgn(n) == 0) throw UsageError(option + ": the zero quaternion is no rotation");
  Mat3 m;
  m.m[0][0] = (w * w + x * x - y * y - z * z) / n;
  m.m[0][1] = 2 * (x * y - w * z) / n;
  m.m[0][2] = 2 * (x * z + w * y) / n;
  m.m[1][0] = 2 * (x * y + w * z) / n;
  m.m[1][1] = (w * w - x * x + y * y - z * z) / n;
  m.m[1][2] = 2 * (y * z - w * x) / n;
  m.m[2][0] = 2 * (x * z - w * y) / n;
  m.m[2][1] = 2 * (y * z + w * x) / n;
  m.m[2][2] = (w * w - x * x - y * y + z * z) / n;
  return m;
}

// A rotation: R^T R == I exactly and det R == 1 (not a reflection).
void check_rotation(const Mat3& r, const std::string& option) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const Rational dot = r.m[0][i] * r.m[0][j] + r.m[1][i] * r.m[1][j] + r.m[2][i] * r.m[2][j];
      if (dot != (i == j ? 1 : 0))
        throw UsageError(option + ": not a rotation (its columns are not orthonormal: column " +
                         std::to_string(i + 1) + " . column " + std::to_string(j + 1) + " = " + to_string(dot) +
                         "); --linear takes any invertible matrix");
    }
  if (r.determinant() != 1)
    throw UsageError(option + ": not a rotation (determinant -1, a reflection); --linear takes any invertible matrix");
}

// The linear part, if any: one of --rotate, --quaternion, --linear (CLI11
// lets only one through).
std::optional<Mat3> linear_part(const Placement& p, const std::string& operand) {
  if (!p.rotate.empty()) {
    const std::string option = "--rotate-" + operand;
    Mat3 r = matrix(numbers(p.rotate, option));
    check_rotation(r, option);
    return r;
  }
  if (!p.quaternion.empty()) {
    const std::string option = "--quaternion-" + operand;
    return quaternion_matrix(numbers(p.quaternion, option), option);
  }
  if (!p.linear.empty()) {
    const std::string option = "--linear-" + operand;
    Mat3 m = matrix(numbers(p.linear, option));
    if (sgn(m.determinant()) == 0) throw UsageError(option + ": the matrix is singular (determinant 0)");
    return m;
  }
  return std::nullopt;
}

// A flat set's image is the hull of its vertices' images (a linear map
// keeps convexity, and an invertible one keeps the dimension).
ConvexSet linear_image(const ConvexSet& set, const Mat3& m) {
  if (set.dimension() == 3) return set.polyhedron().transformed(m, Vec3{});
  std::vector<Vec3> v = set.vertices();
  for (Vec3& p : v) p = m * p;
  return convex_hull_set(v);
}

}  // namespace

void add_placement_options(CLI::App& command, Placement& placement, const std::string& operand) {
  const std::string upper = operand == "a" ? "A" : "B";
  CLI::Option* rotate = command.add_option("--rotate-" + operand, placement.rotate,
                                           "rotate " + upper + " by this exact rotation matrix (9 numbers, row-major)");
  rotate->expected(9)->allow_extra_args(false);
  CLI::Option* quaternion =
      command.add_option("--quaternion-" + operand, placement.quaternion,
                         "rotate " + upper + " by the quaternion w x y z (any nonzero one; exact, no normalising)");
  quaternion->expected(4)->allow_extra_args(false);
  CLI::Option* linear = command.add_option("--linear-" + operand, placement.linear,
                                           "map " + upper + " by any invertible matrix (9 numbers, row-major)");
  linear->expected(9)->allow_extra_args(false);
  rotate->excludes(quaternion)->excludes(linear);
  quaternion->excludes(linear);
  command.add_option("--translate-" + operand, placement.translate, "then translate " + upper + " by x y z")
      ->expected(3)
      ->allow_extra_args(false);
  command.add_flag("--negate-" + operand, placement.negate, "then negate " + upper + " (x -> -x)");
}

void check_placement(const Placement& placement, const std::string& operand) {
  (void)linear_part(placement, operand);
  (void)numbers(placement.translate, "--translate-" + operand);
}

ConvexSet placed(ConvexSet set, const Placement& placement, const std::string& operand) {
  if (const std::optional<Mat3> m = linear_part(placement, operand)) set = linear_image(set, *m);
  if (!placement.translate.empty()) {
    const std::vector<Rational> t = numbers(placement.translate, "--translate-" + operand);
    set = set.translated(Vec3{t[0], t[1], t[2]});
  }
  if (placement.negate) set = set.reflected();
  return set;
}

PolygonSoup placed(PolygonSoup soup, const Placement& placement, const std::string& operand) {
  const std::optional<Mat3> m = linear_part(placement, operand);
  Vec3 t;
  if (!placement.translate.empty()) {
    const std::vector<Rational> v = numbers(placement.translate, "--translate-" + operand);
    t = Vec3{v[0], v[1], v[2]};
  }
  for (Vec3& p : soup.points) {
    if (m) p = *m * p;
    p = p + t;
    if (placement.negate) p = -p;
  }
  const bool reversed = (m && sgn(m->determinant()) < 0) != placement.negate;
  if (reversed)
    for (std::size_t f = 0; f < soup.num_faces(); ++f)
      std::reverse(soup.face_indices.begin() + static_cast<std::ptrdiff_t>(soup.face_offsets[f]),
                   soup.face_indices.begin() + static_cast<std::ptrdiff_t>(soup.face_offsets[f + 1]));
  return soup;
}

}  // namespace cvms::cli
