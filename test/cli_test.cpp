// SPDX-License-Identifier: MIT
// Tests of the `cvms` command-line tool: runs the built binary on real files
// and checks exit codes, the one-line error messages, and the output files,
// read back with the library and compared exactly with independent results
// (hand-counted shapes, brute-force hulls of pairwise sums, CHMS).
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "cvms/convex_polyhedron.hpp"
#include "cvms/io.hpp"
#include "cvms/minkowski.hpp"
#include "cvms/rational.hpp"
#include "cvms/set_io.hpp"
#include "cvms/set_sum.hpp"
#include "cvms/shapes.hpp"
#include "support/oracle.hpp"
#include "support/prism_attack.hpp"
#include "support/set_oracle.hpp"

namespace cvms {
namespace {

namespace fs = std::filesystem;

struct Outcome {
  int code = -1;
  std::string out, err;
};

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t count_lines(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
#ifndef CVMS_CLI_PATH
    GTEST_SKIP() << "the cvms tool is not built (CVMS_BUILD_TOOLS=OFF)";
#else
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("cvms_cli_test_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
#endif
  }
  void TearDown() override {
    if (!dir_.empty() && !HasFailure()) fs::remove_all(dir_);
  }

  fs::path file(const std::string& name) const { return dir_ / name; }
  std::string path(const std::string& name) const { return file(name).string(); }

  void write_text(const std::string& name, const std::string& text) const {
    std::ofstream out(file(name), std::ios::binary);
    out << text;
  }

  // Runs `cvms <args>` in the test directory; stdin from `input` if given.
  Outcome run(const std::string& args, const std::string& input = "") const {
#ifdef CVMS_CLI_PATH
    std::string command = "cd '" + dir_.string() + "' && '" CVMS_CLI_PATH "' " + args + " > '" +
                          path("stdout.txt") + "' 2> '" + path("stderr.txt") + "'";
    if (!input.empty()) command += " < '" + path(input) + "'";
    int status = std::system(command.c_str());
    Outcome outcome;
    outcome.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    outcome.out = slurp(file("stdout.txt"));
    outcome.err = slurp(file("stderr.txt"));
    return outcome;
#else
    (void)args;
    (void)input;
    return {};
#endif
  }

  ConvexPolyhedron load(const std::string& name) const {
    return ConvexPolyhedron::from_soup(read_file(file(name)));
  }

  // A failing run must exit 1 with exactly one line on stderr naming `what`.
  void expect_bad_input(const std::string& args, const std::string& what,
                        const std::string& input = "") const {
    SCOPED_TRACE("cvms " + args);
    Outcome o = run(args, input);
    EXPECT_EQ(o.code, 1) << o.err;
    EXPECT_EQ(count_lines(o.err), 1U) << o.err;
    EXPECT_NE(o.err.find(what), std::string::npos) << o.err;
    EXPECT_NE(o.err.find("cvms: "), std::string::npos) << o.err;
  }

  void expect_usage(const std::string& args) const {
    SCOPED_TRACE("cvms " + args);
    Outcome o = run(args);
    EXPECT_EQ(o.code, 2) << o.err;
    EXPECT_FALSE(o.err.empty());
  }

  fs::path dir_;
};

// V E F and the facet degree histogram of each built-in shape, counted by hand.
struct ShapeCase {
  const char* args;
  const char* counts;
  std::vector<const char*> degrees;
};

TEST_F(Cli, GenThenCheckRoundTrip) {
  const std::vector<ShapeCase> cases = {
      {"tetrahedron", "V 4 E 6 F 4", {"  3: 4"}},
      {"cube", "V 8 E 12 F 6", {"  4: 6"}},
      {"octahedron", "V 6 E 12 F 8", {"  3: 8"}},
      {"truncated-cube", "V 24 E 36 F 14", {"  3: 8", "  8: 6"}},
      {"sphere --subdivisions 1", "V 12 E 30 F 20", {"  3: 20"}},
      {"box", "V 8 E 12 F 6", {"  4: 6"}},
      {"prism", "V 12 E 18 F 8", {"  4: 6", "  6: 2"}},
      {"prism --points 5", "V 10 E 15 F 7", {"  4: 5", "  5: 2"}},
  };
  for (const char* ext : {".off", ".obj", ".stl"}) {
    for (const ShapeCase& c : cases) {
      SCOPED_TRACE(std::string(c.args) + ext);
      std::string name = std::string("shape") + ext;
      Outcome gen = run(std::string("gen ") + c.args + " -o " + name);
      ASSERT_EQ(gen.code, 0) << gen.err;
      Outcome check = run("check " + name);
      ASSERT_EQ(check.code, 0) << check.err;
      EXPECT_NE(check.out.find(c.counts), std::string::npos) << check.out;
      for (const char* d : c.degrees) EXPECT_NE(check.out.find(d), std::string::npos) << check.out;
    }
  }
}

TEST_F(Cli, GenWritesExactShapes) {
  ASSERT_EQ(run("gen truncated-cube -o t.off").code, 0);
  EXPECT_EQ(test::describe(load("t.off")), test::describe(shapes::truncated_cube()));
  ASSERT_EQ(run("gen random --seed 7 --points 40 -o r.obj").code, 0);
  EXPECT_EQ(test::describe(load("r.obj")), test::describe(shapes::random_hull(7, 40)));
  ASSERT_EQ(run("gen rotated-sphere --subdivisions 2 -o s.off").code, 0);
  EXPECT_EQ(test::describe(load("s.off")), test::describe(shapes::rotated_geodesic_sphere(2)));
}

TEST_F(Cli, SumMatchesBruteForceHullOfPairwiseSums) {
  ASSERT_EQ(run("gen cube -o a.off").code, 0);
  ASSERT_EQ(run("gen tetrahedron -o b.obj").code, 0);
  std::vector<Vec3> a = read_file(file("a.off")).points;
  std::vector<Vec3> b = read_file(file("b.obj")).points;
  test::Shape expected = test::brute_force_hull(test::pairwise_sums(a, b));
  ASSERT_FALSE(expected.vertices.empty());
  Outcome o = run("sum a.off b.obj --algorithm chms -o s.off");
  ASSERT_EQ(o.code, 0) << o.err;
  ConvexPolyhedron s = load("s.off");
  EXPECT_EQ(test::describe(s), expected) << test::difference(expected, test::describe(s));
}

TEST_F(Cli, SumOfGeneratedFilesEqualsChmsForEveryAlgorithm) {
  ASSERT_EQ(run("gen truncated-cube -o a.off").code, 0);
  ASSERT_EQ(run("gen sphere --subdivisions 2 -o b.obj").code, 0);
  const test::Shape expected = test::describe(chms(load("a.off"), load("b.obj")));
  for (const char* algorithm : {"", " --algorithm chms", " --algorithm cvms", " --algorithm essdms"}) {
    SCOPED_TRACE(algorithm);
    Outcome o = run(std::string("sum a.off b.obj -o s.off") + algorithm);
    ASSERT_EQ(o.code, 0) << o.err;
    EXPECT_TRUE(o.out.empty()) << o.out;
    EXPECT_EQ(test::describe(load("s.off")), expected);
  }
}

// --threads N writes the same bytes as one thread (the library's guarantee,
// through the CLI); 0 threads is a usage error.
TEST_F(Cli, SumWithThreadsWritesTheSameFile) {
  ASSERT_EQ(run("gen sphere --subdivisions 3 -o a.off").code, 0);
  ASSERT_EQ(run("gen rotated-sphere --subdivisions 3 -o b.off").code, 0);
  ASSERT_EQ(run("sum a.off b.off -o one.off").code, 0);
  for (const char* threads : {"2", "4"}) {
    Outcome o = run(std::string("sum a.off b.off --threads ") + threads + " -o many.off");
    ASSERT_EQ(o.code, 0) << o.err;
    EXPECT_EQ(slurp(file("many.off")), slurp(file("one.off"))) << threads << " threads";
  }
  expect_usage("sum a.off b.off --threads 0");
}

TEST_F(Cli, SumStatsAndFloatOutput) {
  ASSERT_EQ(run("gen cube -o a.off").code, 0);
  ASSERT_EQ(run("gen rotated-sphere --subdivisions 1 -o b.off").code, 0);
  Outcome o = run("sum a.off b.off --algorithm chms --stats --float -o s.off");
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_NE(o.out.find("algorithm: chms"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("\ntime: "), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("\nread time: "), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("\nwrite time: "), std::string::npos) << o.out;
  ConvexPolyhedron exact = chms(load("a.off"), load("b.off"));
  EXPECT_NE(o.out.find("A+B: V " + std::to_string(exact.num_vertices()) + " E " +
                       std::to_string(exact.num_edges()) + " F " + std::to_string(exact.num_facets())),
            std::string::npos)
      << o.out;
  // --float: every coordinate is the double nearest to the exact one (the
  // file holds the shortest decimal that reads back to that double).
  using Doubles = std::array<double, 3>;
  auto nearest = [](const Vec3& p) {
    return Doubles{to_double_nearest(p.x), to_double_nearest(p.y), to_double_nearest(p.z)};
  };
  std::set<Doubles> rounded;
  for (VertexId v : exact.mesh().vertices()) rounded.insert(nearest(exact.vertex(v)));
  std::set<Doubles> got;
  for (const Vec3& p : read_file(file("s.off")).points) got.insert(nearest(p));
  EXPECT_EQ(got, rounded);
  EXPECT_EQ(got.size(), exact.num_vertices());
}

// --stats shows the operands' facet planes as a part of the read time and
// the wait for the disk as a part of the write time: a file replaced
// atomically is synchronised, standard output is not.
TEST_F(Cli, SumStatsShowThePlanesInTheReadAndTheSyncInTheWrite) {
  ASSERT_EQ(run("gen cube -o a.off").code, 0);
  ASSERT_EQ(run("gen rotated-sphere --subdivisions 2 -o b.off").code, 0);
  // The whole and the part of a line "<name> time: W ms (of it, <part> time: P ms)".
  const auto times = [](const std::string& report, const std::string& name, const std::string& part) {
    const std::string head = "\n" + name + " time: ", middle = " ms (of it, " + part + " time: ";
    const std::size_t at = report.find(head);
    const std::size_t mid = at == std::string::npos ? at : report.find(middle, at);
    const std::size_t end = mid == std::string::npos ? mid : report.find(" ms)\n", mid);
    EXPECT_NE(end, std::string::npos) << report;
    if (end == std::string::npos) return std::pair<double, double>{-1, -1};
    const std::size_t whole = at + head.size(), part_at = mid + middle.size();
    return std::pair{std::stod(report.substr(whole, mid - whole)), std::stod(report.substr(part_at, end - part_at))};
  };
  const Outcome to_file = run("sum a.off b.off --stats -o s.off");
  ASSERT_EQ(to_file.code, 0) << to_file.err;
  for (const auto& [name, part] : {std::pair{"read", "facet planes"}, std::pair{"write", "disk sync"}}) {
    const auto [whole, of_it] = times(to_file.out, name, part);
    EXPECT_GE(of_it, 0.0) << name;
    EXPECT_LE(of_it, whole) << name;
  }
  const Outcome to_stdout = run("sum a.off b.off --stats -o -");
  ASSERT_EQ(to_stdout.code, 0) << to_stdout.err;
  EXPECT_EQ(times(to_stdout.err, "write", "disk sync").second, 0.0) << to_stdout.err;
  EXPECT_EQ(to_stdout.out, slurp(file("s.off")));
}

TEST_F(Cli, StdinAndStdout) {
  // gen to stdout is OFF.
  Outcome gen = run("gen octahedron -o -");
  ASSERT_EQ(gen.code, 0) << gen.err;
  std::istringstream off(gen.out);
  EXPECT_EQ(test::describe(ConvexPolyhedron::from_soup(read_off(off, "stdout"))),
            test::describe(shapes::octahedron()));
  write_text("oct.off", gen.out);
  // check from stdin.
  Outcome check = run("check -", "oct.off");
  ASSERT_EQ(check.code, 0) << check.err;
  EXPECT_NE(check.out.find("V 6 E 12 F 8"), std::string::npos) << check.out;
  // sum with one operand on stdin and the result on stdout; stats go to stderr.
  ASSERT_EQ(run("gen cube -o cube.stl").code, 0);
  Outcome sum = run("sum - cube.stl --algorithm chms --stats -o -", "oct.off");
  ASSERT_EQ(sum.code, 0) << sum.err;
  EXPECT_NE(sum.err.find("algorithm: chms"), std::string::npos) << sum.err;
  std::istringstream result(sum.out);
  EXPECT_EQ(test::describe(ConvexPolyhedron::from_soup(read_off(result, "stdout"))),
            test::describe(chms(shapes::octahedron(), shapes::cube())));
  // sum with no -o writes to stdout too.
  Outcome plain = run("sum oct.off cube.stl --algorithm chms");
  ASSERT_EQ(plain.code, 0) << plain.err;
  EXPECT_EQ(plain.out, sum.out);
}

TEST_F(Cli, HullOfPointLines) {
  // The cube's corners, interior points, duplicates and points on its facets.
  write_text("points.xyz",
             "# a cube with clutter\n"
             "-1 -1 -1\n1 -1 -1\n-1 1 -1\n1 1 -1\n-1 -1 1\n1 -1 1\n-1 1 1\n1 1 1\n"
             "0 0 0\n0.5 -0.25 1/3\n1 0 0\n1 1 1\n0 0 -1\n\n1 1 0\n");
  Outcome o = run("hull points.xyz -o h.off");
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_EQ(test::describe(load("h.off")), test::describe(shapes::cube()));
  // Points from a mesh file, read on stdin.
  ASSERT_EQ(run("gen truncated-cube -o t.off").code, 0);
  Outcome piped = run("hull - -o h2.obj", "t.off");
  ASSERT_EQ(piped.code, 0) << piped.err;
  EXPECT_EQ(test::describe(load("h2.obj")), test::describe(shapes::truncated_cube()));
}

TEST_F(Cli, Demo) {
  ConvexPolyhedron sphere = shapes::geodesic_sphere(4);
  ConvexPolyhedron sum = chms(shapes::cube(), sphere);
  auto counts = [](const ConvexPolyhedron& p) {
    return "V " + std::to_string(p.num_vertices()) + " E " + std::to_string(p.num_edges()) + " F " +
           std::to_string(p.num_facets());
  };
  const std::string default_algorithm = Options{}.algorithm == Algorithm::cvms ? "cvms" : "?";
  for (const std::string& algorithm : {std::string(), std::string("chms"), std::string("essdms")}) {
    SCOPED_TRACE("demo " + algorithm);
    Outcome o = run(algorithm.empty() ? "demo" : "demo --algorithm " + algorithm);
    ASSERT_EQ(o.code, 0) << o.err;
    EXPECT_NE(o.out.find("Cube      V 8 E 12 F 6"), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("Sphere4   " + counts(sphere)), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("sum       " + counts(sum)), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("algorithm: " + (algorithm.empty() ? default_algorithm : algorithm)),
              std::string::npos)
        << o.out;
    EXPECT_NE(o.out.find("time: "), std::string::npos) << o.out;
  }
}

TEST_F(Cli, UsageErrorsExitTwo) {
  ASSERT_EQ(run("gen cube -o a.off").code, 0);
  expect_usage("");
  expect_usage("frobnicate");
  expect_usage("sum a.off");
  expect_usage("sum a.off a.off --algorithm fastest");
  expect_usage("sum a.off a.off --bogus");
  expect_usage("sum a.txt a.off");
  expect_usage("sum a.off a.off -o out.wrl");
  expect_usage("sum - - -o x.off");
  expect_usage("gen pyramid");
  expect_usage("gen cube --subdivisions 3");
  expect_usage("gen sphere --subdivisions 0");
  expect_usage("gen sphere --subdivisions 12");
  expect_usage("gen cube --seed 4");
  expect_usage("gen random --points 3");
  expect_usage("check");
  expect_usage("check a.off extra.off");
  Outcome help = run("--help");
  EXPECT_EQ(help.code, 0);
  EXPECT_NE(help.out.find("sum"), std::string::npos);
}

TEST_F(Cli, BadInputExitsOneWithOneLineNamingTheFile) {
  ASSERT_EQ(run("gen cube -o cube.off").code, 0);
  // A parse error: names the file and the line.
  write_text("broken.off", "OFF\n4 4 0\n0 0 0\n1 0 zero\n0 1 0\n0 0 1\n3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n");
  expect_bad_input("check broken.off", "broken.off");
  Outcome parse = run("check broken.off");
  EXPECT_NE(parse.err.find("broken.off:4"), std::string::npos) << "line 4 not named: " << parse.err;
  expect_bad_input("sum cube.off broken.off -o s.off", "broken.off");
  EXPECT_FALSE(fs::exists(file("s.off")));
  // Missing file.
  expect_bad_input("check missing.off", "missing.off");
  expect_bad_input("sum missing.stl cube.off", "missing.stl");
  // Open surface (a cube without its top): topology, names the file.
  write_text("open.off",
             "OFF\n8 5 0\n-1 -1 -1\n1 -1 -1\n1 1 -1\n-1 1 -1\n-1 -1 1\n1 -1 1\n1 1 1\n-1 1 1\n"
             "4 0 3 2 1\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n");
  expect_bad_input("check open.off", "open.off");
  // An octahedron whose top vertex is pushed below the equator: reflex edges.
  // A valid solid (`check` reports it, cli_pieces_test), refused as an
  // operand of a sum of more than two (a sum of two writes its sum as a
  // solid, cli_solid_sum_test).
  write_text("dent.off",
             "OFF\n6 8 0\n1 0 0\n0 1 0\n-1 0 0\n0 -1 0\n0 0 -1/2\n0 0 -1\n"
             "3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4\n3 1 0 5\n3 2 1 5\n3 3 2 5\n3 0 3 5\n");
  expect_bad_input("sum dent.off cube.off cube.off", "dent.off");
  Outcome dent = run("sum dent.off cube.off cube.off");
  EXPECT_NE(dent.err.find("not_convex"), std::string::npos) << dent.err;
  // A non-convex flat face (flat input is a set, but a reflex one is not).
  write_text("bent.off", "OFF\n4 1 0\n0 0 0\n4 0 0\n1 1 0\n0 4 0\n4 0 1 2 3\n");
  expect_bad_input("check bent.off", "bent.off: face 0: polygon: vertex 2 is a reflex corner");
  // Bad input on stdin is named as such.
  expect_bad_input("check -", "<stdin>", "broken.off");
  // An unwritable output.
  expect_bad_input("gen cube -o no/such/dir/x.off", "no/such/dir/x.off");
}

// The CLI's default --max-memory as --help spells it, computed here from the
// machine: the library's 4G, or half of the physical memory (or of a smaller
// cgroup v2 limit, or of the address-space limit less 64 MiB) rounded down
// to MiB where that is less.
std::string expected_default_max_memory() {
  std::uint64_t usable = 0;
#if defined(_SC_PHYS_PAGES) && defined(_SC_PAGESIZE)
  usable = static_cast<std::uint64_t>(sysconf(_SC_PHYS_PAGES)) * static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE));
#endif
  std::ifstream cgroup("/sys/fs/cgroup/memory.max");
  std::string limit;
  if (cgroup >> limit && !limit.empty() && limit.find_first_not_of("0123456789") == std::string::npos &&
      limit.size() < 20 && (usable == 0 || std::stoull(limit) < usable))
    usable = std::stoull(limit);
  struct rlimit address_space {};
  constexpr std::uint64_t program = std::uint64_t{64} << 20;
  if (getrlimit(RLIMIT_AS, &address_space) == 0 && address_space.rlim_cur != RLIM_INFINITY) {
    const std::uint64_t left = std::max<std::uint64_t>(address_space.rlim_cur, program + (4 << 20)) - program;
    if (usable == 0 || left < usable) usable = left;
  }
  if (usable < (std::uint64_t{4} << 20) || usable / 2 >= (std::uint64_t{4} << 30)) return "4G";
  const std::uint64_t mib = usable / 2 >> 20;
  return mib % 1024 == 0 ? std::to_string(mib / 1024) + "G" : std::to_string(mib) + "M";
}

// Output quadratic in the input. Two n-gon prisms with
// perpendicular axes have about n^2 / 2 output facets; sum refuses them
// with one line naming the limit and the option that raises it, writes
// nothing, and the options take sizes with suffixes.
TEST_F(Cli, SumLimitsRefuseThePrismAttack) {
  const test::PrismPair pair = test::prism_attack(150);
  const ConvexPolyhedron& a = pair.a;
  const ConvexPolyhedron& b = pair.b;
  write_file(file("a.off"), a.to_soup());
  write_file(file("b.off"), b.to_soup());
  const test::Shape expected = test::describe(chms(a, b));  // the oracle
  const std::uint64_t facets = expected.planes.size();
  ASSERT_GT(facets, 8000u);

  expect_bad_input("sum a.off b.off --max-facets 5000 -o s.off", "--max-facets");
  Outcome o = run("sum a.off b.off --max-facets 5000 -o s.off");
  EXPECT_NE(o.err.find("cvms: limit: "), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("beyond the limit of 5000 facets (SumLimits::max_output_facets)"), std::string::npos)
      << o.err;
  EXPECT_FALSE(fs::exists(file("s.off")));
  // 4M holds the inputs (12 KB each, 144 bytes of memory per byte), not the output.
  expect_bad_input("sum a.off b.off --max-memory 4M -o s.off", "--max-memory");
  o = run("sum a.off b.off --max-memory 4M -o s.off");
  EXPECT_NE(o.err.find("beyond the limit of 4194304 bytes (SumLimits::max_memory_bytes)"), std::string::npos)
      << o.err;
  expect_bad_input("sum a.off b.off --algorithm essdms --max-facets 5000 -o s.off", "--max-facets");
  expect_bad_input("sum a.off b.off --algorithm chms --max-memory 4M -o s.off", "--max-memory");
  EXPECT_FALSE(fs::exists(file("s.off")));

  // At the exact count (and with room to spare) the sum is the CHMS oracle's.
  for (const std::string& limits : {"--max-facets " + std::to_string(facets), std::string("--max-memory 64M"),
                                    std::string("--max-memory 1GiB --max-facets 50000")}) {
    SCOPED_TRACE(limits);
    ASSERT_EQ(run("sum a.off b.off -o s.off " + limits).code, 0);
    EXPECT_TRUE(test::describe(load("s.off")) == expected);
  }
  o = run("sum a.off b.off -o s.off --max-facets " + std::to_string(facets - 1));
  EXPECT_EQ(o.code, 1) << o.err;

  // Sizes: digits, then K, M, G or T (binary), optionally B or iB.
  for (const char* size : {"4194304", "4096K", "64M", "4G", "1T", "64MB", "64MiB", "64m"})
    EXPECT_EQ(run(std::string("sum a.off a.off -o t.off --max-memory ") + size).code, 0) << size;
  for (const char* bad : {"12X", "-5", "M", "1.5G", "99999999999999999999", "20000000000000000G", "4 G"})
    expect_usage(std::string("sum a.off a.off -o t.off --max-memory '") + bad + "'");
  for (const char* bad : {"0", "-1", "many", "1e6"})
    expect_usage(std::string("sum a.off a.off -o t.off --max-facets ") + bad);

  // The help shows the defaults: the library's facet limit, and its memory
  // limit lowered to half of a small machine's memory (a sum the machine
  // cannot hold is refused before the OOM killer ends it).
  o = run("sum --help");
  EXPECT_NE(o.out.find("--max-facets"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find(std::to_string(SumLimits{}.max_output_facets)), std::string::npos) << o.out;
  const std::string memory_line = o.out.substr(o.out.find("--max-memory"));
  EXPECT_EQ(memory_line.substr(0, memory_line.find('\n')).find("=" + expected_default_max_memory() + " "),
            std::string("--max-memory TEXT").size())
      << o.out;
}

// ---- convex sets of every dimension ------------------------------------------

TEST_F(Cli, FlatInputsAndSumsOfMany) {
  // hull of coplanar points writes the polygon; check reports the dimension.
  write_text("flat.xyz", "0 0 0\n1 0 0\n0 1 0\n1 1 0\n1/2 1/2 0\n");
  ASSERT_EQ(run("hull flat.xyz -o square.off").code, 0);
  Outcome check = run("check square.off");
  ASSERT_EQ(check.code, 0) << check.err;
  EXPECT_NE(check.out.find("square.off: convex polygon\ndimension 2, V 4"), std::string::npos) << check.out;
  // Three axis segments (points-only OFFs) give the box.
  write_text("x.off", "OFF\n2 0 0\n0 0 0\n1 0 0\n");
  write_text("y.off", "OFF\n2 0 0\n0 0 0\n0 2 0\n");
  write_text("z.off", "OFF\n2 0 0\n0 0 0\n0 0 3\n");
  Outcome sum = run("sum x.off y.off z.off -o box.off");
  ASSERT_EQ(sum.code, 0) << sum.err;
  ASSERT_EQ(run("gen box -o expected.off").code, 0);
  EXPECT_EQ(test::describe(load("box.off")), test::describe(load("expected.off")));
  // A flat OBJ as a modeller exports it (every z = 0, a 240-gon fanned from
  // its centre) plus a solid hull, against the oracle.
  const std::vector<Vec2> circle = shapes::circle_polygon(240);
  std::string obj = "o profile\nv 0 0 0\n";
  for (const Vec2& p : circle) obj += "v " + to_string(p.x) + " " + to_string(p.y) + " 0\n";
  for (std::size_t i = 0; i < circle.size(); ++i)
    obj += "f 1 " + std::to_string(i + 2) + " " + std::to_string((i + 1) % circle.size() + 2) + "\n";
  write_text("profile.obj", obj);
  ASSERT_EQ(run("gen random --seed 3 --points 30 -o solid.off").code, 0);
  Outcome flat_sum = run("sum profile.obj solid.off -o swept.off --stats");
  ASSERT_EQ(flat_sum.code, 0) << flat_sum.err;
  EXPECT_NE(flat_sum.out.find("operand 1: convex polygon, dimension 2, V 240"), std::string::npos) << flat_sum.out;
  const test::SetShape expected =
      test::sum_oracle(read_convex_set(file("profile.obj")), ConvexSet(shapes::random_hull(3, 30)));
  EXPECT_EQ(test::describe_set(read_convex_set(file("swept.off"))), expected);
  // Two inputs on stdin are a usage error.
  expect_usage("sum - x.off - -o s.off");
}

TEST_F(Cli, GenZonotope) {
  Outcome gen = run("gen zonotope --generators 6 --seed 5 -o z.obj");
  ASSERT_EQ(gen.code, 0) << gen.err;
  Outcome check = run("check z.obj");
  ASSERT_EQ(check.code, 0) << check.err;
  EXPECT_NE(check.out.find("V 32 E 60 F 30"), std::string::npos) << check.out;  // n^2-n+2, 2n(n-1), n(n-1)
  std::vector<Vec3> g = shapes::random_points(5, 6);
  g.resize(6);
  EXPECT_EQ(test::describe_set(read_convex_set(file("z.obj"))), test::describe_set(zonotope(Vec3{0, 0, 0}, g)));
  ASSERT_EQ(run("gen zonotope --generators 1 -o seg.off").code, 0);
  EXPECT_NE(run("check seg.off").out.find("segment"), std::string::npos);
  expect_usage("gen cube --generators 3");
  expect_usage("gen zonotope --generators 0");
}

// The same set gives the same bytes whatever the operand order (which
// decides the partial sums, and so the numbering) and thread count:
// vertices in lexicographic order, faces from their smallest vertex.
TEST_F(Cli, SumOfManyWritesTheSameBytesInEveryOperandOrder) {
  ASSERT_EQ(run("gen random --points 8 --seed 5 -o r.off").code, 0);
  ASSERT_EQ(run("gen octahedron -o o.off").code, 0);
  ASSERT_EQ(run("gen box -o b.off").code, 0);
  write_text("square.off", "OFF\n4 1 0\n0 0 0\n2 0 0\n2 1 0\n0 1 0\n4 0 1 2 3\n");
  write_text("segment.off", "OFF\n2 0 0\n0 0 0\n1 1 1\n");
  for (const std::vector<std::string>& operands :
       {std::vector<std::string>{"r.off", "o.off", "b.off"}, {"square.off", "segment.off", "o.off"},
        {"segment.off", "square.off", "segment.off", "r.off"}}) {
    std::vector<std::string> order = operands;
    std::sort(order.begin(), order.end());
    std::string first;
    do {
      std::string args = "sum";
      for (const std::string& o : order) args += " " + o;
      for (const char* threads : {"1", "3"}) {
        SCOPED_TRACE(args + " --threads " + threads);
        const Outcome o = run(args + " --threads " + threads);
        ASSERT_EQ(o.code, 0) << o.err;
        if (first.empty()) first = o.out;
        EXPECT_EQ(o.out, first);
      }
    } while (std::next_permutation(order.begin(), order.end()));
    // The order is lexicographic in the exact coordinates.
    const ConvexSet sum = read_convex_set([&] {
      write_text("sum.off", first);
      return file("sum.off");
    }());
    const std::vector<Vec3> v = sum.vertices();
    for (std::size_t i = 1; i < v.size(); ++i)
      EXPECT_TRUE(std::tie(v[i - 1].x, v[i - 1].y, v[i - 1].z) < std::tie(v[i].x, v[i].y, v[i].z)) << i;
  }
}

// Every format a command writes reads back in every command that takes
// that kind of input: sets written as OFF, OBJ, STL (sum, hull, diff, gen)
// and cdd V-representation (halfspaces -o .ext) are read by hull, check,
// sum, diff, distance, penetration and halfspaces; rows written as .ine,
// plain rows and cdd on stdout (halfspaces) by hull --from-halfspaces.
TEST_F(Cli, EveryWrittenFormatReadsBackInEveryReader) {
  write_text("square.off", "OFF\n4 1 0\n0 0 0\n2 0 0\n2 1 0\n0 1 0\n4 0 1 2 3\n");
  ASSERT_EQ(run("gen random --points 30 --seed 7 -o solid.off").code, 0);
  for (const std::string base : {"solid", "square"}) {
    SCOPED_TRACE(base);
    const test::SetShape expected = test::describe_set(read_convex_set(file(base + ".off")));
    const bool solid = base == "solid";
    // Each command's output on the OFF original, compared with its output on each copy.
    const auto output_on = [&](const std::string& command_with_x, const std::string& name) {
      std::string args = command_with_x;
      for (std::size_t at; (at = args.find('X')) != std::string::npos;) args.replace(at, 1, name);
      const Outcome o = run(args);
      EXPECT_EQ(o.code, 0) << args << ": " << o.err;
      std::string out = o.out;
      for (std::size_t at; (at = out.find(name)) != std::string::npos;) out.replace(at, name.size(), "X");
      return out;
    };
    const std::vector<std::string> set_readers = {
        "check X",          "sum X square.off",   "sum square.off X solid.off", "diff X X",
        "distance X solid.off", "penetration X solid.off", "halfspaces X -o -"};
    for (const std::string format : {"off", "obj", "stl", "ply"}) {
      if (format == "stl" && !solid) continue;  // STL holds no flat set as one
      ASSERT_EQ(run("hull " + base + ".off -o " + base + "_hull." + format).code, 0) << format;
    }
    ASSERT_EQ(run("halfspaces " + base + ".off -o " + base + ".ext").code, 0);
    ASSERT_EQ(run("halfspaces " + base + ".off -o " + base + "_rows.ine").code, 0);
    ASSERT_EQ(run("halfspaces " + base + ".off -o " + base + "_rows.txt").code, 0);
    const Outcome rows_on_stdout = run("halfspaces " + base + ".off -o -");
    ASSERT_EQ(rows_on_stdout.code, 0);
    write_text(base + "_stdout.ine", rows_on_stdout.out);
    std::vector<std::string> copies = {base + "_hull.off", base + "_hull.obj", base + "_hull.ply", base + ".ext"};
    if (solid) copies.push_back(base + "_hull.stl");
    for (const std::string& copy : copies) {
      SCOPED_TRACE(copy);
      ASSERT_EQ(run("hull " + copy + " -o back.off").code, 0);
      EXPECT_EQ(test::describe_set(read_convex_set(file("back.off"))), expected);
      for (const std::string& reader : set_readers) {
        SCOPED_TRACE(reader);
        std::string on_copy = output_on(reader, copy);
        std::string on_original = output_on(reader, base + ".off");
        if (reader == "check X") {  // the input counts differ by format (STL: triangles)
          for (std::string* out : {&on_copy, &on_original}) {
            const std::size_t at = out->find("input:");
            if (at != std::string::npos) out->erase(at, out->find('\n', at) + 1 - at);
          }
        }
        if (reader.rfind("halfspaces", 0) == 0) {  // the same rows, perhaps in another order
          write_text("rows_copy.ine", on_copy);
          write_text("rows_original.ine", on_original);
          ASSERT_EQ(run("hull --from-halfspaces rows_copy.ine -o a.off").code, 0);
          ASSERT_EQ(run("hull --from-halfspaces rows_original.ine -o b.off").code, 0);
          EXPECT_EQ(test::describe_set(read_convex_set(file("a.off"))), expected);
          EXPECT_EQ(test::describe_set(read_convex_set(file("b.off"))), expected);
          continue;
        }
        if (reader.rfind("sum", 0) == 0) {  // the same set, numbered by the operands
          write_text("sum_copy.off", on_copy);
          write_text("sum_original.off", on_original);
          EXPECT_EQ(test::describe_set(read_convex_set(file("sum_copy.off"))),
                    test::describe_set(read_convex_set(file("sum_original.off"))));
          continue;
        }
        EXPECT_EQ(on_copy, on_original);
      }
    }
    for (const std::string& rows : {base + "_rows.ine", base + "_rows.txt", base + "_stdout.ine"}) {
      SCOPED_TRACE(rows);
      ASSERT_EQ(run("hull --from-halfspaces " + rows + " -o back.off").code, 0);
      EXPECT_EQ(test::describe_set(read_convex_set(file("back.off"))), expected);
    }
    ASSERT_EQ(run("hull --from-halfspaces - -o back.off", base + "_stdout.ine").code, 0);
    EXPECT_EQ(test::describe_set(read_convex_set(file("back.off"))), expected);
  }
}

// cdd V-representations hold bounded sets only here: rays and lines are
// refused with the reason, and a V-representation is not read as rows.
TEST_F(Cli, CddPointsRefuseRaysAndLines) {
  write_text("ray.ext", "V-representation\nbegin\n2 4 integer\n1 0 0 0\n0 1 0 0\nend\n");
  write_text("line.ext", "V-representation\nlinearity 1 1\nbegin\n1 4 integer\n0 1 0 0\nend\n");
  write_text("points.ext", "V-representation\nbegin\n1 4 integer\n1 0 0 0\nend\n");
  for (const std::string command : {"hull", "check", "halfspaces"}) {
    Outcome o = run(command + " ray.ext");
    EXPECT_EQ(o.code, 1);
    EXPECT_EQ(o.err, "cvms: parse: ray.ext: vertex 2 is a ray (first number 0): unbounded sets are not supported\n");
    o = run(command + " line.ext");
    EXPECT_EQ(o.code, 1);
    EXPECT_EQ(o.err,
              "cvms: parse: line.ext:6: linearity in a V-representation describes lines: unbounded sets are not "
              "supported\n");
  }
  Outcome o = run("hull --from-halfspaces points.ext");
  EXPECT_EQ(o.code, 1);
  EXPECT_EQ(o.err, "cvms: parse: points.ext:1: this is a V-representation, expected a H-representation\n");
  o = run("check points.txt");
  EXPECT_EQ(o.code, 2);
  EXPECT_NE(o.err.find("expected '-' or a file ending in .off, .obj, .stl, .ply or .ext"), std::string::npos) << o.err;
}

// gen takes --max-memory as sum does: a zonotope whose output is estimated
// beyond it is refused before anything is built (at once, not after the
// gigabytes of 2048 generators).
TEST_F(Cli, GenZonotopeRespectsMaxMemory) {
  Outcome o = run("gen zonotope --generators 2048 --max-memory 100M -o z.off");
  EXPECT_EQ(o.code, 1) << o.err;
  EXPECT_EQ(o.err,
            "cvms: limit: minkowski_sum (zonotope of 2048 segments in 2048 directions): the sum has up to 4192256 "
            "facets, which need about 4292870144 bytes (1024 per facet), beyond the limit of 104857600 bytes "
            "(SumLimits::max_memory_bytes); raise it with --max-memory\n");
  EXPECT_FALSE(fs::exists(file("z.off")));
  // 40 generators: 1560 facets, 1597440 bytes by the estimate.
  expect_bad_input("gen zonotope --generators 40 --max-memory 1M -o z.off", "raise it with --max-memory");
  Outcome fits = run("gen zonotope --generators 40 --max-memory 2M -o z.off");
  EXPECT_EQ(fits.code, 0) << fits.err;
  expect_usage("gen zonotope --max-memory 1X");
}

// Output quadratic in the input, for the sums of sets: a polygon plus a polyhedron (and
// sums of many) are counted before they are built and refused with the
// same limit error and hint as two polyhedra; a huge zonotope is refused
// at once.
TEST_F(Cli, SetSumLimitsRefuseBigSums) {
  std::string polygon = "OFF\n60 1 0\n";
  for (int k = 0; k < 60; ++k) polygon += std::to_string(k) + " 0 " + std::to_string(k * k) + "\n";
  polygon += "60";
  for (int k = 0; k < 60; ++k) {
    polygon += ' ';
    polygon += std::to_string(k);
  }
  write_text("parabola.off", polygon + "\n");
  ASSERT_EQ(run("gen prism --points 40 -o prism.off").code, 0);
  Outcome ok = run("sum parabola.off prism.off -o s.off --stats");
  ASSERT_EQ(ok.code, 0) << ok.err;
  const std::uint64_t facets = read_convex_set(file("s.off")).polyhedron().num_facets();
  ASSERT_GT(facets, 500u);
  fs::remove(file("s.off"));
  expect_bad_input("sum parabola.off prism.off --max-facets " + std::to_string(facets - 1) + " -o s.off",
                   "--max-facets");
  Outcome o = run("sum parabola.off prism.off --max-facets 500 -o s.off");
  EXPECT_NE(o.err.find("cvms: limit: "), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("(polygon + polyhedron): the sum has " + std::to_string(facets) + " facets"),
            std::string::npos)
      << o.err;
  EXPECT_NE(o.err.find("; raise it with --max-facets"), std::string::npos) << o.err;
  // 1000K holds the inputs (7 KB, 144 bytes of memory per byte), not the first sum.
  expect_bad_input("sum parabola.off prism.off prism.off --max-memory 1000K -o s.off",
                   "(SumLimits::max_memory_bytes); raise it with --max-memory");
  EXPECT_FALSE(fs::exists(file("s.off")));
  EXPECT_EQ(run("sum parabola.off prism.off --max-facets " + std::to_string(facets) + " -o s.off").code, 0);
  // The CLI's largest zonotope: 10^10 facets, refused, nothing written.
  o = run("gen zonotope --generators 100000 -o z.off");
  EXPECT_EQ(o.code, 1) << o.err;
  EXPECT_NE(o.err.find("SumLimits::max_memory_bytes"), std::string::npos) << o.err;
  EXPECT_FALSE(fs::exists(file("z.off")));
}

// ---- atomic output, readers' limits, messages ---------------------------------

// `cvms sum x.stl x.stl -o x.stl` fails (beyond float), and `--float` beyond
// double fails too: neither may leave the output file at 0 bytes.
TEST_F(Cli, FailedWriteLeavesTheOldFileByteIdentical) {
  // A box whose corner is at 2^127 * 1.5: in float range, its double is not.
  write_text("x.off", "OFF\n4 4 0\n0 0 0\n" + std::string("255211775190703847597530955573826158592") +
                          " 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  ASSERT_EQ(run("sum x.off x.off -o x.stl").code, 1);  // 2 * 2^127 * 1.5 is beyond float
  ASSERT_EQ(run("gen cube -o x.stl").code, 0);
  const std::string before = slurp(file("x.stl"));
  expect_bad_input("sum x.off x.off -o x.stl", "x.stl: coordinate");
  EXPECT_EQ(slurp(file("x.stl")), before);
  // Beyond double with --float.
  std::string huge = "1" + std::string(400, '0');
  write_text("huge.off", "OFF\n4 4 0\n0 0 0\n" + huge + " 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  ASSERT_EQ(run("gen cube -o mine.off").code, 0);
  const std::string mine = slurp(file("mine.off"));
  expect_bad_input("sum mine.off huge.off --float -o mine.off", "mine.off: ");
  EXPECT_EQ(slurp(file("mine.off")), mine);
  // No temporary is left behind.
  for (const auto& entry : fs::directory_iterator(dir_))
    EXPECT_EQ(entry.path().filename().string().find(".cvms-"), std::string::npos) << entry.path();
}

// PLY: exact ASCII by default, binary doubles with --float, both read back
// as the shape written; a coordinate without a finite decimal is refused
// with the file left as it was.
TEST_F(Cli, PlyWritesExactOrDoublesAndRefusesNonDecimals) {
  ASSERT_EQ(run("gen cube -o cube.ply").code, 0);
  EXPECT_EQ(slurp(file("cube.ply")).substr(0, 21), "ply\nformat ascii 1.0\n");
  ASSERT_EQ(run("gen cube --float -o cube_double.ply").code, 0);
  EXPECT_EQ(slurp(file("cube_double.ply")).substr(0, 36), "ply\nformat binary_little_endian 1.0\n");
  ASSERT_EQ(run("gen cube -o cube.off").code, 0);
  const test::SetShape cube = test::describe_set(read_convex_set(file("cube.off")));
  for (const std::string name : {"cube.ply", "cube_double.ply"}) {
    EXPECT_EQ(test::describe_set(read_convex_set(file(name))), cube) << name;
    const Outcome check = run("check " + name);
    EXPECT_EQ(check.code, 0) << check.err;
    EXPECT_NE(check.out.find("V 8 E 12 F 6"), std::string::npos) << check.out;
  }
  // Points on stdin are told PLY by their first byte, binary ones too.
  const Outcome from_stdin = run("hull - -o back.off", "cube_double.ply");
  EXPECT_EQ(from_stdin.code, 0) << from_stdin.err;
  EXPECT_EQ(test::describe_set(read_convex_set(file("back.off"))), cube);
  const Outcome on_stdout = run("gen cube --format ply");
  EXPECT_EQ(on_stdout.out, slurp(file("cube.ply")));
  write_text("third.off", "OFF\n4 4 0\n1/3 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  const std::string before = slurp(file("cube.ply"));
  expect_bad_input("hull third.off -o cube.ply", "cube.ply: vertex 3 has coordinate 1/3, which has no finite decimal");
  EXPECT_EQ(slurp(file("cube.ply")), before);
  EXPECT_EQ(run("hull third.off --float -o third.ply").code, 0);
  write_text("lying.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000000\n"
                          "property float x\nproperty float y\nproperty float z\nend_header\n");
  expect_bad_input("check lying.ply", "lying.ply:3: 1000000000000 vertices exceed the limit");
}

// -o /dev/null needs no extension; --format names the format.
TEST_F(Cli, OutputFormatFromFormatOptionOrDevice) {
  EXPECT_EQ(run("gen cube -o /dev/null").code, 0);
  Outcome to_stdout = run("gen cube -o /dev/stdout");
  EXPECT_EQ(to_stdout.code, 0) << to_stdout.err;
  EXPECT_EQ(to_stdout.out.substr(0, 4), "OFF\n");
  ASSERT_EQ(run("gen cube -o plain --format obj").code, 0);
  EXPECT_EQ(slurp(file("plain")).substr(0, 2), "v ");
  Outcome stl = run("gen cube --format stl");
  EXPECT_EQ(stl.out.size(), 84u + 12 * 50);
  expect_usage("gen cube -o plain");
  expect_usage("gen cube -o x.off --format vrml");
}

// A failed write to stdout or /dev/full names the file and the reason.
TEST_F(Cli, FailedWritesNameTheFileAndTheReason) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  expect_bad_input("gen cube -o /dev/full", "cannot write '/dev/full': No space left on device");
#ifdef CVMS_CLI_PATH
  // run() redirects stdout itself: this one needs stdout on /dev/full.
  const std::string command =
      "'" CVMS_CLI_PATH "' gen cube > /dev/full 2> '" + path("full.txt") + "'";
  const int status = std::system(command.c_str());
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 1) << status;
  EXPECT_EQ(slurp(file("full.txt")), "cvms: io: cannot write standard output: No space left on device\n");
#endif
  fs::create_directory(file("d.off"));
  expect_bad_input("gen cube -o d.off", "cannot write 'd.off': it is a directory");
}

// Every command that writes to stdout (results, reports, help) exits 1 with
// an io error when its output is lost, never 0 with the output gone.
TEST_F(Cli, LostOutputOnStdoutIsAnErrorForEveryCommand) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  ASSERT_EQ(run("gen cube -o c.off").code, 0);
  ASSERT_EQ(run("gen octahedron -o o.off").code, 0);
  write_text("points.xyz", "0 0 0\n1 0 0\n0 1 0\n0 0 1\n");
  write_text("rows.ine", "H-representation\nbegin\n4 4 integer\n0 1 0 0\n0 0 1 0\n0 0 0 1\n1 -1 -1 -1\nend\n");
  const std::vector<std::string> commands = {
      "gen cube",
      "gen zonotope",
      "demo",
      "check c.off",
      "distance c.off o.off",
      "penetration c.off o.off",
      "sum c.off o.off",
      "sum c.off o.off c.off",
      "sum c.off o.off -o s.off --stats",
      "hull points.xyz",
      "hull --from-halfspaces rows.ine",
      "diff c.off o.off",
      "diff c.off o.off -o d.off",
      "halfspaces c.off",
      "--help",
  };
#ifdef CVMS_CLI_PATH
  for (const std::string& args : commands) {
    SCOPED_TRACE("cvms " + args);
    const std::string command = "cd '" + dir_.string() + "' && '" CVMS_CLI_PATH "' " + args +
                                " > /dev/full 2> '" + path("full.txt") + "'";
    const int status = std::system(command.c_str());
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 1) << status;
    const std::string err = slurp(file("full.txt"));
    EXPECT_EQ(err, "cvms: io: cannot write standard output: No space left on device\n");
  }
#else
  (void)commands;
#endif
}

// `hull DIR` names the directory, not "read error after 0 bytes"; an
// unreadable stdin is named as such, not "empty input".
TEST_F(Cli, DirectoriesAndUnreadableStdinAreNamed) {
  fs::create_directory(file("d.xyz"));
  expect_bad_input("hull d.xyz", "cannot read 'd.xyz': it is a directory");
  expect_bad_input("check d.xyz.off", "d.xyz.off");
  expect_bad_input("check - < /", "cannot read standard input: it is a directory");
  expect_bad_input("check - <&-", "cannot read standard input: Bad file descriptor");
  expect_bad_input("hull - 0>/dev/null", "cannot read standard input: it is open for writing only");
}

// /dev/zero as input ends at once; --max-bytes and --max-line-bytes
// lower the readers' limits (before or after the command name).
TEST_F(Cli, DevZeroAndTheReadLimitOptions) {
  expect_bad_input("hull /dev/zero", "/dev/zero:1: a NUL byte at byte 0");
  ASSERT_EQ(run("gen sphere --subdivisions 2 -o s.off").code, 0);
  expect_bad_input("--max-bytes 100 check s.off", "input is larger than the limit of 100 bytes");
  expect_bad_input("check s.off --max-bytes 100", "input is larger than the limit of 100 bytes");
  expect_bad_input("check s.off --max-line-bytes 8", "s.off:3: line longer than the limit of 8 bytes");
  EXPECT_EQ(run("check s.off --max-bytes 1000000").code, 0);
  expect_usage("check s.off --max-bytes -1");
  expect_usage("check s.off --max-bytes 1e6");
}

// gen prism --points 1000001 is a usage error (caught in the CLI's range,
// not later as exit 1); --seed beyond 2^64-1 or negative is refused.
TEST_F(Cli, GenCountsAndSeedsOutOfRangeAreUsageErrors) {
  expect_usage("gen prism --points 1000001");
  expect_usage("gen random --points 10000001");
  expect_usage("gen random --seed -1");
  expect_usage("gen random --seed 18446744073709551616");
  expect_usage("gen random --seed 1e3");
  Outcome max_seed = run("gen random --seed 18446744073709551615 --points 5 -o r.off");
  EXPECT_EQ(max_seed.code, 0) << max_seed.err;
  EXPECT_EQ(test::describe(load("r.off")),
            test::describe(shapes::random_hull(std::numeric_limits<std::uint64_t>::max(), 5)));
}

// File names with terminal escape codes are escaped, never printed raw.
TEST_F(Cli, ControlCharactersInFileNamesAreEscaped) {
  Outcome o = run("check \"$(printf 'evil\\033[2J.off')\"");
  EXPECT_EQ(o.code, 1) << o.err;
  EXPECT_EQ(o.err.find('\x1b'), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("evil\\x1b[2J.off"), std::string::npos) << o.err;
  // Also in usage errors (a wrong extension, reported by the parser).
  Outcome usage = run("check \"$(printf 'evil\\033[2J.txt')\"");
  EXPECT_EQ(usage.code, 2) << usage.err;
  EXPECT_EQ(usage.err.find('\x1b'), std::string::npos) << usage.err;
  EXPECT_NE(usage.err.find("evil\\x1b[2J.txt"), std::string::npos) << usage.err;
  ASSERT_EQ(run("gen cube -o \"$(printf 'new\\nline.off')\"").code, 0);
  Outcome check = run("check \"$(printf 'new\\nline.off')\"");
  EXPECT_EQ(check.code, 0) << check.err;
  EXPECT_NE(check.out.find("new\\x0aline.off: convex polyhedron"), std::string::npos) << check.out;
}

}  // namespace
}  // namespace cvms
