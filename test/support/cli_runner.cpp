// SPDX-License-Identifier: MIT
// Running the built `cvms` tool from a test (see cli_runner.hpp).
#include "support/cli_runner.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace cvms::test {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

ScratchDirectory::ScratchDirectory(const std::string& tag)
    : dir_(std::filesystem::temp_directory_path() / ("cvms_" + tag + "_" + std::to_string(::getpid()))) {
  std::filesystem::remove_all(dir_);
  std::filesystem::create_directories(dir_);
}

ScratchDirectory::~ScratchDirectory() {
  if (!keep_) {
    std::error_code ignored;
    std::filesystem::remove_all(dir_, ignored);
  }
}

void ScratchDirectory::write(const std::string& name, const std::string& text) const {
  std::ofstream(dir_ / name, std::ios::binary) << text;
}

CliOutcome run_cli(const std::filesystem::path& dir, const std::string& program, const std::string& args) {
  const std::string command = "cd '" + dir.string() + "' && '" + program + "' " + args + " > out.txt 2> err.txt";
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir / "out.txt"), slurp(dir / "err.txt")};
}

}  // namespace cvms::test
