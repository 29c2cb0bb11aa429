// SPDX-License-Identifier: MIT
// Smallest use of an installed cvms: exact decimal arithmetic and one exact
// predicate. Exits 0 when both are right.
#include <cvms/predicates.hpp>
#include <cvms/rational.hpp>
#include <cvms/vec.hpp>

#include <cstdio>

int main() {
  const cvms::Rational sum = cvms::parse_rational("0.1") + cvms::parse_rational("0.2");
  const cvms::Vec3 o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, z{0, 0, cvms::parse_rational("1e-300")};
  const bool ok = cvms::to_string(sum) == "0.3" &&
                  cvms::orient3d(o, x, y, z) == cvms::Sign::positive;
  std::printf("cvms test_package: 0.1 + 0.2 = %s, orient3d = %s\n", cvms::to_string(sum).c_str(),
              ok ? "positive" : "WRONG");
  return ok ? 0 : 1;
}
