// SPDX-License-Identifier: MIT
// Test helpers for the I/O tests: paths of the committed corpus, soups built
// by hand, and a check that a call throws cvms::Error of a given category
// whose message contains given pieces (file name, line, what went wrong).
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <ostream>
#include <span>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "cvms/error.hpp"
#include "cvms/io.hpp"

namespace cvms {
// Readable gtest output for exact points (found by ADL).
inline void PrintTo(const Vec3& v, std::ostream* os) {
  *os << "(" << to_string(v.x) << ", " << to_string(v.y) << ", " << to_string(v.z) << ")";
}
}  // namespace cvms

namespace cvms::test {

/// The whole content of a file, bytes as they are (empty if it cannot be read).
inline std::string file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// How much slower than a plain build the time bounds of the hostile-input
/// tests allow (AddressSanitizer builds run several times slower).
#if defined(__SANITIZE_ADDRESS__)
inline constexpr double slow_factor = 8.0;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr double slow_factor = 8.0;
#else
inline constexpr double slow_factor = 1.0;
#endif
#else
inline constexpr double slow_factor = 1.0;
#endif

inline std::filesystem::path data_path(std::string_view name) {
  return std::filesystem::path(CVMS_TEST_DATA_DIR) / std::filesystem::path(name);
}

/// Runs f and checks that it throws Error(category) whose what() contains every needle.
template <class F>
::testing::AssertionResult throws_error(F&& f, ErrorCategory category,
                                        std::initializer_list<std::string_view> needles) {
  try {
    f();
  } catch (const Error& e) {
    std::string what = e.what();
    if (e.category() != category)
      return ::testing::AssertionFailure() << "category " << to_string(e.category()) << ", expected "
                                           << to_string(category) << ": " << what;
    for (std::string_view needle : needles)
      if (what.find(needle) == std::string::npos)
        return ::testing::AssertionFailure() << "message lacks '" << needle << "': " << what;
    return ::testing::AssertionSuccess() << what;
  } catch (const std::exception& e) {
    return ::testing::AssertionFailure() << "threw a non-cvms exception: " << e.what();
  }
  return ::testing::AssertionFailure() << "did not throw";
}

/// A soup from points and faces written out by hand.
inline PolygonSoup make_soup(std::vector<Vec3> points,
                             std::initializer_list<std::vector<std::uint32_t>> faces) {
  PolygonSoup soup;
  soup.points = std::move(points);
  for (const auto& f : faces) soup.add_face(std::span<const std::uint32_t>(f.data(), f.size()));
  return soup;
}

/// The faces of a soup as plain vectors, for readable comparisons.
inline std::vector<std::vector<std::uint32_t>> faces_of(const PolygonSoup& soup) {
  std::vector<std::vector<std::uint32_t>> out;
  for (std::size_t f = 0; f < soup.num_faces(); ++f)
    out.emplace_back(soup.face(f).begin(), soup.face(f).end());
  return out;
}

inline Vec3 v3(const Rational& x, const Rational& y, const Rational& z) { return {x, y, z}; }

}  // namespace cvms::test
