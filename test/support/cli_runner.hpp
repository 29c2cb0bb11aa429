// SPDX-License-Identifier: MIT
// Running the built `cvms` tool from a test: a scratch directory per test and
// one call that runs the program there and collects exit code, stdout and
// stderr. (The program's path comes from the test target: CVMS_CLI_PATH.)
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace cvms::test {

/// What a run of the tool produced.
struct CliOutcome {
  int code = -1;  ///< exit code, -1 if it did not exit normally
  std::string out, err;
};

/// A fresh, empty directory under the system's temporary directory, named
/// after `tag` and the process id; removed on destruction unless keep() was
/// called (so a failing test leaves its files to look at).
class ScratchDirectory {
 public:
  explicit ScratchDirectory(const std::string& tag);
  ~ScratchDirectory();
  ScratchDirectory(const ScratchDirectory&) = delete;
  ScratchDirectory& operator=(const ScratchDirectory&) = delete;

  [[nodiscard]] const std::filesystem::path& path() const noexcept { return dir_; }
  /// Writes `text` to the file `name` in the directory.
  void write(const std::string& name, const std::string& text) const;
  /// Leave the directory in place.
  void keep() noexcept { keep_ = true; }

 private:
  std::filesystem::path dir_;
  bool keep_ = false;
};

/// The bytes of a file (empty if it cannot be read).
std::string slurp(const std::filesystem::path& p);

/// Runs `program args` with the directory as working directory.
CliOutcome run_cli(const std::filesystem::path& dir, const std::string& program, const std::string& args);

/// A fixture for the tool's test suites: a scratch directory named after
/// `prefix` and the test, kept when the test fails, and run() of the tool
/// there. Derived fixtures skip in SetUp when the tool is not built.
class CliTest : public ::testing::Test {
 protected:
  explicit CliTest(const std::string& prefix)
      : dir_(prefix + ::testing::UnitTest::GetInstance()->current_test_info()->name()) {}
  void TearDown() override {
    if (HasFailure()) dir_.keep();
  }
  /// `cvms args` in the scratch directory (CVMS_CLI_PATH of the test target).
  [[nodiscard]] CliOutcome run(const std::string& args) const {
#ifdef CVMS_CLI_PATH
    return run_cli(dir_.path(), CVMS_CLI_PATH, args);
#else
    (void)args;
    return {};
#endif
  }
  ScratchDirectory dir_;
};

}  // namespace cvms::test
