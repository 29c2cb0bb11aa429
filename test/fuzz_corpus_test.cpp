// SPDX-License-Identifier: MIT
// Replays the committed fuzz seed corpora (test/fuzz/corpus/<target>/) and the
// inputs that once failed (test/fuzz/regressions/<target>/) through the fuzz
// target bodies, so the default suite (any compiler, ASan in CI) checks them
// without libFuzzer. A target throws FuzzFinding for a broken invariant; any
// exception escaping it is a failure.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz/parse_number_target.hpp"
#include "support/fuzz_targets.hpp"

namespace {

namespace fs = std::filesystem;

const fs::path fuzz_dir = fs::path(CVMS_TEST_DATA_DIR).parent_path() / "fuzz";

std::vector<std::uint8_t> read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Runs every file under fuzz_dir/<kind>/<target>/ through the target;
// returns how many files there were. `run` defaults to the target of that name.
std::size_t replay(const std::string& kind, const std::string& target, cvms::fuzz::Target run = nullptr) {
  if (run == nullptr) run = cvms::fuzz::target_by_name(target);
  const fs::path dir = fuzz_dir / kind / target;
  std::size_t count = 0;
  if (!fs::is_directory(dir)) return 0;
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.string());
    const std::vector<std::uint8_t> bytes = read_bytes(file);
    try {
      run(bytes);
    } catch (const std::exception& e) {
      ADD_FAILURE() << "escaped: " << e.what();
    }
    ++count;
  }
  return count;
}

class FuzzCorpus : public ::testing::TestWithParam<std::string> {};

TEST_P(FuzzCorpus, SeedsPassTheTarget) {
  ASSERT_NE(cvms::fuzz::target_by_name(GetParam()), nullptr);
  EXPECT_GE(replay("corpus", GetParam()), 4u) << "the seed corpus of " << GetParam() << " is missing";
}

TEST_P(FuzzCorpus, RegressionInputsPassTheTarget) { replay("regressions", GetParam()); }

INSTANTIATE_TEST_SUITE_P(Targets, FuzzCorpus, ::testing::ValuesIn(cvms::fuzz::target_names()),
                         [](const auto& info) { return info.param; });

// The number-parser harness (test/fuzz/parse_number_target.hpp) tests a
// private function, so it is not among target_names(); its corpus is
// replayed here.
TEST(FuzzCorpusParseNumber, SeedsPassTheTarget) {
  EXPECT_GE(replay("corpus", "parse_number", cvms::fuzz::parse_number_target), 4u)
      << "the seed corpus of parse_number is missing";
}

TEST(FuzzCorpusParseNumber, RegressionInputsPassTheTarget) {
  replay("regressions", "parse_number", cvms::fuzz::parse_number_target);
}

TEST(FuzzCorpusParseNumber, EmptyInputIsNotAFinding) { EXPECT_NO_THROW(cvms::fuzz::parse_number_target({})); }

TEST(FuzzTargets, UnknownNameGivesNull) { EXPECT_EQ(cvms::fuzz::target_by_name("nope"), nullptr); }

// The decoder the seeds (test/fuzz/make_seeds.py) are written against.
TEST(FuzzTargets, CoordinateDecoding) {
  using cvms::Rational;
  EXPECT_EQ(cvms::fuzz::decode_coordinate(15), Rational(0));
  EXPECT_EQ(cvms::fuzz::decode_coordinate(0), Rational(-15));
  EXPECT_EQ(cvms::fuzz::decode_coordinate(31), Rational(16));
  EXPECT_EQ(cvms::fuzz::decode_coordinate(16 | (5 << 5)), Rational(1, 2));
  EXPECT_EQ(cvms::fuzz::decode_coordinate(17 | (7 << 5)), Rational(1, 2));  // 2/4, reduced
  EXPECT_EQ(cvms::fuzz::decode_coordinate(17 | (7 << 5)).get_den(), 2);
  EXPECT_EQ(cvms::fuzz::decode_coordinate(12 | (6 << 5)), Rational(-1));  // -3/3
}

// Empty input: every reader rejects it, every decoder yields nothing to build.
TEST(FuzzTargets, EmptyInputsAreRejectedNotFindings) {
  for (const std::string& name : cvms::fuzz::target_names()) {
    SCOPED_TRACE(name);
    EXPECT_NO_THROW(cvms::fuzz::target_by_name(name)({}));
  }
}

}  // namespace
