// SPDX-License-Identifier: MIT
// A program outside the cvms tree: computes with the installed library and
// checks the results exactly. Built by CMake (find_package, from an install
// prefix and from a build tree), by pkg-config on the command line, and fully
// static (scripts/check-consumers.sh). Exits 0 only when every check holds.
#include <cvms/predicates.hpp>
#include <cvms/rational.hpp>
#include <cvms/vec.hpp>

#include <cstdio>
#include <string>

namespace {

int failures = 0;

void check(bool ok, const char* what) {
  if (!ok) {
    std::printf("consumer: FAILED: %s\n", what);
    ++failures;
  }
}

}  // namespace

int main() {
  using cvms::Rational;
  using cvms::Sign;
  using cvms::Vec3;

  // Exact decimal parsing and printing (library code in rational.cpp).
  const Vec3 a{cvms::parse_rational("0.1"), 0, 0};
  const Vec3 b{cvms::parse_rational("0.2"), 0, 0};
  check((a + b).x == Rational(3, 10), "0.1 + 0.2 == 3/10");
  check(cvms::to_string((a + b).x) == "0.3", "to_string(0.1 + 0.2) == \"0.3\"");
  check(cvms::to_string(Rational(1, 3)) == "1/3", "to_string(1/3) == \"1/3\"");

  // Exact predicates (predicates.cpp): orientation of a point on, above and
  // (seen the other way round) below the plane z = 0.
  const Vec3 p{0, 0, 0};
  const Vec3 q{cvms::parse_rational("0.1"), 0, 0};
  const Vec3 r{0, cvms::parse_rational("0.3"), 0};
  const Vec3 on{cvms::parse_rational("0.7"), cvms::parse_rational("0.9"), 0};
  const Vec3 above{0, 0, cvms::parse_rational("1e-300")};
  check(cvms::orient3d(p, q, r, on) == Sign::zero, "orient3d coplanar == zero");
  check(cvms::orient3d(p, q, r, above) == Sign::positive, "orient3d above == positive");
  check(cvms::orient3d(p, r, q, above) == Sign::negative, "orient3d swapped == negative");

  // gmpxx itself through the public headers (links libgmpxx and libgmp).
  const Rational big = Rational(mpz_class("123456789012345678901234567890"), 7);
  check(big * 7 == Rational(mpz_class("123456789012345678901234567890")), "gmpxx big rational");

  std::printf("consumer: %s (%d failed)\n", failures == 0 ? "ok" : "FAILED", failures);
  return failures == 0 ? 0 : 1;
}
