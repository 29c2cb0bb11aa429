// SPDX-License-Identifier: MIT
// Regression tests for bugs found by fuzzing (test/fuzz/, docs/fuzzing.md),
// each named after what it found. The failing inputs themselves are also
// replayed through the fuzz targets by test/fuzz_corpus_test.cpp
// (test/fuzz/regressions/<target>/).
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "cvms/error.hpp"
#include "cvms/io.hpp"

namespace {

// Expects read_off to reject `text` with Error(category) whose message
// contains `part`.
void expect_off_error(const std::string& text, cvms::ErrorCategory category, const std::string& part) {
  std::istringstream in(text);
  try {
    cvms::read_off(in, "t.off");
    ADD_FAILURE() << "accepted";
  } catch (const cvms::Error& e) {
    EXPECT_EQ(e.category(), category) << e.what();
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

// fuzz read_off: the message for a vertex with the wrong number of values
// quoted the header keyword through a string_view into the line buffer,
// which later (longer) lines had reallocated: a heap use-after-free (ASan),
// garbage in the message otherwise.
TEST(Regression, ReadOffUseAfterFreeOfHeaderKeywordInVertexMessage) {
  expect_off_error(std::string("OFF\n4 4 6\n0 0 0\n1 3 3 4 1 3\x1d", 28), cvms::ErrorCategory::parse,
                   "t.off:4: vertex 1 has 6 values, expected 3 for a 'OFF' file");
  // Counts on the header line, CRLF, then a line long enough to regrow the buffer.
  expect_off_error("COFF 1 0 0\r\n" + std::string(200, ' ') + "0 0 0 1 2\r\n", cvms::ErrorCategory::parse,
                   "vertex 0 has 5 values, expected 6 or 7 for a 'COFF' file");
}

}  // namespace
