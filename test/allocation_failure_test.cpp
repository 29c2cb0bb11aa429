// SPDX-License-Identifier: MIT
// Out of memory at every allocation: each public operation (read, validate,
// sum of two, sum of many, sum of unions, decomposition, hull, half-spaces,
// difference, distance, penetration, write) run with its 1st, 2nd, 3rd ...
// call of operator new failing, until a run completes without reaching the
// failure (support/allocation_sweep.hpp). Every failing run must end in a
// cvms::Error or std::bad_alloc with the operands unchanged, and the
// complete run must give the result of a run made before the sweep. Under
// the asan preset, LeakSanitizer reports any block a failing run leaves
// behind, at the end of the test's process.
//
// The operations run with Options::threads = 1, so that the k-th call is
// the same call in every run; the sum of unions runs on two threads too,
// where the order of the calls varies between runs but every run must
// still end in a typed error or the reference result. The inputs are
// small, so that every sweep takes a few seconds under AddressSanitizer;
// allocation_failure_soak_test.cpp runs larger ones, label soak.
//
// GMP's own allocations are not failed (failing_allocator.hpp says why).
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <istream>
#include <memory>
#include <new>
#include <sstream>
#include <string>
#include <vector>

#include "cvms/cvms.hpp"
#include "support/allocation_sweep.hpp"
#include "support/hand_solids.hpp"
#include "support/io_expect.hpp"

namespace cvms::test {
namespace {

// Each test ends with a leak check (a no-op without AddressSanitizer).
class AllocationFailure : public ::testing::Test {
 protected:
  void TearDown() override {
    EXPECT_FALSE(unreachable_blocks()) << "LeakSanitizer found blocks left behind (above)";
  }
};

ConvexPolyhedron polyhedron_of(const PolygonSoup& soup) { return ConvexPolyhedron::from_soup(soup); }

Vec3 q3(long x, long y, long z, long d) { return {Rational(x, d), Rational(y, d), Rational(z, d)}; }

// A box with rational corners, and a tetrahedron with a tilted face: small,
// with non-parallel facets so that the sums have edge-edge facets.
ConvexPolyhedron box() { return polyhedron_of(mapped(cube_quads(2), Mat3::identity(), q3(-1, -1, -1, 2))); }
ConvexPolyhedron tetra() {
  return convex_hull(std::vector<Vec3>{v3(0, 0, 0), v3(2, 0, 0), v3(0, 3, 0), q3(1, 1, 5, 2)});
}
ConvexPolyhedron octa() { return polyhedron_of(octahedron()); }

PolygonSoup l_block_soup() { return read_file(data_path("solids/l_block.off")); }

// Runs the sweep and prints its summary; the test fails on any finding.
template <class Run>
void expect_sweep(std::string_view name, Run run, const std::function<std::string()>& operands,
                  SweepOptions options = {}) {
  const SweepReport report = sweep_allocation_failures(name, run, operands, options);
  std::cout << summary(name, report) << '\n';
}

const std::function<std::string()> no_operands = [] { return std::string(); };

// A run that writes into a string stream (allocating as it grows) and
// returns the text.
template <class Write>
auto written(Write write) {
  return [write] {
    std::ostringstream out;
    write(out);
    return out.str();
  };
}

// A run that reads `text` (which outlives it) through a stream that takes
// no allocation of its own.
template <class Read>
auto read_from_text(const std::string& text, Read read) {
  return [&text, read] {
    TextBuffer buffer(text);
    std::istream in(&buffer);
    return read(in);
  };
}

// Where the allocations of EveryFormOfOperatorNewFails go: a volatile
// store keeps the compiler from pairing a new with its delete and removing
// both.
void* volatile kept_block = nullptr;

template <class T>
void keep_and_delete(T* block) {
  kept_block = block;
  delete static_cast<T*>(kept_block);
}

template <class T>
void keep_and_delete_array(T* block) {
  kept_block = block;
  delete[] static_cast<T*>(kept_block);
}

struct alignas(64) CacheLine {
  char bytes[64];
};

// The replaced operator new fails in each of its forms, and only the
// armed k-th call (or every call from the k-th on, persistent).
TEST_F(AllocationFailure, EveryFormOfOperatorNewFails) {
  const auto fails = [](auto allocate) {
    const FailingAllocations failing(1);
    try {
      allocate();
    } catch (const std::bad_alloc&) {
      return FailingAllocations::failures() == 1;
    }
    return false;
  };
  EXPECT_TRUE(fails([] { keep_and_delete(new int(1)); }));
  EXPECT_TRUE(fails([] { keep_and_delete_array(new int[3]); }));
  EXPECT_TRUE(fails([] { keep_and_delete(new CacheLine); }));
  EXPECT_TRUE(fails([] { keep_and_delete_array(new CacheLine[2]); }));
  EXPECT_TRUE(fails([] { kept_block = std::make_unique<std::vector<int>>(5).get(); }));
  {
    const FailingAllocations failing(2);
    int* first = new (std::nothrow) int(1);
    kept_block = first;
    int* second = new (std::nothrow) int(2);
    kept_block = second;
    CacheLine* aligned = new (std::nothrow) CacheLine;
    kept_block = aligned;
    EXPECT_NE(first, nullptr);
    EXPECT_EQ(second, nullptr);
    EXPECT_NE(aligned, nullptr);
    EXPECT_EQ(FailingAllocations::calls(), 3u);
    delete first;
    delete aligned;
  }
  {
    const FailingAllocations failing(1, /*persistent=*/true);
    int* ints = new (std::nothrow) int[2];
    kept_block = ints;
    CacheLine* lines = new (std::nothrow) CacheLine[2];
    kept_block = lines;
    EXPECT_EQ(ints, nullptr);
    EXPECT_EQ(lines, nullptr);
    EXPECT_EQ(FailingAllocations::failures(), 2u);
  }
  const std::uint64_t before = total_allocations();
  keep_and_delete(new int(3));  // disarmed
  EXPECT_EQ(total_allocations(), before + 1);
}

// Where the library maps large blocks itself (optimised builds on Linux),
// the sweep's hook sees them: so its check that none was mapped during a
// sweep means that the sweep could fail every block.
TEST_F(AllocationFailure, TheSweepSeesBlocksThatBypassOperatorNew) {
#if defined(CVMS_TEST_BLOCKS_MAPPED)
  const std::vector<Vec3> points = shapes::random_points(1, 20000, 1 << 20);
  std::uint64_t mapped = 0;
  {
    const FailingAllocations never(std::uint64_t{1} << 62);
    (void)convex_hull(points);
    mapped = FailingAllocations::mapped_blocks();
  }
  EXPECT_GT(mapped, 0u);
#else
  GTEST_SKIP() << "this build takes every block from operator new";
#endif
}

// --- read --------------------------------------------------------------------

TEST_F(AllocationFailure, ReadEachFormatFromMemory) {
  const PolygonSoup cube = box().to_soup();
  for (const FileFormat format : {FileFormat::off, FileFormat::obj, FileFormat::ply, FileFormat::stl}) {
    std::ostringstream out;
    write(out, cube, format, format == FileFormat::stl ? Coordinates::double_ : Coordinates::exact);
    const std::string text = out.str();
    expect_sweep(std::string("read ") + std::to_string(static_cast<int>(format)),
                 read_from_text(text, [&](std::istream& in) { return read(in, format, "cube"); }),
                 no_operands);
  }
}

TEST_F(AllocationFailure, ReadFiles) {
  expect_sweep(
      "read_file off", [] { return read_file(data_path("cube.off")); }, no_operands);
  expect_sweep(
      "read_file obj", [] { return read_file(data_path("cube.obj")); }, no_operands);
  expect_sweep(
      "read_file stl", [] { return read_file(data_path("tetra_ascii.stl")); }, no_operands);
  expect_sweep(
      "read_polyhedron", [] { return read_polyhedron(data_path("tetra_exact.off")); }, no_operands);
  expect_sweep(
      "read_convex_set", [] { return read_convex_set(data_path("cube.off")); }, no_operands);
  expect_sweep(
      "read_solid", [] { return read_solid(data_path("solids/l_block.off")); }, no_operands);
}

TEST_F(AllocationFailure, ReadPointsAndRows) {
  const ConvexSet set = tetra();
  std::ostringstream cdd_rows, plain_rows, cdd_points, plain_points;
  write_halfspaces(cdd_rows, to_halfspaces(set), HalfspaceFormat::cdd);
  write_halfspaces(plain_rows, to_halfspaces(set), HalfspaceFormat::plain);
  write_cdd_points(cdd_points, set);
  write_plain_points(plain_points, set);
  const std::string xyz = file_bytes(data_path("points.xyz"));
  const auto sweep_text = [](std::string_view name, const std::string& text, auto read_from) {
    expect_sweep(name, read_from_text(text, read_from), no_operands);
  };
  sweep_text("read_halfspaces cdd", cdd_rows.str(),
             [](std::istream& in) { return read_halfspaces(in, HalfspaceFormat::cdd); });
  sweep_text("read_halfspaces plain", plain_rows.str(),
             [](std::istream& in) { return read_halfspaces_of_any_dimension(in, HalfspaceFormat::plain); });
  sweep_text("read_cdd_points", cdd_points.str(), [](std::istream& in) { return read_cdd_points(in); });
  sweep_text("read_plain_points", plain_points.str(), [](std::istream& in) { return read_plain_points(in); });
  sweep_text("read_points", xyz, [](std::istream& in) { return read_points(in, "points.xyz"); });

  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "cvms_allocation_failure_read";
  std::filesystem::create_directories(dir);
  write_halfspace_file(dir / "rows.ine", to_halfspaces(set));
  write_pieces(dir / "two.pieces",
               ConvexUnion(std::vector<ConvexPolyhedron>{box(), tetra().translated(v3(3, 0, 0))}));
  expect_sweep(
      "read_halfspace_file", [&] { return read_halfspace_file(dir / "rows.ine"); }, no_operands);
  expect_sweep(
      "read_pieces of a file", [&] { return read_pieces(dir / "two.pieces"); }, no_operands);
  std::filesystem::remove_all(dir);
}

TEST_F(AllocationFailure, ReadPieces) {
  const ConvexUnion pieces(std::vector<ConvexPolyhedron>{box(), tetra().translated(v3(3, 0, 0))});
  std::ostringstream out;
  write_pieces(out, pieces);
  const std::string text = out.str();
  expect_sweep("read_pieces",
               read_from_text(text, [&](std::istream& in) { return read_pieces(in, "pieces"); }),
               no_operands);
}

// --- validate ----------------------------------------------------------------

TEST_F(AllocationFailure, Validate) {
  const PolygonSoup cube = cube_triangles();
  const PolygonSoup l_block = l_block_soup();
  const PolygonSoup square = make_soup({v3(0, 0, 0), v3(1, 0, 0), v3(1, 1, 0), v3(0, 1, 0)}, {{0, 1, 2, 3}});
  const auto soup_of = [](const PolygonSoup& soup) { return [&soup] { return fingerprint(soup); }; };
  expect_sweep(
      "ConvexPolyhedron::from_soup", [&] { return ConvexPolyhedron::from_soup(cube); }, soup_of(cube));
  expect_sweep(
      "to_polyhedron", [&] { return to_polyhedron(cube, "cube"); }, soup_of(cube));
  expect_sweep(
      "convex_set_from_soup", [&] { return convex_set_from_soup(square); }, soup_of(square));
  expect_sweep(
      "Solid::from_soup", [&] { return Solid::from_soup(l_block); }, soup_of(l_block));
}

// --- sums --------------------------------------------------------------------

TEST_F(AllocationFailure, SumOfTwoWithEachAlgorithm) {
  const ConvexPolyhedron a = tetra();
  const ConvexPolyhedron b = box();
  const auto operands = [&] { return fingerprint(a) + fingerprint(b); };
  for (const Algorithm algorithm : {Algorithm::cvms, Algorithm::essdms, Algorithm::chms}) {
    Options options;
    options.algorithm = algorithm;
    options.threads = 1;
    expect_sweep(
        std::string("minkowski_sum ") + to_string(algorithm),
        [&] { return minkowski_sum(a, b, options).polyhedron; }, operands);
  }
  expect_sweep(
      "chms", [&] { return chms(a, b); }, operands);
}

TEST_F(AllocationFailure, SumOfTwoSetsOfLowerDimension) {
  const ConvexSet segment = ConvexSet::segment(v3(0, 0, 0), v3(1, 2, 3));
  const std::array<Vec3, 3> triangle{v3(0, 0, 0), v3(2, 0, 0), v3(0, 2, 0)};
  const ConvexSet polygon = ConvexSet::polygon(triangle);
  expect_sweep(
      "minkowski_sum segment + polygon", [&] { return minkowski_sum(segment, polygon); },
      [&] { return fingerprint(segment) + fingerprint(polygon); });
}

TEST_F(AllocationFailure, SumOfMany) {
  const std::array<Vec3, 3> triangle{v3(0, 0, 0), v3(2, 0, 0), v3(0, 2, 1)};
  const std::vector<ConvexSet> operands{ConvexSet::segment(v3(0, 0, 0), v3(1, 2, 3)),
                                        ConvexSet::polygon(triangle), ConvexSet(tetra()),
                                        ConvexSet::point(v3(5, 5, 5))};
  const auto fingerprints = [&] {
    std::string text;
    for (const ConvexSet& s : operands) text += fingerprint(s);
    return text;
  };
  expect_sweep(
      "n-ary minkowski_sum", [&] { return minkowski_sum(std::span<const ConvexSet>(operands)); },
      fingerprints);
  const std::vector<Vec3> generators{v3(1, 0, 0), v3(0, 1, 0), v3(0, 0, 1), v3(1, 1, 1)};
  expect_sweep(
      "zonotope", [&] { return zonotope(v3(0, 0, 0), generators); }, [&] { return fingerprint(generators); });
}

ConvexUnion two_pieces(const Vec3& offset) {
  return ConvexUnion(
      std::vector<ConvexPolyhedron>{box().translated(offset), tetra().translated(offset + v3(2, 0, 0))});
}

TEST_F(AllocationFailure, SumOfUnionsOnOneAndTwoThreads) {
  // On two threads, which call is the k-th differs between runs, so the
  // sweep ends near (not at) the number of calls of a whole run; each run
  // must still end in a typed error, or the reference result, with no leak.
  const ConvexUnion a = two_pieces(v3(0, 0, 0));
  const ConvexUnion b(std::vector<ConvexPolyhedron>{octa(), tetra().translated(v3(0, 0, 4))});
  for (const unsigned threads : {1u, 2u}) {
    Options options;
    options.threads = threads;
    expect_sweep(
        "minkowski_sum of unions, threads " + std::to_string(threads),
        [&] { return minkowski_sum(a, b, options); }, [&] { return fingerprint(a) + fingerprint(b); });
  }
}

TEST_F(AllocationFailure, ConvexDecomposition) {
  const Solid l_block = Solid::from_soup(l_block_soup());
  expect_sweep(
      "convex_decomposition", [&] { return convex_decomposition(l_block); },
      [&] { return fingerprint(l_block); });
}

TEST_F(AllocationFailure, SumOfPieces) {
  const Solid l_block = Solid::from_soup(l_block_soup());
  const Solid small = Solid::from_polyhedron(tetra());
  Options options;
  options.threads = 1;
  expect_sweep(
      "minkowski_sum_pieces", [&] { return minkowski_sum_pieces(l_block, small, options); },
      [&] { return fingerprint(l_block) + fingerprint(small); });
}

TEST_F(AllocationFailure, SumOfSolidsAsOneSolid) {
  const Solid l_block = Solid::from_soup(l_block_soup());
  const Solid small = Solid::from_polyhedron(tetra());
  Options options;
  options.threads = 1;
  // One convex operand: the faces' sums, their fragments and the assembly.
  expect_sweep(
      "minkowski_sum(Solid, convex Solid)", [&] { return minkowski_sum(l_block, small, options); },
      [&] { return fingerprint(l_block) + fingerprint(small); });
  // Neither convex (both decomposed, then the union of the pieces' sums):
  // the soak sweeps it.
}

TEST_F(AllocationFailure, UnionAsOneSolid) {
  const ConvexUnion pieces(std::vector<ConvexPolyhedron>{box(), tetra(), octa()});
  Options options;
  options.threads = 1;
  expect_sweep(
      "union_solid", [&] { return union_solid(pieces, options); }, [&] { return fingerprint(pieces); });
}

// --- hull and half-spaces -----------------------------------------------------

TEST_F(AllocationFailure, Hull) {
  std::vector<Vec3> points;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 2; ++k) points.push_back(v3(i * i - j, 2 * j + k, k * 3 - i));
  const std::vector<std::array<double, 3>> doubles{
      {0, 0, 0}, {1.5, 0, 0}, {0, 0.25, 0}, {0, 0, 3}, {0.1, 0.1, 0.1}};
  const std::vector<Vec3> coplanar{v3(0, 0, 1), v3(4, 0, 1), v3(0, 4, 1), v3(1, 1, 1), v3(4, 4, 1)};
  const auto operands = [&] { return fingerprint(points); };
  expect_sweep(
      "convex_hull", [&] { return convex_hull(points); }, operands);
  expect_sweep(
      "convex_hull of doubles", [&] { return convex_hull(std::span<const std::array<double, 3>>(doubles)); },
      no_operands);
  expect_sweep(
      "convex_hull_set", [&] { return convex_hull_set(coplanar); }, [&] { return fingerprint(coplanar); });
}

std::vector<HalfspaceRow> box_rows() {
  std::vector<HalfspaceRow> rows;
  for (int axis = 0; axis < 3; ++axis)
    for (const long sign : {1L, -1L}) {
      Vec3 n{Rational(0), Rational(0), Rational(0)};
      (axis == 0 ? n.x : axis == 1 ? n.y : n.z) = Rational(sign);
      rows.push_back({n, Rational(axis + 1)});
    }
  rows.push_back({v3(1, 1, 1), Rational(4)});    // cuts a corner
  rows.push_back({v3(1, 1, 0), Rational(100)});  // redundant
  return rows;
}

TEST_F(AllocationFailure, FromHalfspaces) {
  const std::vector<HalfspaceRow> rows = box_rows();
  const std::vector<HalfspaceRow> unbounded(rows.begin(), rows.begin() + 5);
  HalfspaceSystem with_equality;
  with_equality.inequalities = rows;
  with_equality.equalities.push_back({v3(0, 0, 1), Rational(1, 2)});
  expect_sweep(
      "from_halfspaces", [&] { return from_halfspaces(rows); }, [&] { return fingerprint(rows); });
  expect_sweep(
      "intersect_halfspaces, unbounded", [&] { return intersect_halfspaces(unbounded); },
      [&] { return fingerprint(unbounded); });
  expect_sweep(
      "from_halfspaces with an equality", [&] { return from_halfspaces(with_equality); },
      [&] { return fingerprint(with_equality); });
  const ConvexSet set = box();
  expect_sweep(
      "to_halfspaces", [&] { return to_halfspaces(set); }, [&] { return fingerprint(set); });
}

TEST_F(AllocationFailure, Difference) {
  const ConvexSet big = ConvexSet(polyhedron_of(cube_quads(4)));
  const ConvexSet b = tetra();
  const auto operands = [&] { return fingerprint(big) + fingerprint(b); };
  expect_sweep(
      "pontryagin_difference", [&] { return pontryagin_difference(big, b); }, operands);
  Options options;
  options.threads = 1;
  expect_sweep(
      "minkowski_difference", [&] { return minkowski_difference(big, b, options); }, operands);
}

// --- proximity ------------------------------------------------------------------

TEST_F(AllocationFailure, Distance) {
  const ConvexPolyhedron a = box();
  const ConvexPolyhedron b = tetra().translated(v3(3, 1, 0));
  const auto operands = [&] { return fingerprint(a) + fingerprint(b); };
  expect_sweep(
      "squared_distance", [&] { return squared_distance(a, b); }, operands);
  Placement placement;
  placement.translation = {3.5, 0.25, -1.0};
  expect_sweep(
      "squared_distance, placed",
      [&] { return squared_distance(PlacedPolyhedron(a), PlacedPolyhedron(tetra(), placement)); }, operands);
  const ConvexSet segment = ConvexSet::segment(v3(5, 5, 5), v3(6, 7, 5));
  expect_sweep(
      "squared_distance of sets", [&] { return squared_distance(ConvexSet(a), segment); },
      [&] { return fingerprint(a) + fingerprint(segment); });
  expect_sweep(
      "intersects", [&] { return intersects(a, b); }, operands);
}

TEST_F(AllocationFailure, Penetration) {
  const ConvexPolyhedron a = box();
  const ConvexPolyhedron b = tetra().translated(q3(-1, -1, -1, 4));
  expect_sweep(
      "penetration", [&] { return penetration(a, b); }, [&] { return fingerprint(a) + fingerprint(b); });
  const ConvexSet segment = ConvexSet::segment(v3(-2, 0, 0), v3(2, 0, 0));
  expect_sweep(
      "penetration of sets", [&] { return penetration(ConvexSet(a), segment); },
      [&] { return fingerprint(a) + fingerprint(segment); });
}

// --- write -------------------------------------------------------------------------

TEST_F(AllocationFailure, WriteEachFormatToMemory) {
  const ConvexPolyhedron p = tetra();
  const auto operands = [&] { return fingerprint(p); };
  for (const FileFormat format : {FileFormat::off, FileFormat::obj, FileFormat::ply, FileFormat::stl})
    for (const Coordinates coordinates :
         {Coordinates::exact, Coordinates::double_, Coordinates::double_outer}) {
      // STL holds float32: exact and outer coordinates are refused.
      if (format == FileFormat::stl && coordinates != Coordinates::double_) continue;
      expect_sweep(
          "write " + std::to_string(static_cast<int>(format)) + " " +
              std::to_string(static_cast<int>(coordinates)),
          written([&](std::ostream& out) { write(out, p, format, coordinates, VertexOrder::canonical); }),
          operands);
    }
}

TEST_F(AllocationFailure, WriteSoupsInEachFormat) {
  // A soup need not be convex: the L-shaped block, written as it is.
  const PolygonSoup l_block = l_block_soup();
  for (const FileFormat format : {FileFormat::off, FileFormat::obj, FileFormat::ply, FileFormat::stl})
    expect_sweep("write soup " + std::to_string(static_cast<int>(format)), written([&](std::ostream& out) {
                   write(out, l_block, format,
                         format == FileFormat::stl ? Coordinates::double_ : Coordinates::exact);
                 }),
                 [&] { return fingerprint(l_block); });
}

TEST_F(AllocationFailure, WriteSetsRowsAndPieces) {
  const ConvexSet set = ConvexSet::polygon(std::array<Vec3, 3>{v3(0, 0, 0), v3(2, 0, 0), v3(0, 2, 1)});
  const ConvexSet solid = box();
  const ConvexUnion pieces = two_pieces(v3(1, 1, 1));
  expect_sweep("write set", written([&](std::ostream& out) { write(out, set, FileFormat::off, "triangle"); }),
               [&] { return fingerprint(set); });
  expect_sweep("write_halfspaces", written([&](std::ostream& out) {
                 write_halfspaces(out, to_halfspaces(solid), HalfspaceFormat::cdd);
               }),
               [&] { return fingerprint(solid); });
  expect_sweep("write_cdd_points", written([&](std::ostream& out) { write_cdd_points(out, solid); }),
               [&] { return fingerprint(solid); });
  expect_sweep("write_plain_points", written([&](std::ostream& out) { write_plain_points(out, solid); }),
               [&] { return fingerprint(solid); });
  expect_sweep("write_pieces", written([&](std::ostream& out) { write_pieces(out, pieces); }),
               [&] { return fingerprint(pieces); });
}

TEST_F(AllocationFailure, WriteFileKeepsTheExistingFile) {
  // A failed write leaves the file that was there, or the whole new one,
  // and no other file.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "cvms_allocation_failure_write";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::filesystem::path path = dir / "out.off";
  const std::string before = "the file before\n";
  const ConvexPolyhedron p = tetra();
  write_file(path, p);
  const std::string written = file_bytes(path);
  // Called after every run: checks the file, then puts the old one back.
  const auto operands = [&] {
    std::string text = fingerprint(p);
    for (const auto& entry : std::filesystem::directory_iterator(dir))
      text += entry.path().filename().string() + '\n';
    const std::string bytes = file_bytes(path);
    text += bytes == before || bytes == written ? "old or new file\n" : "a broken file:\n" + bytes;
    std::ofstream(path, std::ios::binary | std::ios::trunc) << before;
    return text;
  };
  expect_sweep(
      "write_file",
      [&] {
        write_file(path, p);
        return file_bytes(path);
      },
      operands);
  std::filesystem::remove_all(dir);
}

// --- memory that stays exhausted -------------------------------------------------

TEST_F(AllocationFailure, PersistentFailureOnTheLongerPaths) {
  // Every call from the k-th on fails, so that the code that unwinds (error
  // messages, the union's worker collecting a pair's exception, the writer
  // removing its temporary file) meets failures too.
  SweepOptions persistent;
  persistent.persistent = true;
  const ConvexPolyhedron a = tetra();
  const ConvexPolyhedron b = box();
  const auto operands = [&] { return fingerprint(a) + fingerprint(b); };
  expect_sweep(
      "minkowski_sum, persistent", [&] { return minkowski_sum(a, b).polyhedron; }, operands, persistent);
  const ConvexUnion u = two_pieces(v3(0, 0, 0));
  Options two_threads;
  two_threads.threads = 2;
  expect_sweep(
      "minkowski_sum of unions, 2 threads, persistent", [&] { return minkowski_sum(u, u, two_threads); },
      [&] { return fingerprint(u); }, persistent);
  const std::vector<HalfspaceRow> rows = box_rows();
  expect_sweep(
      "from_halfspaces, persistent", [&] { return from_halfspaces(rows); }, [&] { return fingerprint(rows); },
      persistent);
  expect_sweep(
      "read_solid, persistent", [] { return read_solid(data_path("solids/l_block.off")); }, no_operands,
      persistent);
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "cvms_allocation_failure_persistent";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::filesystem::path path = dir / "out.obj";
  write_file(path, a);
  const std::string whole = file_bytes(path);
  std::filesystem::remove(path);
  // Called after every run: no file but the whole one, which it removes.
  const auto left_behind = [&] {
    std::string text;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
      if (entry.path() != path || file_bytes(path) != whole) text += entry.path().filename().string() + '\n';
    std::filesystem::remove(path);
    return text;
  };
  expect_sweep(
      "write_file, persistent",
      [&] {
        write_file(path, a);
        return file_bytes(path);
      },
      left_behind, persistent);
  std::filesystem::remove_all(dir);
}

// --- queries that build a cache on first use -----------------------------------------

TEST_F(AllocationFailure, FirstQueriesBuildTheirCacheOnce) {
  // Solid::locate and ConvexUnion::contains build a hierarchy of boxes on
  // their first call: a call that fails while building it must leave an
  // object whose next call builds it again and answers right.
  const Solid reference_solid = Solid::from_soup(l_block_soup());
  const Vec3 point = q3(3, 3, 1, 2);
  SweepOptions options;
  options.reference = fingerprint(reference_solid.locate(point) == Location::inside);
  const Solid solid = Solid::from_soup(l_block_soup());
  expect_sweep(
      "Solid::locate, first call", [&] { return solid.locate(point) == Location::inside; },
      [&] { return fingerprint(solid); }, options);

  const ConvexUnion reference_union = two_pieces(v3(0, 0, 0));
  options.reference = fingerprint(reference_union.contains(point));
  const ConvexUnion u = two_pieces(v3(0, 0, 0));
  expect_sweep(
      "ConvexUnion::contains, first call", [&] { return u.contains(point); }, [&] { return fingerprint(u); },
      options);
}

}  // namespace
}  // namespace cvms::test
