// SPDX-License-Identifier: MIT
// A point as a text exporter writes it (Meshlab and most CAD tools: 6
// decimals, "%.6f") and as cvms then reads it: exact decimals, not dyadic,
// so the benchmark rows on decimal input see the denominators 10^6 that real
// files carry.
#pragma once

#include <cstdio>

#include "cvms/rational.hpp"
#include "cvms/vec.hpp"

namespace cvms_bench {

inline cvms::Vec3 six_decimal_point(double x, double y, double z) {
  const double c[3] = {x, y, z};
  cvms::Vec3 p;
  for (int i = 0; i < 3; ++i) {
    char digits[32];
    std::snprintf(digits, sizeof digits, "%.6f", c[i]);
    p[i] = cvms::parse_rational(digits);
  }
  return p;
}

}  // namespace cvms_bench
