// SPDX-License-Identifier: MIT
// Hostile inputs for the readers, measured: headers that lie about counts,
// a 100 MB single line (generated at test time, in a temp file or by a
// stream that makes it up on the fly), megabytes of binary junk. Each must
// end with the documented error (or a correct result) quickly, and the
// memory the reader allocates is measured by counting operator new.
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <new>
#include <random>
#include <sstream>

#include "cvms/io.hpp"
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

#if defined(__SANITIZE_ADDRESS__)
constexpr double slow_factor = 8.0;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr double slow_factor = 8.0;
#else
constexpr double slow_factor = 1.0;
#endif
#else
constexpr double slow_factor = 1.0;
#endif

constexpr std::size_t MiB = std::size_t{1} << 20;
constexpr std::size_t hundred_mb = 100 * 1000 * 1000;

// Peak bytes allocated through operator new and seconds elapsed while f runs.
struct Cost {
  std::size_t peak = 0;
  double seconds = 0;
};
template <class F>
Cost measure(F&& f) {
  std::size_t base = current_bytes.load();
  peak_bytes.store(base);
  auto start = std::chrono::steady_clock::now();
  f();
  std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
  Cost cost{peak_bytes.load() - base, elapsed.count()};
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

}  // namespace
}  // namespace cvms
