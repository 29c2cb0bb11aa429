// SPDX-License-Identifier: MIT
// Points and meshes as text exporters write them, and as cvms then reads
// them: exact decimals, not dyadic, so the benchmark rows on decimal input
// see the denominators that real files carry.
//
// A mesh whose coordinates are doubles is written in one of three forms:
//  - dyadic: each double's exact binary expansion (cvms's own exact output),
//    so reading it back gives the doubles themselves;
//  - shortest: the shortest decimal that reads back to the double as a
//    double (std::to_chars without a precision: what Python, numpy and most
//    exporters write); read exactly, "0.1" is 1/10, not the double;
//  - six_digits: 6 decimals ("%.6f": Meshlab, scanners, most CAD tools),
//    denominators 10^6.
#pragma once

#include <charconv>
#include <cstdio>
#include <sstream>
#include <string>
#include <system_error>

#include "cvms/polygon_soup.hpp"
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

/// How an exporter writes a coordinate that is a double (file comment).
enum class TextForm { dyadic = 0, shortest = 1, six_digits = 2 };
inline constexpr int num_text_forms = 3;

inline const char* text_form_name(TextForm form) {
  switch (form) {
    case TextForm::dyadic:
      return "dyadic";
    case TextForm::shortest:
      return "shortest";
    case TextForm::six_digits:
      break;
  }
  return "6_digits";
}

/// The coordinate c, a double, written in `form`.
inline std::string coordinate_text(const cvms::Rational& c, TextForm form) {
  if (form == TextForm::dyadic) return cvms::to_string(c);
  char digits[64];
  const double d = c.get_d();
  if (form == TextForm::six_digits) {
    std::snprintf(digits, sizeof digits, "%.6f", d);
    return digits;
  }
  const std::to_chars_result r = std::to_chars(digits, digits + sizeof digits, d);
  return std::string(digits, r.ec == std::errc{} ? r.ptr : digits);
}

/// The OFF text of a soup whose coordinates are doubles, written in `form`,
/// as an exporter writes it: the header, one "x y z" line per point, one
/// "n i_1 .. i_n" line per face.
inline std::string off_text(const cvms::PolygonSoup& soup, TextForm form) {
  std::ostringstream out;
  out << "OFF\n" << soup.points.size() << ' ' << soup.num_faces() << " 0\n";
  for (const cvms::Vec3& p : soup.points)
    out << coordinate_text(p.x, form) << ' ' << coordinate_text(p.y, form) << ' ' << coordinate_text(p.z, form)
        << '\n';
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    out << soup.face(f).size();
    for (std::uint32_t i : soup.face(f)) out << ' ' << i;
    out << '\n';
  }
  return out.str();
}

}  // namespace cvms_bench
