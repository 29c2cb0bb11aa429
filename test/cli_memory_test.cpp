// SPDX-License-Identifier: MIT
// The tool's memory budget for its inputs (tools/cvms/input_memory.hpp), run
// as a program on generated files of many duplicate rows and points, the
// costliest inputs per byte (one-digit numbers): a file too big for the
// budget is refused with a `limit` error naming the file and --max-memory,
// before its numbers are made; under an address-space limit (`ulimit -v`)
// the default budget refuses it instead of GMP aborting the process on a
// failed allocation; and the estimate is an upper bound, checked by running
// each reader at a budget of exactly its estimate under an address-space
// limit of that estimate plus the program's own share.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>

#include "support/cli_runner.hpp"
#include "support/under_sanitizer.hpp"

namespace {

// The tool's constants (input_memory.hpp, machine_memory.hpp), restated: the
// tests check the behaviour they promise, not the code that computes it.
constexpr std::uint64_t memory_per_mesh_byte = 144;
constexpr std::uint64_t memory_per_row_byte = 256;  // rows and point lists
constexpr std::uint64_t program_address_space = std::uint64_t{64} << 20;

// The six faces of the cube [-1, 1]^3 as rows a b c d (a x + b y + c z <= d),
// repeated: from_halfspaces gives the cube, whatever the count.
constexpr const char* cube_rows[] = {"1 0 0 1", "-1 0 0 1", "0 1 0 1", "0 -1 0 1", "0 0 1 1", "0 0 -1 1"};

std::string duplicate_plain_rows(int count) {
  std::string text;
  for (int i = 0; i < count; ++i) (text += cube_rows[i % 6]) += '\n';
  return text;
}

// cdd's H-representation: b -A, that is d -a -b -c.
std::string duplicate_cdd_rows(int count) {
  std::ostringstream s;
  s << "H-representation\nbegin\n" << count << " 4 integer\n";
  for (int i = 0; i < count; ++i) {
    int a = 0, b = 0, c = 0, d = 0;
    std::istringstream(cube_rows[i % 6]) >> a >> b >> c >> d;
    s << d << ' ' << -a << ' ' << -b << ' ' << -c << '\n';
  }
  s << "end\n";
  return s.str();
}

// The corners of the unit cube, repeated.
std::string duplicate_points(int count) {
  std::string text;
  for (int i = 0; i < count; ++i) {
    const int corner = i % 8;
    text += std::to_string(corner & 1) + ' ' + std::to_string((corner >> 1) & 1) + ' ' +
            std::to_string(corner >> 2) + '\n';
  }
  return text;
}

std::string duplicate_cdd_points(int count) {
  std::ostringstream s;
  s << "V-representation\nbegin\n" << count << " 4 integer\n";
  for (int i = 0; i < count; ++i) {
    const int corner = i % 8;
    s << "1 " << (corner & 1) << ' ' << ((corner >> 1) & 1) << ' ' << (corner >> 2) << '\n';
  }
  s << "end\n";
  return s.str();
}

// Only the address-space tests use it, and sanitizer builds skip them.
[[maybe_unused]] std::string duplicate_off_vertices(int count) {
  return "OFF\n" + std::to_string(count) + " 0 0\n" + duplicate_points(count);
}

class CliMemory : public cvms::test::CliTest {
 protected:
  CliMemory() : CliTest("cli_memory_") {}
  void SetUp() override {
#ifndef CVMS_CLI_PATH
    GTEST_SKIP() << "the cvms tool is not built (CVMS_BUILD_TOOLS=OFF)";
#endif
  }
  [[nodiscard]] std::uint64_t size_of(const std::string& name) const {
    return std::filesystem::file_size(dir_.path() / name);
  }
  // `cvms args` through /bin/sh under `ulimit -v kib`; exec, so that a
  // signal ends the run itself (code -1), not a shell that reports it.
  [[nodiscard]] cvms::test::CliOutcome run_within(std::uint64_t kib, const std::string& args) const {
#ifdef CVMS_CLI_PATH
    return cvms::test::run_cli(
        dir_.path(), "/bin/sh",
        "-c \"ulimit -v " + std::to_string(kib) + " && exec '" CVMS_CLI_PATH "' " + args + "\"");
#else
    (void)kib;
    (void)args;
    return {};
#endif
  }
};

TEST_F(CliMemory, AFileBeyondTheBudgetIsRefusedBeforeItIsRead) {
  dir_.write("dup.rows", duplicate_plain_rows(60'000));
  const std::uint64_t estimate = size_of("dup.rows") * memory_per_row_byte;
  cvms::test::CliOutcome o =
      run("hull --from-halfspaces dup.rows -o cube.off --max-memory " + std::to_string(estimate - 1));
  EXPECT_EQ(o.code, 1) << o.err;
  EXPECT_EQ(o.err, "cvms: limit: dup.rows: an input of " + std::to_string(size_of("dup.rows")) +
                       " bytes is estimated to need up to " + std::to_string(estimate) +
                       " bytes of memory (256 per byte), beyond the memory limit of " +
                       std::to_string(estimate - 1) + " bytes; raise it with --max-memory\n");
  EXPECT_FALSE(std::filesystem::exists(dir_.path() / "cube.off"));
  o = run("hull --from-halfspaces dup.rows -o cube.off --max-memory " + std::to_string(estimate));
  ASSERT_EQ(o.code, 0) << o.err;
  o = run("check cube.off");
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_NE(o.out.find("V 8 E 12 F 6"), std::string::npos) << o.out;
}

TEST_F(CliMemory, TheInputsOfACommandShareTheBudget) {
  dir_.write("a.xyz", duplicate_points(10'000));
  dir_.write("b.rows", duplicate_plain_rows(10'000));
  const std::uint64_t a = size_of("a.xyz") * memory_per_row_byte, b = size_of("b.rows") * memory_per_row_byte;
  cvms::test::CliOutcome o = run("sum a.xyz b.rows -o s.off --max-memory " + std::to_string(a + b));
  ASSERT_EQ(o.code, 0) << o.err;
  o = run("sum a.xyz b.rows -o s.off --max-memory " + std::to_string(a + b - 1));
  EXPECT_EQ(o.code, 1) << o.err;
  EXPECT_NE(o.err.find("cvms: limit: b.rows: an input of "), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("beyond " + std::to_string(b - 1) + " bytes left of the memory limit of " +
                       std::to_string(a + b - 1) + " bytes; raise it with --max-memory"),
            std::string::npos)
      << o.err;
}

TEST_F(CliMemory, EveryCommandTakesTheOption) {
  dir_.write("p.ext", duplicate_cdd_points(1'000));
  dir_.write("cube.off",
             "OFF\n8 6 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n"
             "4 0 2 3 1\n4 4 5 7 6\n4 0 1 5 4\n4 2 6 7 3\n4 0 4 6 2\n4 1 3 7 5\n");
  for (const std::string command :
       {"hull p.ext -o h.off", "check p.ext", "halfspaces p.ext -o h.ine", "diff p.ext cube.off -o d.off",
        "distance p.ext cube.off", "penetration p.ext cube.off", "sum p.ext cube.off -o s.off"}) {
    const cvms::test::CliOutcome o = run(command + " --max-memory 1K");
    EXPECT_EQ(o.code, 1) << command << ": " << o.err;
    EXPECT_NE(o.err.find("cvms: limit: p.ext: an input of "), std::string::npos) << command << ": " << o.err;
    EXPECT_NE(o.err.find("raise it with --max-memory"), std::string::npos) << command << ": " << o.err;
  }
  const cvms::test::CliOutcome o = run("gen zonotope --generators 100 -o z.off --max-memory 1K");
  EXPECT_EQ(o.code, 1) << o.err;
  EXPECT_NE(o.err.find("raise it with --max-memory"), std::string::npos) << o.err;
}

TEST_F(CliMemory, AStreamStopsAtTheBudget) {
  dir_.write("dup.ine", duplicate_cdd_rows(10'000));
  const std::uint64_t budget = std::uint64_t{1} << 20;
  const cvms::test::CliOutcome o = run("hull --from-halfspaces - -o cube.off --max-memory 1M < dup.ine");
  EXPECT_EQ(o.code, 1) << o.err;
  EXPECT_EQ(o.err, "cvms: limit: <stdin>: input is larger than the limit of " +
                       std::to_string(budget / memory_per_row_byte) +
                       " bytes (256 bytes of memory per byte of input, beyond the memory limit of " +
                       std::to_string(budget) + " bytes; raise it with --max-memory)\n");
}

#ifndef CVMS_TEST_UNDER_SANITIZER  // sanitizers reserve terabytes of address space

// 240,000 duplicate rows (2 MB) need about 230 MiB of address space; under a
// limit of 146 MiB the default budget is 41 MiB, and the file is refused at
// once, never with GMP's abort (code -1, SIGABRT) or `out of memory`.
TEST_F(CliMemory, UnderAnAddressSpaceLimitTheDefaultBudgetRefusesInsteadOfAborting) {
  dir_.write("dup.rows", duplicate_plain_rows(240'000));
  dir_.write("dup.ine", duplicate_cdd_rows(240'000));
  constexpr std::uint64_t kib = 150'000;
  for (const std::string name : {"dup.rows", "dup.ine"}) {
    cvms::test::CliOutcome o = run_within(kib, "hull --from-halfspaces " + name + " -o cube.off");
    EXPECT_EQ(o.code, 1) << name << ": " << o.err;
    EXPECT_EQ(o.err.rfind("cvms: limit: " + name + ": an input of ", 0), 0u) << o.err;
    EXPECT_NE(o.err.find("beyond the memory limit of 42991616 bytes; raise it with --max-memory"),
              std::string::npos)
        << o.err;
    o = run_within(kib, "hull --from-halfspaces - -o cube.off < " + name);
    EXPECT_EQ(o.code, 1) << name << " on stdin: " << o.err;
    EXPECT_EQ(o.err.rfind("cvms: limit: <stdin>: input is larger than the limit of ", 0), 0u) << o.err;
  }
  const cvms::test::CliOutcome o = run_within(kib, "sum --help");
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_NE(o.out.find("--max-memory TEXT=41M "), std::string::npos) << o.out;
}

// Each reader at a budget of exactly its estimate, in an address space of
// that budget plus the program's own share: it completes, so the memory it
// takes per byte of input stays within the estimate.
TEST_F(CliMemory, TheEstimateBoundsWhatEachReaderTakes) {
  constexpr int count = 60'000;
  dir_.write("dup.rows", duplicate_plain_rows(count));
  dir_.write("dup.ine", duplicate_cdd_rows(count));
  dir_.write("dup.xyz", duplicate_points(count));
  dir_.write("dup.ext", duplicate_cdd_points(count));
  dir_.write("dup.off", duplicate_off_vertices(count));
  // Files of the plane: the square [-1, 1]^2 as rows a b c, the unit square as corners x y.
  constexpr const char* square[] = {"1 0 1\n", "-1 0 1\n", "0 1 1\n", "0 -1 1\n"};
  std::string square_rows, square_corners;
  for (int i = 0; i < count; ++i) {
    square_rows += square[i % 4];
    square_corners += std::to_string(i & 1) + ' ' + std::to_string((i >> 1) & 1) + '\n';
  }
  dir_.write("square.rows", square_rows);
  dir_.write("square.xyz", square_corners);
  dir_.write("origin.xyz", "0 0\n");
  struct Case {
    std::string args, file;
    std::uint64_t per_byte;
  };
  for (const Case& c : {Case{"hull --from-halfspaces {} -o h.off", "dup.rows", memory_per_row_byte},
                        Case{"hull --from-halfspaces {} -o h.off", "dup.ine", memory_per_row_byte},
                        Case{"hull {} -o h.off", "dup.xyz", memory_per_row_byte},
                        Case{"hull {} -o h.off", "dup.ext", memory_per_row_byte},
                        Case{"hull {} -o h.off", "dup.off", memory_per_mesh_byte},
                        Case{"check {}", "dup.ext", memory_per_row_byte},
                        Case{"halfspaces {} -o h.ine", "dup.off", memory_per_mesh_byte},
                        Case{"diff {} origin.xyz -o d.rows", "square.rows", memory_per_row_byte},
                        Case{"diff {} origin.xyz -o d.xyz", "square.xyz", memory_per_row_byte}}) {
    // origin.xyz, 4 bytes, is within the rounding of the budget.
    const std::uint64_t estimate = size_of(c.file) * c.per_byte + 4 * memory_per_row_byte;
    const std::uint64_t kib = (estimate + program_address_space) / 1024;
    std::string args = c.args;
    args.replace(args.find("{}"), 2, c.file);
    args += " --max-memory " + std::to_string(estimate);
    const cvms::test::CliOutcome o = run_within(kib, args);
    EXPECT_EQ(o.code, 0) << args << " within " << kib << " KiB: " << o.err;
  }
}

#endif

}  // namespace
