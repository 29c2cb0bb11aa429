// SPDX-License-Identifier: MIT
// The paper's benchmark shapes (Table 1: Cube, Tetra, Hedra, Truncated cube,
// Sphere1..6) and other generators: boxes, prisms, random hulls, exact
// rotations and scalings.
//
// Fixed shapes are built as polygon soups with hand-checked counterclockwise
// faces and go through ConvexPolyhedron::from_soup, which verifies them.
// Geodesic spheres and random clouds go through the exact convex_hull.
//
// Everything computed in double here (geodesic sphere points, the angles of
// circle_polygon) must come out bit-identical on every platform, because the
// exact shapes are defined by those doubles. So only IEEE operations that are
// correctly rounded are used (+ - * / and std::sqrt, never std::sin/cos/tan),
// in a fixed order, and every intermediate result passes through a volatile
// store so that the compiler can neither fuse a*b+c into an fma (clang does
// so by default on targets with fma) nor keep excess precision.
#include "cvms/shapes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <unordered_map>
#include <utility>

#include "cvms/error.hpp"
#include "filtered_predicates.hpp"
#include "cvms/convex_hull.hpp"

namespace cvms::shapes {
namespace {

// ---- deterministic double arithmetic --------------------------------------

double rounded(double x) {
  volatile double v = x;
  return v;
}
double add(double a, double b) { return rounded(a + b); }
double sub(double a, double b) { return rounded(a - b); }
double mul(double a, double b) { return rounded(a * b); }
double div(double a, double b) { return rounded(a / b); }

struct D3 {
  double x, y, z;
};

// p / |p| with |p| = sqrt((x*x + y*y) + z*z).
D3 normalised(const D3& p) {
  double norm = std::sqrt(add(add(mul(p.x, p.x), mul(p.y, p.y)), mul(p.z, p.z)));
  return {div(p.x, norm), div(p.y, norm), div(p.z, norm)};
}

// Taylor series of sin and cos, |x| <= pi/2: 30 terms are far more than
// enough for full double accuracy, and a fixed term count keeps the result
// independent of the platform.
double taylor_sin(double x) {
  double x2 = mul(x, x), term = x, sum = x;
  for (int i = 1; i <= 30; ++i) {
    term = div(mul(term, -x2), static_cast<double>((2 * i) * (2 * i + 1)));
    sum = add(sum, term);
  }
  return sum;
}
double taylor_cos(double x) {
  double x2 = mul(x, x), term = 1.0, sum = 1.0;
  for (int i = 1; i <= 30; ++i) {
    term = div(mul(term, -x2), static_cast<double>((2 * i - 1) * (2 * i)));
    sum = add(sum, term);
  }
  return sum;
}

// ---- exact helpers ----------------------------------------------------------

mpz_class integer(std::int64_t v) {
  if constexpr (sizeof(long) >= sizeof(std::int64_t)) {
    return mpz_class(static_cast<long>(v));
  } else {
    return mpz_class(std::to_string(v));
  }
}

Rational exact(double d) { return rational_from_double(d); }
Vec3 exact(const D3& p) { return {exact(p.x), exact(p.y), exact(p.z)}; }

// The 8 corners of a box, index bits (x, y, z) = (bit 0, bit 1, bit 2), a
// set bit meaning the upper bound.
std::vector<Vec3> box_corners(const Vec3& lo, const Vec3& hi) {
  std::vector<Vec3> corners;
  for (int i = 0; i < 8; ++i)
    corners.push_back({(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z});
  return corners;
}

// Faces of box_corners, counterclockwise seen from outside.
void add_box_faces(PolygonSoup& soup) {
  soup.add_face({0, 4, 6, 2});  // x = lo
  soup.add_face({1, 3, 7, 5});  // x = hi
  soup.add_face({0, 1, 5, 4});  // y = lo
  soup.add_face({2, 6, 7, 3});  // y = hi
  soup.add_face({0, 2, 3, 1});  // z = lo
  soup.add_face({4, 5, 7, 6});  // z = hi
}

void check_count(int n, int lo, int hi, const char* what) {
  if (n < lo || n > hi)
    throw Error(ErrorCategory::invalid_argument, std::string(what) + " = " + std::to_string(n) +
                                                     " is outside " + std::to_string(lo) + ".." +
                                                     std::to_string(hi));
}

// ---- geodesic spheres ------------------------------------------------------

// The icosahedron: (+-1, +-phi, 0), (0, +-1, +-phi), (+-phi, 0, +-1), where
// 2 stands for phi below. Faces are index triples, counterclockwise seen from
// outside.
// clang-format off
constexpr std::array<std::array<int, 3>, 12> kIcosaVertices{{
    {-1, 2, 0}, {1, 2, 0}, {-1, -2, 0}, {1, -2, 0},
    {0, -1, 2}, {0, 1, 2}, {0, -1, -2}, {0, 1, -2},
    {2, 0, -1}, {2, 0, 1}, {-2, 0, -1}, {-2, 0, 1}}};
// clang-format on
constexpr std::array<std::array<std::uint32_t, 3>, 20> kIcosaFaces{{
    {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
    {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
    {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1},
}};

// The fixed generic rotation of rotated_geodesic_sphere, as the quaternion
// (a, b, c, d) of rational_rotation.
constexpr std::array<std::int64_t, 4> kSphereRotation{1, 3, 5, 7};

std::vector<D3> icosahedron_points(bool rotated) {
  const double phi = div(add(1.0, std::sqrt(5.0)), 2.0);
  auto coordinate = [phi](int c) { return c == 2 ? phi : (c == -2 ? -phi : static_cast<double>(c)); };
  // Integer numerators of rational_rotation's matrix (all small, exact in
  // double), divided by the common denominator after the products.
  double m[3][3] = {};
  double denominator = 1.0;
  if (rotated) {
    auto [a, b, c, d] = kSphereRotation;
    Mat3 r = rational_rotation(a, b, c, d);
    denominator = static_cast<double>(a * a + b * b + c * c + d * d);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m[i][j] = Rational(r.m[i][j] * (a * a + b * b + c * c + d * d)).get_d();
  }
  std::vector<D3> points;
  for (const auto& v : kIcosaVertices) {
    D3 p = normalised({coordinate(v[0]), coordinate(v[1]), coordinate(v[2])});
    if (rotated) {
      D3 q{};
      double* out[3] = {&q.x, &q.y, &q.z};
      for (int i = 0; i < 3; ++i)
        *out[i] = div(add(add(mul(m[i][0], p.x), mul(m[i][1], p.y)), mul(m[i][2], p.z)), denominator);
      p = normalised(q);
    }
    points.push_back(p);
  }
  return points;
}

std::vector<D3> geodesic_points(int k, bool rotated) {
  check_count(k, 1, 9, "geodesic sphere level k");
  std::vector<D3> points = icosahedron_points(rotated);
  std::vector<std::array<std::uint32_t, 3>> triangles(kIcosaFaces.begin(), kIcosaFaces.end());
  for (int level = 1; level < k; ++level) {
    // Each edge's midpoint is created once, keyed by its endpoint pair, so
    // neighbouring triangles share it.
    std::unordered_map<std::uint64_t, std::uint32_t> midpoints;
    midpoints.reserve(triangles.size() * 2);
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      std::uint64_t key = (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
      auto [it, inserted] = midpoints.try_emplace(key, static_cast<std::uint32_t>(points.size()));
      if (inserted) {
        const D3 pa = points[a], pb = points[b];
        points.push_back(
            normalised({mul(add(pa.x, pb.x), 0.5), mul(add(pa.y, pb.y), 0.5), mul(add(pa.z, pb.z), 0.5)}));
      }
      return it->second;
    };
    std::vector<std::array<std::uint32_t, 3>> finer;
    finer.reserve(triangles.size() * 4);
    for (const auto& [a, b, c] : triangles) {
      std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      finer.push_back({a, ab, ca});
      finer.push_back({ab, b, bc});
      finer.push_back({ca, bc, c});
      finer.push_back({ab, bc, ca});
    }
    triangles = std::move(finer);
  }
  return points;
}

// ---- random clouds ----------------------------------------------------------

// Uniform in [-range, range] by rejection on the raw 64-bit output, which
// std::mt19937_64 defines exactly (std::uniform_int_distribution does not:
// it differs between standard libraries).
std::int64_t draw(std::mt19937_64& engine, std::int64_t range) {
  const std::uint64_t span = 2 * static_cast<std::uint64_t>(range) + 1;
  const std::uint64_t limit = std::numeric_limits<std::uint64_t>::max() / span * span;
  std::uint64_t x;
  do {
    x = engine();
  } while (x >= limit);
  return static_cast<std::int64_t>(x % span) - range;
}

// Tracks whether the points seen so far span 3D: the first point, the first
// one different from it, the first one not collinear with those, and the
// first one not coplanar with those three.
class SpanTracker {
 public:
  void add(const Vec3& p) {
    switch (basis_.size()) {
      case 0:
        basis_.push_back(p);
        break;
      case 1:
        if (p != basis_[0]) basis_.push_back(p);
        break;
      case 2:
        if (!is_parallel(basis_[1] - basis_[0], p - basis_[0])) basis_.push_back(p);
        break;
      case 3:
        if (orient3d(basis_[0], basis_[1], basis_[2], p) != Sign::zero) basis_.push_back(p);
        break;
      default:
        break;
    }
  }
  [[nodiscard]] bool spans_3d() const { return basis_.size() == 4; }

 private:
  std::vector<Vec3> basis_;
};

}  // namespace

// ---- Platonic and Archimedean solids ---------------------------------------

ConvexPolyhedron tetrahedron() {
  PolygonSoup soup;
  soup.points = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  soup.add_face({0, 1, 2});
  soup.add_face({0, 3, 1});
  soup.add_face({0, 2, 3});
  soup.add_face({1, 3, 2});
  return ConvexPolyhedron::from_soup(std::move(soup));
}

ConvexPolyhedron cube() { return box({-1, -1, -1}, {1, 1, 1}); }

ConvexPolyhedron octahedron() {
  PolygonSoup soup;
  // 2a is the vertex on the +axis a, 2a+1 the one on the -axis.
  soup.points = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int s = 0; s < 8; ++s) {
    std::uint32_t x = (s & 1) ? 1 : 0, y = (s & 2) ? 3 : 2, z = (s & 4) ? 5 : 4;
    // One facet per octant; a reflection in an odd number of axes reverses
    // the orientation of (x, y, z).
    bool odd = (((s & 1) != 0) + ((s & 2) != 0) + ((s & 4) != 0)) % 2 == 1;
    if (odd) {
      soup.add_face({x, z, y});
    } else {
      soup.add_face({x, y, z});
    }
  }
  return ConvexPolyhedron::from_soup(std::move(soup));
}

ConvexPolyhedron truncated_cube() {
  // Vertex 3c + i is corner c of the cube (bits as in box_corners) with
  // coordinate i moved to +-1/3: the cut point on the corner's edge along i.
  PolygonSoup soup;
  const Rational third(1, 3);
  for (const Vec3& corner : box_corners({-1, -1, -1}, {1, 1, 1}))
    for (int i = 0; i < 3; ++i) {
      Vec3 p = corner;
      p[i] *= third;
      soup.points.push_back(p);
    }
  auto id = [](int corner, int axis) { return static_cast<std::uint32_t>(3 * corner + axis); };
  // Octagons: on the face x_a = s, walk its corners counterclockwise in the
  // right-handed frame (u, v) = (a+1, a+2); at each corner (su, sv) the two
  // cut points come in the order (cut along v, cut along u) when su*sv > 0.
  for (int a = 0; a < 3; ++a)
    for (int s : {1, -1}) {
      const int u = (a + 1) % 3, v = (a + 2) % 3;
      std::vector<std::uint32_t> octagon;
      for (auto [su, sv] : {std::pair{1, 1}, {-1, 1}, {-1, -1}, {1, -1}}) {
        int corner = ((s > 0) << a) | ((su > 0) << u) | ((sv > 0) << v);
        if (su * sv > 0) {
          octagon.push_back(id(corner, v));
          octagon.push_back(id(corner, u));
        } else {
          octagon.push_back(id(corner, u));
          octagon.push_back(id(corner, v));
        }
      }
      if (s < 0) std::reverse(octagon.begin(), octagon.end());
      soup.add_face(octagon);
    }
  // Triangles: (cut x, cut y, cut z) is counterclockwise at corner (+,+,+);
  // reflections in an odd number of axes reverse it.
  for (int c = 0; c < 8; ++c) {
    bool odd = (((c & 1) == 0) + ((c & 2) == 0) + ((c & 4) == 0)) % 2 == 1;
    if (odd) {
      soup.add_face({id(c, 0), id(c, 2), id(c, 1)});
    } else {
      soup.add_face({id(c, 0), id(c, 1), id(c, 2)});
    }
  }
  return ConvexPolyhedron::from_soup(std::move(soup));
}

// ---- geodesic spheres ------------------------------------------------------

std::vector<Vec3> geodesic_sphere_points(int k, bool rotated) {
  std::vector<D3> points = geodesic_points(k, rotated);
  std::vector<Vec3> result;
  result.reserve(points.size());
  for (const D3& p : points) result.push_back(exact(p));
  return result;
}

ConvexPolyhedron geodesic_sphere(int k) {
  std::vector<Vec3> points = geodesic_sphere_points(k, false);
  return convex_hull(points);
}

ConvexPolyhedron rotated_geodesic_sphere(int k) {
  std::vector<Vec3> points = geodesic_sphere_points(k, true);
  return convex_hull(points);
}

// ---- boxes and prisms ------------------------------------------------------

ConvexPolyhedron box(const Vec3& lo, const Vec3& hi) {
  for (int i = 0; i < 3; ++i)
    if (!(lo[i] < hi[i]))
      throw Error(ErrorCategory::degenerate, "box: lo[" + std::to_string(i) + "] = " + to_string(lo[i]) +
                                                 " is not below hi[" + std::to_string(i) +
                                                 "] = " + to_string(hi[i]));
  PolygonSoup soup;
  soup.points = box_corners(lo, hi);
  add_box_faces(soup);
  return ConvexPolyhedron::from_soup(std::move(soup));
}

std::vector<Vec2> circle_polygon(int n) {
  check_count(n, 3, 1000000, "circle_polygon: n");
  // The point of parameter t is at angle 2 atan(t). Aim at half-angles
  // phi_i = -pi/2 + pi (i + 1/2) / n and round t = tan(phi_i) to a multiple of
  // 1/(4n): consecutive tangents differ by at least pi/n (tan' >= 1) and each
  // rounding moves them by at most 1/(8n), so the t_i strictly increase and
  // the points are distinct and counterclockwise, hence a strictly convex
  // polygon (points on a circle are all extreme).
  const double pi = std::numbers::pi;
  const std::int64_t denominator = 4 * static_cast<std::int64_t>(n);
  const mpz_class den = integer(denominator), den2 = den * den;
  std::vector<Vec2> points;
  points.reserve(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    double phi = sub(div(mul(pi, add(static_cast<double>(i), 0.5)), static_cast<double>(n)), div(pi, 2.0));
    double t = div(taylor_sin(phi), taylor_cos(phi));
    mpz_class p = integer(std::llround(mul(t, static_cast<double>(denominator))));
    mpz_class p2 = p * p;
    Rational scale(mpz_class(1), den2 + p2);
    points.push_back({Rational(den2 - p2) * scale, Rational(2 * p * den) * scale});
  }
  return points;
}

ConvexPolyhedron prism(int n, const Rational& height) {
  check_count(n, 3, 1000000, "prism: n");
  if (sgn(height) <= 0)
    throw Error(ErrorCategory::invalid_argument, "prism: height " + to_string(height) + " is not positive");
  const Rational half = height / 2;
  const std::uint32_t m = static_cast<std::uint32_t>(n);
  PolygonSoup soup;
  std::vector<Vec2> base = circle_polygon(n);
  for (const Vec2& q : base) soup.points.push_back({q.x, q.y, -half});
  for (const Vec2& q : base) soup.points.push_back({q.x, q.y, half});
  std::vector<std::uint32_t> bottom, top;
  for (std::uint32_t i = 0; i < m; ++i) {
    bottom.push_back(m - 1 - i);  // seen from below: clockwise in xy
    top.push_back(m + i);
  }
  soup.add_face(bottom);
  soup.add_face(top);
  for (std::uint32_t i = 0; i < m; ++i) {
    std::uint32_t j = (i + 1) % m;
    soup.add_face({i, j, m + j, m + i});
  }
  return ConvexPolyhedron::from_soup(std::move(soup));
}

// ---- random hulls -----------------------------------------------------------

std::vector<Vec3> random_points(std::uint64_t seed, int n, std::int64_t range) {
  check_count(n, 4, 10000000, "random_points: n");
  if (range < 1 || range > (std::int64_t{1} << 62))
    throw Error(ErrorCategory::invalid_argument,
                "random_points: range " + std::to_string(range) + " is outside 1..2^62");
  std::mt19937_64 engine(seed);
  std::vector<Vec3> points;
  points.reserve(static_cast<std::size_t>(n));
  SpanTracker span;
  // Each extra point leaves a given plane with probability >= 2/3 (a plane
  // holds at most 9 of the 27 points of the smallest grid), so the cap is
  // never reached in practice; it only guarantees termination.
  const std::size_t cap = static_cast<std::size_t>(n) + 10000;
  while (points.size() < static_cast<std::size_t>(n) || !span.spans_3d()) {
    if (points.size() >= cap)
      throw Error(ErrorCategory::degenerate,
                  "random_points: seed " + std::to_string(seed) + " gave no 3D cloud");
    Vec3 p;
    for (int i = 0; i < 3; ++i) p[i] = Rational(integer(draw(engine, range)));
    span.add(p);
    points.push_back(std::move(p));
  }
  return points;
}

ConvexPolyhedron random_hull(std::uint64_t seed, int n, std::int64_t range) {
  std::vector<Vec3> points = random_points(seed, n, range);
  return convex_hull(points);
}

// ---- linear maps ------------------------------------------------------------

Mat3 rational_rotation(std::int64_t a, std::int64_t b, std::int64_t c, std::int64_t d) {
  // The rotation x -> q x q^-1 of the quaternion q = a + bi + cj + dk; it is
  // orthogonal with determinant 1 for every q != 0, and q, -q, and any
  // multiple of q give the same matrix.
  const mpz_class qa = integer(a), qb = integer(b), qc = integer(c), qd = integer(d);
  const mpz_class norm = qa * qa + qb * qb + qc * qc + qd * qd;
  if (norm == 0) throw Error(ErrorCategory::invalid_argument, "rational_rotation: the quaternion is 0");
  const mpz_class entries[3][3] = {
      {qa * qa + qb * qb - qc * qc - qd * qd, 2 * (qb * qc - qa * qd), 2 * (qb * qd + qa * qc)},
      {2 * (qb * qc + qa * qd), qa * qa - qb * qb + qc * qc - qd * qd, 2 * (qc * qd - qa * qb)},
      {2 * (qb * qd - qa * qc), 2 * (qc * qd + qa * qb), qa * qa - qb * qb - qc * qc + qd * qd},
  };
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      r.m[i][j] = Rational(entries[i][j], norm);
      r.m[i][j].canonicalize();
    }
  return r;
}

Mat3 scaling(const Rational& sx, const Rational& sy, const Rational& sz) {
  if (sgn(sx) == 0 || sgn(sy) == 0 || sgn(sz) == 0)
    throw Error(ErrorCategory::invalid_argument, "scaling: a factor is 0");
  Mat3 r;
  r.m[0][0] = sx;
  r.m[1][1] = sy;
  r.m[2][2] = sz;
  return r;
}

}  // namespace cvms::shapes
