// SPDX-License-Identifier: MIT
// Sums of the same geometry with its coordinates written as files write
// them: the doubles' exact (dyadic) values, their shortest round-trip
// decimals, 6 decimals, 18 decimals (a common denominator 10^18, just below
// 2^63, where machine-word directions still apply) and 19 (10^19, just
// beyond, where the general rational path takes over), and one operand of
// each kind mixed, and rationals over denominators at the word-size bounds
// of the integer paths. Each sum is checked against an independent oracle: the
// exact hull of the pairwise vertex sums (vertices and facet planes), the
// sum's stored facet normals against primitive normals worked out here in
// plain rationals from each facet's vertices, and the written bytes against
// those of the hull (canonical order) and of the two-thread sum.
#include <gtest/gtest.h>

#include <charconv>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "cvms/convex_hull.hpp"
#include "cvms/io.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/shapes.hpp"
#include "support/oracle.hpp"

namespace cvms {
namespace {

enum class Form { dyadic, shortest, six_digits, eighteen_digits, nineteen_digits };

const char* name(Form form) {
  switch (form) {
    case Form::dyadic:
      return "dyadic";
    case Form::shortest:
      return "shortest";
    case Form::six_digits:
      return "6 digits";
    case Form::eighteen_digits:
      return "18 digits";
    case Form::nineteen_digits:
      break;
  }
  return "19 digits";
}

// The double c written in `form` and read back exactly.
Rational written(const Rational& c, Form form) {
  if (form == Form::dyadic) return c;
  const double d = c.get_d();
  char digits[64];
  std::size_t length = 0;
  if (form == Form::shortest) {
    length = static_cast<std::size_t>(std::to_chars(digits, digits + sizeof digits, d).ptr - digits);
  } else {
    const int places = form == Form::six_digits ? 6 : form == Form::eighteen_digits ? 18 : 19;
    length = static_cast<std::size_t>(std::snprintf(digits, sizeof digits, "%.*f", places, d));
  }
  return parse_rational(std::string_view(digits, length));
}

ConvexPolyhedron in_form(const ConvexPolyhedron& p, Form form) {
  PolygonSoup soup = p.to_soup();
  for (Vec3& v : soup.points)
    for (int k = 0; k < 3; ++k) v[k] = written(v[k], form);
  return ConvexPolyhedron::from_soup(std::move(soup));
}

std::string canonical_off(const ConvexPolyhedron& p) {
  std::ostringstream out;
  write(out, p, FileFormat::off, Coordinates::exact, VertexOrder::canonical);
  return out.str();
}

std::string as_is_off(const ConvexPolyhedron& p) {
  std::ostringstream out;
  write(out, p, FileFormat::off);
  return out.str();
}

std::vector<Vec3> points(const ConvexPolyhedron& p) {
  std::vector<Vec3> out;
  for (VertexId v : p.mesh().vertices()) out.push_back(p.vertex(v));
  return out;
}

// "" when every stored facet normal of p is the primitive integer normal of
// the facet's first three corners (plain rationals; counterclockwise from
// outside, so it points outward).
std::string check_stored_normals(const ConvexPolyhedron& p) {
  for (FaceId f : p.mesh().faces()) {
    std::vector<Vec3> corners;
    for (HalfedgeId h : p.mesh().face_halfedges(f)) corners.push_back(p.vertex(p.mesh().from(h)));
    const Vec3 n = primitive_direction(cross(corners[1] - corners[0], corners[2] - corners[0]));
    if (p.normal(f) != n)
      return "facet " + std::to_string(f.index()) + ": stored " + test::to_text(p.normal(f)) + ", expected " +
             test::to_text(n);
  }
  return "";
}

void check_sum(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const std::string& what) {
  SCOPED_TRACE(what);
  const MinkowskiResult sum = minkowski_sum(a, b);
  const ConvexPolyhedron hull = convex_hull(test::pairwise_sums(points(a), points(b)));
  const test::Shape expected = test::describe(hull), actual = test::describe(sum.polyhedron);
  ASSERT_EQ(actual, expected) << test::difference(expected, actual);
  ASSERT_EQ(check_stored_normals(sum.polyhedron), "");
  ASSERT_EQ(canonical_off(sum.polyhedron), canonical_off(hull));
  Options two;
  two.threads = 2;
  ASSERT_EQ(as_is_off(minkowski_sum(a, b, two).polyhedron), as_is_off(sum.polyhedron));
}

const Form all_forms[] = {Form::dyadic, Form::shortest, Form::six_digits, Form::eighteen_digits,
                          Form::nineteen_digits};

TEST(DecimalOperands, SphereAndRotatedSphereInEveryForm) {
  const ConvexPolyhedron a = shapes::geodesic_sphere(3), b = shapes::rotated_geodesic_sphere(3);
  for (Form form : all_forms) check_sum(in_form(a, form), in_form(b, form), std::string("both ") + name(form));
}

TEST(DecimalOperands, CubeAndSphereInEveryForm) {
  const ConvexPolyhedron a = shapes::cube(), b = shapes::geodesic_sphere(3);
  for (Form form : all_forms) check_sum(a, in_form(b, form), std::string("sphere ") + name(form));
}

// One operand dyadic, the other decimal: the edge facets pair a machine-word
// direction of each kind (or a rational one past the word-size bound).
TEST(DecimalOperands, MixedDyadicAndDecimalOperands) {
  const ConvexPolyhedron a = shapes::geodesic_sphere(3), b = shapes::rotated_geodesic_sphere(3);
  for (Form form : all_forms) {
    if (form == Form::dyadic) continue;
    check_sum(a, in_form(b, form), std::string("dyadic + ") + name(form));
    check_sum(in_form(a, form), b, std::string(name(form)) + " + dyadic");
  }
  check_sum(in_form(a, Form::shortest), in_form(b, Form::six_digits), "shortest + 6 digits");
}

// The vertices of p times s, each coordinate rounded to the nearest multiple
// of 1 / q (ties up).
std::vector<Vec3> on_grid(const ConvexPolyhedron& p, const Rational& s, const mpz_class& q) {
  std::vector<Vec3> out;
  for (const Vec3& v : points(p)) {
    Vec3& w = out.emplace_back();
    for (int k = 0; k < 3; ++k) {
      const Rational x = v[k] * s;
      mpz_class n = 2 * x.get_num() * q + x.get_den();
      mpz_fdiv_q(n.get_mpz_t(), n.get_mpz_t(), mpz_class(2 * x.get_den()).get_mpz_t());
      w[k] = Rational(n, q);
      w[k].canonicalize();
    }
  }
  return out;
}

// Operands whose coordinates are rationals over denominators at the
// word-size bounds of the integer paths and just past them: the common
// denominator below 2^63 (10^18, 2^62, 2^63 - 1) and not (2^63, 2^63 + 1,
// 10^19), alone and mixed (2^61 with 10^17: sums of about 120 bits), and
// small rationals (thirds, 1 / 231).
TEST(DecimalOperands, RationalGridsAtTheWordSizeBounds) {
  const mpz_class two = 2;
  const mpz_class ten18("1000000000000000000"), ten17("100000000000000000"), ten19("10000000000000000000");
  const mpz_class two61 = two << 60, two62 = two << 61, two63 = two << 62;
  const std::pair<mpz_class, mpz_class> denominators[] = {
      {ten18, ten18},         {two62, ten18}, {two63 - 1, two63 - 1}, {two63 - 1, ten17}, {two63, ten17},
      {two63 + 1, two63 + 1}, {ten19, 1000000}, {two61, ten17},      {3, 231},           {231, 1000000}};
  const ConvexPolyhedron a = shapes::geodesic_sphere(2), b = shapes::rotated_geodesic_sphere(2);
  const Rational fifth(1, 5);  // coordinates below 2^61 / 2^63 in magnitude
  for (const auto& [qa, qb] : denominators) {
    const ConvexPolyhedron ga = convex_hull(on_grid(a, fifth, qa)), gb = convex_hull(on_grid(b, fifth, qb));
    check_sum(ga, gb, "grids 1/" + qa.get_str() + " and 1/" + qb.get_str());
  }
}

// Rationals over denominators at the bounds of the two-word integer path
// (two_word_scaled.hpp): common denominators beyond one word but below
// 2^124 (10^19, 10^30, 2^123 - 1, lcm(2^61, 10^17)), where the sums are
// 128-bit integers over the lcm of the two, and just past (2^124 + 1; and
// lcm(2^70, 10^30) or 10^30 with 2^123 - 1, whose sums' denominators pass
// 2^126), where the general rational paths take over.
TEST(DecimalOperands, RationalGridsAtTheTwoWordBounds) {
  const mpz_class two = 2;
  const mpz_class ten17("100000000000000000"), ten19("10000000000000000000"), ten30("1" + std::string(30, '0'));
  const mpz_class two61 = two << 60, two70 = two << 69, two123 = two << 122, two124 = two << 123;
  const std::pair<mpz_class, mpz_class> denominators[] = {
      {ten19, ten19}, {ten30, ten19},         {two123 - 1, two123 - 1}, {two61, ten30},         {ten30, 7},
      {two70, ten30}, {two124 + 1, two124 + 1}, {ten30, two123 - 1},    {two124 - 1, ten17}};
  const ConvexPolyhedron a = shapes::geodesic_sphere(2), b = shapes::rotated_geodesic_sphere(2);
  const Rational fifth(1, 5);
  for (const auto& [qa, qb] : denominators) {
    const ConvexPolyhedron ga = convex_hull(on_grid(a, fifth, qa)), gb = convex_hull(on_grid(b, fifth, qb));
    check_sum(ga, gb, "grids 1/" + qa.get_str() + " and 1/" + qb.get_str());
  }
}

// Coordinates as small as 1e-30 (denominator 10^30) beside shortest
// decimals, and exact ties: a two-word operand plus itself (every facet has
// a parallel twin).
TEST(DecimalOperands, TinyCoordinatesAndTiesOnTwoWords) {
  const ConvexPolyhedron a = in_form(shapes::geodesic_sphere(3), Form::shortest);
  std::vector<Vec3> nudged = points(in_form(shapes::rotated_geodesic_sphere(2), Form::nineteen_digits));
  const Rational tiny(mpz_class(1), mpz_class("1" + std::string(30, '0')));
  for (std::size_t j = 0; j < nudged.size(); ++j) nudged[j][static_cast<int>(j % 3)] += (j % 2 == 0 ? tiny : -tiny);
  const ConvexPolyhedron b = convex_hull(nudged);
  check_sum(a, b, "shortest + 19 digits nudged by 1e-30");
  check_sum(a, a, "shortest + itself");
  const ConvexPolyhedron c = in_form(shapes::geodesic_sphere(3), Form::nineteen_digits);
  check_sum(c, c, "19 digits + itself");
  // Points whose coordinates are 1e-30 and zero: a tiny tetrahedron.
  const ConvexPolyhedron t = convex_hull(std::vector<Vec3>{
      {Rational(0), Rational(0), Rational(0)}, {tiny, Rational(0), Rational(0)}, {Rational(0), tiny, Rational(0)},
      {Rational(0), Rational(0), -tiny}});
  check_sum(t, a, "1e-30 tetrahedron + shortest");
}

// Loaded operands make their facet planes on first use; the fast path for
// decimal corners gives the same primitive normals as plain rationals.
TEST(DecimalOperands, LoadedOperandsHaveTheRationalNormals) {
  const ConvexPolyhedron a = shapes::rotated_geodesic_sphere(3);
  for (Form form : all_forms) {
    SCOPED_TRACE(name(form));
    EXPECT_EQ(check_stored_normals(in_form(a, form)), "");
  }
}

}  // namespace
}  // namespace cvms
