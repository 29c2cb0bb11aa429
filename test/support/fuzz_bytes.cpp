// SPDX-License-Identifier: MIT
// The fuzz targets' byte decoders (see the header).
#include "support/fuzz_bytes.hpp"

#include "cvms/convex_hull.hpp"
#include "support/fuzz_targets.hpp"

namespace cvms::fuzz {
namespace {

// Coordinates on a 5x5x5 grid {-2..2}^3: almost every configuration is
// degenerate (coplanar facets, collinear edges, duplicate points).
Rational grid_coordinate(std::uint8_t b) { return Rational(static_cast<int>(b % 5) - 2); }

}  // namespace

Rational fraction(long p, long q) {
  Rational r(p, q);
  r.canonicalize();
  return r;
}

bool is_canonical(const Rational& r) {
  Rational c = r;
  c.canonicalize();
  return c.get_num() == r.get_num() && c.get_den() == r.get_den() && sgn(r.get_den()) > 0;
}

Options with(Algorithm algorithm) {
  Options options;
  options.algorithm = algorithm;
  return options;
}

[[noreturn]] void finding(const std::string& what) { throw FuzzFinding(what); }

Vec3 decode_point(ByteStream& in, bool grid) {
  Vec3 p;
  for (int i = 0; i < 3; ++i) {
    const std::uint8_t b = in.next();
    p[i] = grid ? grid_coordinate(b) : decode_coordinate(b);
  }
  return p;
}

Rational power_of_two(long e) {
  mpz_class p = 1;
  mpz_mul_2exp(p.get_mpz_t(), p.get_mpz_t(), static_cast<mp_bitcnt_t>(e < 0 ? -e : e));
  return e < 0 ? Rational(mpz_class(1), p) : Rational(p);
}

// Scales every point by 2^e, e in [-1024, 1016]: coordinates beyond the
// double range or in its subnormal range, where the predicate filters must
// fall back to exact arithmetic rather than trust inf or 0.
void scale_extreme(std::vector<Vec3>& points, ByteStream& in) {
  const Rational s = power_of_two(static_cast<long>(static_cast<std::int8_t>(in.next())) * 8);
  for (Vec3& p : points) p = s * p;
}

// Moves some points by tiny steps (k * 2^-(20..79)): nearly coplanar and
// nearly collinear configurations that a double evaluation gets wrong.
void perturb_tiny(std::vector<Vec3>& points, ByteStream& in) {
  for (Vec3& p : points) {
    const std::uint8_t b = in.next();
    if ((b & 1) == 0) continue;
    const long k = static_cast<long>((b >> 1) % 7) - 3;
    p[(b >> 4) % 3] += Rational(k) * power_of_two(-20 - static_cast<long>(in.next() % 60));
  }
}

std::vector<Vec3> decode_cloud(ByteStream& in, std::size_t count, bool grid) {
  std::vector<Vec3> points;
  points.reserve(count);
  for (std::size_t i = 0; i < count && !in.empty(); ++i) points.push_back(decode_point(in, grid));
  return points;
}

// One small convex set of any dimension: a cloud (bits 0-1 of the mode
// byte: kept, flattened onto a plane z = (p x + q y) / 2 + r, onto a line
// o + x d, or to its first point; bit 2: rational coordinates instead of the
// grid); the set is the hull in the dimension it spans.
ConvexSet decode_set(ByteStream& in) {
  const std::uint8_t mode = in.next();
  const bool grid = (mode & 4) == 0;
  std::vector<Vec3> points = decode_cloud(in, 1 + in.next() % 12, grid);
  if (points.empty()) points.push_back(Vec3{0, 0, 0});
  switch (mode & 3) {
    case 1: {  // a plane
      const Rational p = fraction(static_cast<long>(in.next() % 5) - 2, 2);
      const Rational q = fraction(static_cast<long>(in.next() % 5) - 2, 2);
      const Rational r = decode_coordinate(in.next());
      for (Vec3& x : points) x.z = p * x.x + q * x.y + r;
      break;
    }
    case 2: {  // a line
      const Vec3 d = decode_point(in, true);
      const Vec3 o = points[0];
      for (Vec3& x : points) x = o + x.x * d;
      break;
    }
    case 3:  // a point
      points.resize(1);
      break;
    default:
      break;
  }
  return convex_hull_set(points);
}

}  // namespace cvms::fuzz
