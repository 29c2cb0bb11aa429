// SPDX-License-Identifier: MIT
// Hostile inputs for the readers, measured: headers that lie about counts,
// a 100 MB single line (generated at test time, in a temp file or by a
// stream that makes it up on the fly), megabytes of binary junk. Each must
// end with the documented error (or a correct result) quickly, and the
// memory the reader allocates is measured by counting operator new.
#include <gmp.h>
#include <gtest/gtest.h>
#include <malloc.h>
#include <unistd.h>

#include <atomic>
#include <cfloat>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <new>
#include <random>
#include <sstream>

#include "cvms/convex_hull.hpp"
#include "cvms/convex_polyhedron.hpp"
#include "cvms/io.hpp"
#include "support/cpu_time.hpp"
#include "support/hand_solids.hpp"
#include "support/io_expect.hpp"

// ---- allocation accounting --------------------------------------------------
// Replacing the global operator new is the one way to see what the reader
// allocates from the outside; the counters are process-wide on purpose and
// only read around one call at a time.
namespace {

std::atomic<std::size_t> current_bytes{0};
std::atomic<std::size_t> peak_bytes{0};
constexpr std::size_t header = alignof(std::max_align_t);

void* tracked_alloc(std::size_t n) {
  void* raw = std::malloc(n + header);
  if (raw == nullptr) throw std::bad_alloc();
  *static_cast<std::size_t*>(raw) = n;
  std::size_t now = current_bytes.fetch_add(n) + n;
  std::size_t peak = peak_bytes.load();
  while (now > peak && !peak_bytes.compare_exchange_weak(peak, now)) {
  }
  return static_cast<char*>(raw) + header;
}

void tracked_free(void* p) noexcept {
  if (p == nullptr) return;
  char* raw = static_cast<char*>(p) - header;
  current_bytes.fetch_sub(*reinterpret_cast<std::size_t*>(raw));
  std::free(raw);
}

// GMP allocates its limbs with malloc, past operator new: route it through
// the same counters (sized by malloc_usable_size, as GMP's free does not
// pass a trustworthy size for blocks allocated before this runs).
void* gmp_alloc(std::size_t n) {
  void* p = std::malloc(n);
  if (p == nullptr) std::abort();  // as GMP's own allocator does
  std::size_t now = current_bytes.fetch_add(malloc_usable_size(p)) + malloc_usable_size(p);
  std::size_t peak = peak_bytes.load();
  while (now > peak && !peak_bytes.compare_exchange_weak(peak, now)) {
  }
  return p;
}
void gmp_free(void* p, std::size_t) {
  current_bytes.fetch_sub(malloc_usable_size(p));
  std::free(p);
}
void* gmp_realloc(void* p, std::size_t, std::size_t n) {
  void* q = gmp_alloc(n);
  std::memcpy(q, p, std::min(n, malloc_usable_size(p)));
  gmp_free(p, 0);
  return q;
}
const bool gmp_counted = (mp_set_memory_functions(gmp_alloc, gmp_realloc, gmp_free), true);

}  // namespace

void* operator new(std::size_t n) { return tracked_alloc(n); }
void* operator new[](std::size_t n) { return tracked_alloc(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  try {
    return tracked_alloc(n);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
  try {
    return tracked_alloc(n);
  } catch (...) {
    return nullptr;
  }
}
void operator delete(void* p) noexcept { tracked_free(p); }
void operator delete[](void* p) noexcept { tracked_free(p); }
void operator delete(void* p, std::size_t) noexcept { tracked_free(p); }
void operator delete[](void* p, std::size_t) noexcept { tracked_free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { tracked_free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { tracked_free(p); }

namespace cvms {
namespace {

using test::throws_error;

using test::slow_factor;

constexpr std::size_t MiB = std::size_t{1} << 20;
constexpr std::size_t hundred_mb = 100 * 1000 * 1000;

// Peak bytes allocated through operator new and CPU seconds used while f runs.
struct Cost {
  std::size_t peak = 0;
  double seconds = 0;
};
template <class F>
Cost measure(F&& f) {
  std::size_t base = current_bytes.load();
  peak_bytes.store(base);
  auto start = test::cpu_seconds();
  f();
  const double elapsed = test::cpu_seconds() - start;
  Cost cost{peak_bytes.load() - base, elapsed};
  std::printf("    peak %zu bytes, %.3f s\n", cost.peak, cost.seconds);
  return cost;
}

// A non-seekable stream that makes up prefix + count copies of `fill` + suffix
// without ever holding them: the memory measured is the reader's alone.
class GeneratedBuffer : public std::streambuf {
 public:
  GeneratedBuffer(std::string prefix, char fill, std::size_t count, std::string suffix)
      : prefix_(std::move(prefix)), suffix_(std::move(suffix)), count_(count), block_(1 << 16, fill) {}

 protected:
  int_type underflow() override {
    if (stage_ == 0) {
      stage_ = 1;
      if (!prefix_.empty()) return serve(prefix_.data(), prefix_.size());
    }
    if (stage_ == 1) {
      if (count_ > 0) {
        std::size_t n = std::min(count_, block_.size());
        count_ -= n;
        return serve(block_.data(), n);
      }
      stage_ = 2;
      if (!suffix_.empty()) return serve(suffix_.data(), suffix_.size());
    }
    return traits_type::eof();
  }

 private:
  int_type serve(char* data, std::size_t n) {
    setg(data, data, data + n);
    return traits_type::to_int_type(*data);
  }
  std::string prefix_, suffix_;
  std::size_t count_;
  std::string block_;
  int stage_ = 0;
};

// A file of prefix + count copies of fill + suffix in the temp directory, removed afterwards.
struct GeneratedFile {
  std::filesystem::path path;
  GeneratedFile(const std::string& name, const std::string& prefix, char fill, std::size_t count,
                const std::string& suffix) {
    path = std::filesystem::temp_directory_path() /
           ("cvms_io_hostile_" + std::to_string(::getpid()) + "_" + name);
    std::ofstream out(path, std::ios::binary);
    out << prefix;
    std::string block(MiB, fill);
    for (std::size_t left = count; left > 0;) {
      std::size_t n = std::min(left, block.size());
      out.write(block.data(), static_cast<std::streamsize>(n));
      left -= n;
    }
    out << suffix;
    if (!out) throw std::runtime_error("cannot write " + path.string());
  }
  ~GeneratedFile() {
    std::error_code ec;
    std::filesystem::remove(path, ec);
  }
};

TEST(Hostile, AllocationCounterSeesAllocations) {
  Cost c = measure([] {
    std::vector<char> block(10 * MiB);
    block[5] = 1;
    EXPECT_EQ(block[5], 1);
  });
  EXPECT_GE(c.peak, 10 * MiB);
  EXPECT_LT(c.peak, 11 * MiB);
  ASSERT_TRUE(gmp_counted);
  Cost limbs = measure([] {
    mpz_class big;
    mpz_ui_pow_ui(big.get_mpz_t(), 2, 80 * MiB);  // 10 MiB of limbs
    EXPECT_GT(mpz_sizeinbase(big.get_mpz_t(), 2), 80 * MiB);
  });
  EXPECT_GE(limbs.peak, 10 * MiB);
  EXPECT_LT(limbs.peak, 21 * MiB);
}

// ---- lying headers ----------------------------------------------------------

TEST(Hostile, LyingOffHeadersFinishFastWithBoundedMemory) {
  Cost beyond = measure([] {
    EXPECT_TRUE(throws_error([] { read_file(test::data_path("bad/lying_header.off")); }, ErrorCategory::limit,
                             {"lying_header.off:2:"}));
  });
  Cost within = measure([] {
    EXPECT_TRUE(throws_error([] { read_file(test::data_path("bad/lying_header_within_limits.off")); },
                             ErrorCategory::parse, {"lying_header_within_limits.off:6:"}));
  });
  // Exactly at the default limits: 5e7 vertices and 1e8 faces in a 40-byte input.
  Cost at_limit = measure([] {
    std::istringstream in("OFF\n50000000 100000000 0\n0 0 0\n");
    EXPECT_TRUE(
        throws_error([&] { read_off(in, "lie.off"); }, ErrorCategory::parse, {"lie.off:3:", "only 1"}));
  });
  for (const Cost& c : {beyond, within, at_limit}) {
    EXPECT_LT(c.peak, 2 * MiB);
    EXPECT_LT(c.seconds, 1.0 * slow_factor);
  }
}

TEST(Hostile, LyingBinaryStlCountFinishesFastWithBoundedMemory) {
  Cost c = measure([] {
    EXPECT_TRUE(throws_error([] { read_file(test::data_path("bad/binary_lying_count.stl")); },
                             ErrorCategory::parse, {"binary_lying_count.stl: byte 134:"}));
  });
  EXPECT_LT(c.peak, MiB);
  EXPECT_LT(c.seconds, 1.0 * slow_factor);
}

// ---- a 100 MB single line ---------------------------------------------------

TEST(Hostile, HundredMegabyteLineInAFileHitsTheByteLimitEarly) {
  GeneratedFile file("byte_limit.off", "OFF\n", '1', hundred_mb, "\n");
  Cost c = measure([&] {
    EXPECT_TRUE(throws_error([&] { read_file(file.path, ReadLimits{.max_bytes = MiB}); },
                             ErrorCategory::limit, {"byte_limit.off", "1048576 bytes"}));
  });
  EXPECT_LT(c.peak, 4 * MiB);
  EXPECT_LT(c.seconds, 1.0 * slow_factor);
}

TEST(Hostile, HundredMegabyteNumberInAFileWithDefaultLimits) {
  GeneratedFile file("long_number.off", "OFF\n1 0 0\n", '7', hundred_mb, " 0 0\n");
  Cost c = measure([&] {
    EXPECT_TRUE(throws_error([&] { read_file(file.path); }, ErrorCategory::limit,
                             {"long_number.off:3:", "x coordinate of vertex 0 has 100000000 characters"}));
  });
  // The line is buffered whole (about its size, twice while the buffer grows).
  EXPECT_LT(c.peak, 3 * hundred_mb);
  EXPECT_LT(c.seconds, 5.0 * slow_factor);
}

TEST(Hostile, HundredMegabyteLineOfBlanksIsReadCorrectly) {
  GeneratedFile file("blanks.off", "OFF\n1 0 0\n", ' ', hundred_mb, "1 -2 3/4\n");
  PolygonSoup soup;
  Cost c = measure([&] { soup = read_file(file.path); });
  ASSERT_EQ(soup.points.size(), 1u);
  EXPECT_EQ(soup.points[0], test::v3(1, -2, Rational(3, 4)));
  EXPECT_LT(c.peak, 3 * hundred_mb);
  EXPECT_LT(c.seconds, 5.0 * slow_factor);
}

TEST(Hostile, HundredMegabyteLinesInEveryReaderFromAStream) {
  // OBJ: a 100 MB comment is skipped.
  {
    GeneratedBuffer buffer("v 0 0 0\nv 1 0 0\nv 0 1 0\n#", 'c', hundred_mb, "\nf 1 2 3\n");
    std::istream in(&buffer);
    PolygonSoup soup;
    Cost c = measure([&] { soup = read_obj(in, "<stdin>"); });
    EXPECT_EQ(soup.num_faces(), 1u);
    EXPECT_LT(c.peak, 3 * hundred_mb);
    EXPECT_LT(c.seconds, 5.0 * slow_factor);
  }
  // STL: the input is read whole, so max_bytes stops it early.
  {
    GeneratedBuffer buffer("solid ", 'n', hundred_mb, "\nendsolid\n");
    std::istream in(&buffer);
    Cost c = measure([&] {
      EXPECT_TRUE(throws_error([&] { read_stl(in, "<stdin>", ReadLimits{.max_bytes = 4 * MiB}); },
                               ErrorCategory::limit, {"<stdin>", "4194304 bytes"}));
    });
    EXPECT_LT(c.peak, 16 * MiB);
  }
  // STL with default limits: a 100 MB solid name is skipped.
  {
    GeneratedBuffer buffer("solid ", 'n', hundred_mb, "\nendsolid\n");
    std::istream in(&buffer);
    PolygonSoup soup;
    Cost c = measure([&] { soup = read_stl(in, "<stdin>"); });
    EXPECT_EQ(soup.num_faces(), 0u);
    EXPECT_LT(c.peak, 3 * hundred_mb);
    EXPECT_LT(c.seconds, 5.0 * slow_factor);
  }
  // Points: 100 MB of junk in one token is a parse error... after the number limit.
  {
    GeneratedBuffer buffer("0 0 0\n", 'z', hundred_mb, " 0 0\n");
    std::istream in(&buffer);
    Cost c = measure([&] {
      EXPECT_TRUE(throws_error([&] { read_points(in, "<stdin>"); }, ErrorCategory::limit, {"<stdin>:2:"}));
    });
    EXPECT_LT(c.peak, 3 * hundred_mb);
    EXPECT_LT(c.seconds, 5.0 * slow_factor);
  }
}

TEST(Hostile, OneFaceWithAMillionIndices) {
  std::string text = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n1000000";
  for (int i = 0; i < 1000000; ++i) text += i % 2 ? " 1" : " 2";
  text += "\n";
  std::istringstream in(text);
  PolygonSoup soup = read_off(in, "big_face.off");
  ASSERT_EQ(soup.num_faces(), 1u);
  EXPECT_EQ(soup.face(0).size(), 1000000u);
  EXPECT_EQ(soup.face(0)[0], 2u);
  EXPECT_EQ(soup.face(0)[999999], 1u);
}

// ---- binary junk ------------------------------------------------------------

TEST(Hostile, MegabytesOfBinaryJunkInEveryReader) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937_64 rng(seed);
    std::string junk(4 * MiB, '\0');
    for (char& c : junk) c = static_cast<char>(rng() & 0xff);
    for (FileFormat format : {FileFormat::off, FileFormat::obj, FileFormat::stl}) {
      std::istringstream in(junk);
      Cost c = measure([&] {
        EXPECT_TRUE(throws_error([&] { read(in, format, "junk"); }, ErrorCategory::parse, {"junk"}));
      });
      EXPECT_LT(c.peak, 64 * MiB);
      EXPECT_LT(c.seconds, 2.0 * slow_factor);
    }
    std::istringstream in(junk);
    EXPECT_TRUE(throws_error([&] { read_points(in, "junk"); }, ErrorCategory::parse, {"junk:"}));
  }
}

// ---- /dev/zero and endless lines ---------------------------------------------

// A line buffer that doubles as it reads /dev/zero would take GBs of memory
// before the 4 GiB max_bytes error. A NUL byte ends a text reader at its
// first chunk, and the STL reader (which reads whole) reads no more than a
// binary STL's declared size plus a megabyte.
TEST(Hostile, DevZeroIsRefusedAtOnceByEveryReader) {
  for (int reader = 0; reader < 4; ++reader) {
    SCOPED_TRACE(reader);
    GeneratedBuffer zeros("", '\0', std::size_t{1} << 40, "");  // a terabyte, never made
    std::istream in(&zeros);
    Cost c = measure([&] {
      EXPECT_TRUE(throws_error(
          [&] {
            if (reader == 0) (void)read_off(in, "/dev/zero");
            if (reader == 1) (void)read_obj(in, "/dev/zero");
            if (reader == 2) (void)read_points(in, "/dev/zero");
            if (reader == 3) (void)read_stl(in, "/dev/zero");
          },
          ErrorCategory::parse, {"/dev/zero"}));
    });
    EXPECT_LT(c.peak, 8 * MiB);
    EXPECT_LT(c.seconds, 1.0 * slow_factor);
  }
  std::ifstream real("/dev/zero", std::ios::binary);
  if (!real) GTEST_SKIP() << "no /dev/zero";
  EXPECT_TRUE(throws_error([&] { (void)read_off(real, "/dev/zero"); }, ErrorCategory::parse,
                           {"/dev/zero:1: a NUL byte at byte 0"}));
}

// An ASCII STL header followed by zeros: too long to be binary, and a NUL
// byte is not ASCII, so it ends after the first megabyte.
TEST(Hostile, SolidFollowedByZerosEndsEarly) {
  GeneratedBuffer zeros("solid zeros\n", '\0', std::size_t{1} << 40, "");
  std::istream in(&zeros);
  Cost c = measure([&] {
    EXPECT_TRUE(throws_error([&] { (void)read_stl(in, "z.stl"); }, ErrorCategory::parse,
                             {"z.stl: byte 84:", "a NUL byte in an ASCII STL; not binary either"}));
  });
  EXPECT_LT(c.peak, 8 * MiB);
}

// A line without an end, from a stream: Error(limit) at max_line_bytes, the
// buffer never past it plus a chunk.
TEST(Hostile, EndlessLineStopsAtMaxLineBytes) {
  for (int reader = 0; reader < 3; ++reader) {
    SCOPED_TRACE(reader);
    GeneratedBuffer line(reader == 1 ? "v 0 0 0\n#" : "OFF\n", 'a', std::size_t{1} << 40, "");
    std::istream in(&line);
    const ReadLimits limits{.max_line_bytes = 4 * MiB};
    Cost c = measure([&] {
      EXPECT_TRUE(throws_error(
          [&] {
            if (reader == 0) (void)read_off(in, "long", limits);
            if (reader == 1) (void)read_obj(in, "long", limits);
            if (reader == 2) (void)read_points(in, "long", limits);
          },
          ErrorCategory::limit, {"long:2: line longer than the limit of 4194304 bytes (ReadLimits::max_line_bytes)"}));
    });
    // The buffer doubles: the old one and the new, twice the limit, live at once.
    EXPECT_LT(c.peak, 16 * MiB);
    EXPECT_LT(c.seconds, 1.0 * slow_factor);
  }
}

// ---- what a polyhedron keeps --------------------------------------------------

// A box given as 12,288 coplanar triangles (sheared, so that the normals are
// large integers) merges into 6 facets; the result keeps no more memory
// than the same box given as 6 quads: none of the exact normals of the
// faces merged away (the arena keeps only the facets').
TEST(Hostile, AFinelyTriangulatedBoxKeepsOnlyItsFacets) {
  auto sheared = [](PolygonSoup soup) {
    for (Vec3& q : soup.points)
      q = Vec3{1000003 * q.x + 7 * q.y + 11 * q.z, 13 * q.x + 999983 * q.y + 17 * q.z,
               19 * q.x + 23 * q.y + 1000033 * q.z};
    return soup;
  };
  // The bytes p holds: the heap in use while p lives, less after it died
  // (the input, moved into from_soup, is gone in both).
  auto retained = [](const PolygonSoup& soup) {
    PolygonSoup copy = soup;
    std::size_t with_p = 0;
    {
      const ConvexPolyhedron p = ConvexPolyhedron::from_soup(std::move(copy));
      EXPECT_EQ(p.num_facets(), 6u);
      with_p = current_bytes.load();
    }
    return with_p - current_bytes.load();
  };
  const PolygonSoup fine = sheared(test::subdivided(test::cube_quads(), 5));
  ASSERT_EQ(fine.num_faces(), 12288u);
  const std::size_t coarse_bytes = retained(sheared(test::cube_quads()));
  const std::size_t fine_bytes = retained(fine);
  std::printf("    kept %zu bytes (6 quads), %zu bytes (12,288 triangles)\n", coarse_bytes, fine_bytes);
  EXPECT_LE(fine_bytes, coarse_bytes + 1024);
}

// ---- exact numbers that are much bigger than their text ----------------------

// A 687 KB OFF of "1e99999" tokens, each a 332,000-bit integer if built,
// would take GBs of memory; the reader stops at its first token.
TEST(Hostile, ExponentTokensOf1e99999AreRefusedAtTheFirstOne) {
  std::string text = "OFF\n28625 0 0\n";
  for (int i = 0; i < 28625; ++i) text += "1e99999 1e99999 1e99999\n";
  ASSERT_GT(text.size(), 680000u);
  std::istringstream in(text);
  Cost c = measure([&] {
    EXPECT_TRUE(throws_error(
        [&] { read_off(in, "exp.off"); }, ErrorCategory::limit,
        {"exp.off:3: x coordinate of vertex 0 '1e99999' needs a numerator of at least 332190 bits",
         "limit of 4096 (ReadLimits::max_number_bits)"}));
  });
  EXPECT_LT(c.peak, 2 * MiB);
  EXPECT_LT(c.seconds, 0.5 * slow_factor);
}

// The integer points of a paraboloid cap: a valid convex polyhedron with 81
// vertices, written with each coordinate k as "k<suffix>".
std::string paraboloid_off(const std::string& suffix) {
  std::vector<Vec3> points;
  for (int x = -5; x <= 5; ++x)
    for (int y = -5; y <= 5; ++y)
      if (x * x + y * y <= 25) points.push_back(test::v3(x, y, x * x + y * y));
  PolygonSoup soup = convex_hull(points).to_soup();
  std::string text =
      "OFF\n" + std::to_string(soup.points.size()) + " " + std::to_string(soup.num_faces()) + " 0\n";
  for (const Vec3& p : soup.points)
    text += to_string(p.x) + suffix + " " + to_string(p.y) + suffix + " " + to_string(p.z) + suffix + "\n";
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    text += std::to_string(soup.face(f).size());
    for (std::uint32_t i : soup.face(f)) {
      text += ' ';  // not " " + to_string(i): a false GCC 12 -Wrestrict at -O3 (bug 105329)
      text += std::to_string(i);
    }
    text += "\n";
  }
  return text;
}

// An 84-vertex polyhedron written "k e-99999" (3.7 KB) would take seconds to
// check, 1,056 vertices minutes. Refused at its first coordinate;
// at the cap (k e-1233, 4096-bit denominators) it reads and checks quickly.
TEST(Hostile, PolyhedronWithCoordinatesWrittenKeMinus99999IsRefusedAtOnce) {
  ASSERT_EQ(ConvexPolyhedron::from_soup([] {
              std::istringstream in(paraboloid_off(""));
              return read_off(in, "plain.off");
            }())
                .num_vertices(),
            81u);
  const std::string attack = paraboloid_off("e-99999");
  ASSERT_LT(attack.size(), 4000u);
  Cost c = measure([&] {
    EXPECT_TRUE(throws_error(
        [&] {
          std::istringstream in(attack);
          (void)ConvexPolyhedron::from_soup(read_off(in, "tiny.off"));
        },
        ErrorCategory::limit,
        {"tiny.off:3: x coordinate of vertex 0 '", "e-99999' needs a denominator of at least 33"}));
  });
  EXPECT_LT(c.seconds, 0.5 * slow_factor);
  Cost at_cap = measure([&] {
    std::istringstream in(paraboloid_off("e-1233"));
    EXPECT_EQ(ConvexPolyhedron::from_soup(read_off(in, "cap.off")).num_vertices(), 81u);
  });
  EXPECT_LT(at_cap.seconds, 2.0 * slow_factor);
  EXPECT_TRUE(throws_error(
      [&] {
        std::istringstream in(paraboloid_off("e-2466"));
        (void)read_off(in, "over.off");
      },
      ErrorCategory::limit, {"over.off:3:", "needs a denominator of at least 8189 bits", "limit of 4096"}));
}

// A tetrahedron of p/q with 500,000-digit p and q (each token just under
// max_number_chars, 12 MB) would take minutes to check.
TEST(Hostile, HalfMillionDigitFractionsAreRefusedFromTheirDigitCount) {
  const std::string big = std::string(500000, '9') + "/" + std::string(499999, '7') + "1";
  ASSERT_LT(big.size(), ReadLimits{}.max_number_chars);
  std::string text = "OFF\n4 4 0\n";
  for (int v = 0; v < 4; ++v) text += big + " " + big + " " + big + "\n";
  text += "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  std::istringstream in(text);
  Cost c = measure([&] {
    EXPECT_TRUE(throws_error(
        [&] { read_off(in, "frac.off"); }, ErrorCategory::limit,
        {"frac.off:3: x coordinate of vertex 0 '999", "...' needs a numerator of at least 1660961 bits"}));
  });
  EXPECT_LT(c.peak, 16 * MiB);  // the 3 MB line is buffered whole
  EXPECT_LT(c.seconds, 0.5 * slow_factor);
}

// Tokens just under the per-number cap ("1e1233" is 4097 bits in 7 bytes)
// meet the total: at most 256 bits per byte of input (2^20 at least).
TEST(Hostile, TokensJustUnderTheBitCapStopAtTheTotal) {
  std::string text = "OFF\n28625 0 0\n";
  for (int i = 0; i < 28625; ++i) text += "1e1233 1e1233 1e1233\n";
  std::istringstream in(text);
  Cost c = measure([&] {
    EXPECT_TRUE(throws_error(
        [&] { read_off(in, "total.off"); }, ErrorCategory::limit,
        {"total.off:", "'1e1233' brings the numbers read to", "ReadLimits::max_number_bits_per_byte"}));
  });
  EXPECT_LT(c.peak, 2 * MiB);
  EXPECT_LT(c.seconds, 0.5 * slow_factor);
  // With the bytes to pay for them (padding comments), the numbers are read,
  // and their memory is bounded by the input: at most 32 bytes of digits per
  // byte, plus each rational's fixed ~100 bytes.
  std::string padded = "OFF\n5000 0 0\n";
  for (int i = 0; i < 5000; ++i) padded += "1e1233 1e1233 1e1233 #" + std::string(42, '-') + "\n";
  std::istringstream in2(padded);
  PolygonSoup soup;
  Cost read = measure([&] { soup = read_off(in2, "padded.off"); });
  EXPECT_EQ(soup.points.size(), 5000u);
  EXPECT_LT(read.peak, 48 * padded.size());
}

// The caps never meet honest input: extreme doubles, shortest or exact,
// and a whole file of the densest one ("1e308 ", 171 bits per byte).
TEST(Hostile, HonestExtremeDoublesPassTheNumberCaps) {
  std::string text;
  for (double d : {5e-324, DBL_MIN, DBL_MAX, -DBL_MAX, 1e-300, 1e300, 4.9406564584124654e-324}) {
    char shortest[64];
    auto end = std::to_chars(shortest, shortest + sizeof shortest, d).ptr;
    text += std::string(shortest, end) + " " + to_string(rational_from_double(d)) + " 0\n";
  }
  for (int i = 0; i < 100000; ++i) text += "1e308 -1e308 1e-308\n";
  std::istringstream in(text);
  std::vector<Vec3> points;
  Cost c = measure([&] { points = read_points(in, "honest.xyz"); });
  ASSERT_EQ(points.size(), 100007u);
  EXPECT_EQ(points[0].y, rational_from_double(5e-324));
  EXPECT_LT(c.seconds, 5.0 * slow_factor);
}

// PLY headers that lie: beyond the limits they are refused on their line;
// at the limits (5e7 vertices, 1e8 faces) over a body of one vertex, ASCII
// and binary, the reader ends at the body's end having reserved no more
// than the input can hold.
TEST(Hostile, LyingPlyHeadersFinishFastWithBoundedMemory) {
  const std::string xyz = "property float x\nproperty float y\nproperty float z\n";
  const std::string faces = "element face 100000000\nproperty list uchar int vertex_indices\nend_header\n";
  Cost beyond = measure([] {
    EXPECT_TRUE(throws_error([] { read_file(test::data_path("bad/ply_lying_vertex_count.ply")); },
                             ErrorCategory::limit, {"ply_lying_vertex_count.ply:3:"}));
  });
  Cost ascii = measure([&] {
    std::istringstream in("ply\nformat ascii 1.0\nelement vertex 50000000\n" + xyz + faces + "0 0 0\n");
    EXPECT_TRUE(throws_error([&] { read_ply(in, "lie.ply"); }, ErrorCategory::parse,
                             {"lie.ply:10:", "missing x coordinate of vertex 1"}));
  });
  Cost binary = measure([&] {
    std::istringstream in("ply\nformat binary_big_endian 1.0\nelement vertex 50000000\n" + xyz + faces +
                          std::string(12, '\0'));
    EXPECT_TRUE(throws_error([&] { read_ply(in, "lie.ply"); }, ErrorCategory::parse,
                             {"lie.ply: byte ", "unexpected end of input in x coordinate of vertex 1"}));
  });
  for (const Cost& c : {beyond, ascii, binary}) {
    EXPECT_LT(c.peak, 2 * MiB);
    EXPECT_LT(c.seconds, 1.0 * slow_factor);
  }
}

}  // namespace
}  // namespace cvms
