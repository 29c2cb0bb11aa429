// SPDX-License-Identifier: MIT
// The readers' shared pieces (lib/io/io_reader.hpp): how much a header's
// count may reserve, and the point buffer that holds what was read. The
// expected sizes are worked out by hand from the input's length; the points
// are compared with the ones appended.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "io_reader.hpp"

namespace cvms::io_detail {
namespace {

// A stream buffer that cannot seek, like a pipe.
class PipeBuffer : public std::stringbuf {
 public:
  explicit PipeBuffer(const std::string& data) : std::stringbuf(data) {}

 protected:
  pos_type seekoff(off_type, std::ios_base::seekdir, std::ios_base::openmode) override { return pos_type(-1); }
  pos_type seekpos(pos_type, std::ios_base::openmode) override { return pos_type(-1); }
};

TEST(ReserveFor, AnHonestCountIsReservedWhole) {
  std::istringstream in(std::string(60'000, ' '));
  const LineReader reader(in, "in", {});
  EXPECT_EQ(reader.reserve_for(10'000, 6), 10'000u);
}

TEST(ReserveFor, ALyingCountReservesNoMoreThanTheInputCanHold) {
  std::istringstream in(std::string(1200, ' '));
  const LineReader reader(in, "in", {});
  EXPECT_EQ(reader.reserve_for(50'000'000, 6), 1200u / 6 + 1);
  const std::string data(600, ' ');
  const LineReader in_memory(data, "in", {});
  EXPECT_EQ(in_memory.reserve_for(50'000'000, 6), 600u / 6 + 1);
}

TEST(ReserveFor, OnlyTheBytesLeftCountAndTheStreamReadsOnFromWhereItWas) {
  std::istringstream in("skipped line\nOFF\n");
  std::string skipped;
  std::getline(in, skipped);
  LineReader reader(in, "in", {});
  EXPECT_EQ(reader.reserve_for(1000, 1), 4u + 1);  // "OFF\n"
  std::string_view line;
  ASSERT_TRUE(reader.next(line));
  EXPECT_EQ(line, "OFF");
  EXPECT_FALSE(reader.next(line));
}

TEST(ReserveFor, AStreamThatCannotSeekGetsTheFixedCap) {
  PipeBuffer pipe(std::string(1'000'000, ' '));
  std::istream in(&pipe);
  const LineReader reader(in, "in", {});
  EXPECT_EQ(reader.reserve_for(50'000'000, 6), safe_reserve(50'000'000));
  EXPECT_EQ(reader.reserve_for(7, 6), 7u);
}

TEST(ReserveFor, TheByteLimitBoundsTheReserveToo) {
  std::istringstream in(std::string(60'000, ' '));
  ReadLimits limits;
  limits.max_bytes = 600;
  const LineReader reader(in, "in", limits);
  EXPECT_EQ(reader.reserve_for(10'000, 6), 600u / 6 + 1);
}

Vec3 nth_point(std::size_t i) { return Vec3(Rational(i), Rational(1, i + 1), Rational(-1)); }

void expect_points_in_order(PointBuffer buffer, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) buffer.append() = nth_point(i);
  ASSERT_EQ(buffer.size(), count);
  const std::vector<Vec3> points = buffer.take();
  ASSERT_EQ(points.size(), count);
  for (std::size_t i = 0; i < count; ++i) ASSERT_EQ(points[i], nth_point(i)) << "point " << i;
  EXPECT_EQ(buffer.size(), 0u);
}

TEST(PointBuffer, KeepsEveryPointInOrderWhateverTheDeclaredCount) {
  for (const std::size_t count : {1u, 3u, 64u, 65u, 5'000u, 10'000u}) {
    SCOPED_TRACE("count " + std::to_string(count));
    expect_points_in_order(PointBuffer(), count);
    expect_points_in_order(PointBuffer(PointBuffer::Declared{count}), count);      // exact
    expect_points_in_order(PointBuffer(PointBuffer::Declared{10'000}), count);     // a larger header
    expect_points_in_order(PointBuffer(PointBuffer::Declared{3}), count);          // a smaller one
    expect_points_in_order(PointBuffer(PointBuffer::Declared{0}), count);
  }
}

// Without a declared count a point never moves until take() (the ASCII STL
// reader keys its vertex map on their addresses), across blocks too.
TEST(PointBuffer, WithoutACountPointsNeverMove) {
  PointBuffer buffer;
  std::vector<const Vec3*> addresses;
  for (std::size_t i = 0; i < 10'000; ++i) {
    Vec3& p = buffer.append();
    p = nth_point(i);
    addresses.push_back(&p);
  }
  for (std::size_t i = 0; i < addresses.size(); ++i) ASSERT_EQ(*addresses[i], nth_point(i)) << i;
}

TEST(PointBuffer, AnExactDeclaredCountIsTakenWithoutMovingAPoint) {
  PointBuffer small(PointBuffer::Declared{3});
  const Vec3* first = &small.append();
  small.append();
  small.append();
  EXPECT_EQ(small.take().data(), first);
  // A large block is reserved after its first few points were read; from
  // then on nothing moves.
  PointBuffer large(PointBuffer::Declared{1000});
  for (int i = 0; i < 100; ++i) large.append();
  const Vec3* hundredth = &large.append();
  for (int i = 101; i < 1000; ++i) large.append();
  EXPECT_EQ(large.take().data() + 100, hundredth);
}

// A block handed over whole keeps no unused room: a few points in a buffer
// sized for many come back in a vector of their own size.
TEST(PointBuffer, FewPointsDoNotKeepARoomyBlock) {
  PointBuffer buffer;
  for (int i = 0; i < 65; ++i) buffer.append();
  EXPECT_EQ(buffer.take().capacity(), 65u);
  PointBuffer declared(PointBuffer::Declared{10'000});
  for (int i = 0; i < 100; ++i) declared.append();
  EXPECT_EQ(declared.take().capacity(), 100u);
}

// Counts and indices saturate at 2^64 - 1: against GMP's value of the
// digits, clamped, at and around the boundary.
TEST(ParseUnsigned, SaturatesExactlyBeyond64Bits) {
  const mpz_class max("18446744073709551615");
  for (const char* token :
       {"0", "7", "000123", "1844674407370955161", "1844674407370955162", "18446744073709551609",
        "18446744073709551610", "18446744073709551614", "18446744073709551615", "18446744073709551616",
        "18446744073709551619", "18446744073709551620", "99999999999999999999", "0018446744073709551615",
        "123456789012345678901234567890",
        // at and just past the 19 digits that need no overflow test
        "9999999999999999999", "1000000000000000000", "0000000000000000009", "10000000000000000000"}) {
    const mpz_class value(token, 10);  // base 10: base 0 reads a leading 0 as octal
    const std::optional<std::uint64_t> parsed = parse_unsigned(token);
    ASSERT_TRUE(parsed.has_value()) << token;
    EXPECT_EQ(mpz_class(std::to_string(*parsed)), value > max ? max : value) << token;
  }
  for (const char* junk : {"", "-1", "+1", "1e3", "12a", " 1", "123456789012345678a", "1234567890123456789a"})
    EXPECT_FALSE(parse_unsigned(junk).has_value()) << junk;
}

}  // namespace
}  // namespace cvms::io_detail
