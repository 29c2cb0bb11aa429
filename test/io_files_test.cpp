// SPDX-License-Identifier: MIT
// write_file on real files (a failed write must never truncate the existing
// file): atomic replacement, the mode of the new file, targets that are not
// regular files (/dev/null, /dev/full, a directory, a symlink), a file
// size limit hit in the middle of the text, the times a write reports, and
// the reader messages that concern line ends and the OFF header.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <csignal>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cvms/io.hpp"
#include "cvms/shapes.hpp"
#include "support/io_expect.hpp"

namespace cvms {
namespace {

namespace fs = std::filesystem;
using test::throws_error;

class WriteFile : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("cvms_write_file_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);
  }
  fs::path file(const std::string& name) const { return dir_ / name; }
  static std::string slurp(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
  static void put(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
  }
  // The names in the test directory: a leftover temporary would show here.
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& entry : fs::directory_iterator(dir_)) out.push_back(entry.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
  }
  fs::path dir_;
};

PolygonSoup tetrahedron_at(const Rational& scale) {
  PolygonSoup soup;
  soup.points = {Vec3{0, 0, 0}, Vec3{scale, 0, 0}, Vec3{0, scale, 0}, Vec3{0, 0, scale}};
  soup.add_face({0, 2, 1});
  soup.add_face({0, 1, 3});
  soup.add_face({0, 3, 2});
  soup.add_face({1, 2, 3});
  return soup;
}

// `cvms sum x.stl x.stl -o x.stl` fails (beyond float); x.stl must keep its
// bytes, not be left at 0 bytes by an early truncation.
TEST_F(WriteFile, FailedStlWriteLeavesTheOldFileByteIdentical) {
  const fs::path path = file("x.stl");
  write_file(path, tetrahedron_at(Rational(1)));
  const std::string before = slurp(path);
  ASSERT_EQ(before.size(), 84u + 4 * 50);
  EXPECT_TRUE(throws_error([&] { write_file(path, tetrahedron_at(Rational(mpz_class(1) << 200))); },
                           ErrorCategory::invalid_argument, {path.string() + ": ", "beyond the range of float"}));
  EXPECT_EQ(slurp(path), before);
  EXPECT_EQ(names(), std::vector<std::string>{"x.stl"});
}

// ... and `--float` beyond the range of double left mine.off empty.
TEST_F(WriteFile, FailedDoubleWriteLeavesTheOldFileByteIdentical) {
  const fs::path path = file("mine.off");
  put(path, "the old content\n");
  EXPECT_TRUE(throws_error(
      [&] { write_file(path, tetrahedron_at(Rational(mpz_class(1) << 2000)), Coordinates::double_); },
      ErrorCategory::invalid_argument, {path.string() + ": "}));
  EXPECT_EQ(slurp(path), "the old content\n");
  EXPECT_EQ(names(), std::vector<std::string>{"mine.off"});
  // A soup the writers refuse (an index out of range) changes nothing either.
  PolygonSoup bad = tetrahedron_at(Rational(1));
  bad.face_indices.back() = 9;
  EXPECT_TRUE(throws_error([&] { write_file(path, bad); }, ErrorCategory::invalid_argument, {"index 9"}));
  EXPECT_EQ(slurp(path), "the old content\n");
  EXPECT_EQ(names(), std::vector<std::string>{"mine.off"});
}

TEST_F(WriteFile, SuccessReplacesTheFileAndKeepsItsMode) {
  const fs::path path = file("a.off");
  put(path, "old\n");
  ASSERT_EQ(::chmod(path.c_str(), 0640), 0);
  write_file(path, tetrahedron_at(Rational(2)));
  EXPECT_EQ(slurp(path).substr(0, 4), "OFF\n");
  struct stat info {};
  ASSERT_EQ(::stat(path.c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 07777, 0640u);
  EXPECT_EQ(names(), std::vector<std::string>{"a.off"});
}

TEST_F(WriteFile, ANewFileGetsTheUmaskMode) {
  const mode_t mask = ::umask(022);
  write_file(file("new.obj"), tetrahedron_at(Rational(1)));
  ::umask(mask);
  struct stat info {};
  ASSERT_EQ(::stat(file("new.obj").c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 07777, 0644u);
}

TEST_F(WriteFile, ThroughASymlinkTheFileItNamesIsReplaced) {
  put(file("real.off"), "old\n");
  fs::create_symlink("real.off", file("link.off"));
  write_file(file("link.off"), tetrahedron_at(Rational(1)));
  EXPECT_TRUE(fs::is_symlink(file("link.off")));
  EXPECT_EQ(slurp(file("real.off")).substr(0, 4), "OFF\n");
  EXPECT_EQ(names(), (std::vector<std::string>{"link.off", "real.off"}));
}

TEST_F(WriteFile, ADirectoryIsAClearError) {
  fs::create_directory(file("d.off"));
  EXPECT_TRUE(throws_error([&] { write_file(file("d.off"), tetrahedron_at(Rational(1))); }, ErrorCategory::io,
                           {"cannot write '" + file("d.off").string() + "': it is a directory"}));
}

TEST_F(WriteFile, AMissingDirectoryNamesTheReason) {
  const fs::path path = file("no/such/dir.off");
  EXPECT_TRUE(throws_error([&] { write_file(path, tetrahedron_at(Rational(1))); }, ErrorCategory::io,
                           {"cannot write '" + path.string() + "'", "No such file or directory"}));
}

TEST_F(WriteFile, AnUnwritableDirectoryLeavesTheFileAlone) {
  if (::geteuid() == 0) GTEST_SKIP() << "root may write anywhere";
  const fs::path sub = file("ro");
  fs::create_directory(sub);
  put(sub / "x.off", "old\n");
  ASSERT_EQ(::chmod(sub.c_str(), 0555), 0);
  EXPECT_TRUE(throws_error([&] { write_file(sub / "x.off", tetrahedron_at(Rational(1))); }, ErrorCategory::io,
                           {"cannot create a temporary file", "Permission denied"}));
  ::chmod(sub.c_str(), 0755);
  EXPECT_EQ(slurp(sub / "x.off"), "old\n");
}

// A read-only file is refused, as opening it for writing was: the rename
// alone would need only the directory's permission.
TEST_F(WriteFile, AReadOnlyFileIsNotReplaced) {
  if (::geteuid() == 0) GTEST_SKIP() << "root may write anything";
  put(file("ro.off"), "old\n");
  ASSERT_EQ(::chmod(file("ro.off").c_str(), 0444), 0);
  EXPECT_TRUE(throws_error([&] { write_file(file("ro.off"), tetrahedron_at(Rational(1))); }, ErrorCategory::io,
                           {"cannot write '" + file("ro.off").string() + "': Permission denied"}));
  EXPECT_EQ(slurp(file("ro.off")), "old\n");
}

// Targets that are not regular files are written in place, by format.
TEST_F(WriteFile, DevNullIsWrittenAndDevFullNamesTheReason) {
  EXPECT_NO_THROW(write_file("/dev/null", tetrahedron_at(Rational(1)), FileFormat::off));
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  EXPECT_TRUE(throws_error([] { write_file("/dev/full", tetrahedron_at(Rational(1)), FileFormat::stl); },
                           ErrorCategory::io, {"cannot write '/dev/full': No space left on device"}));
}

// Holds RLIMIT_FSIZE at `bytes` (SIGXFSZ ignored, so that write() fails
// with EFBIG instead of ending the process) for the object's life.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    previous_handler_ = std::signal(SIGXFSZ, SIG_IGN);
    ok_ = ::getrlimit(RLIMIT_FSIZE, &previous_) == 0;
    const rlimit limited{bytes, previous_.rlim_max};
    ok_ = ok_ && bytes <= previous_.rlim_max && ::setrlimit(RLIMIT_FSIZE, &limited) == 0;
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;
  ~FileSizeLimit() {
    if (ok_) ::setrlimit(RLIMIT_FSIZE, &previous_);
    std::signal(SIGXFSZ, previous_handler_);
  }
  [[nodiscard]] bool ok() const { return ok_; }

 private:
  rlimit previous_{};
  void (*previous_handler_)(int) = SIG_DFL;
  bool ok_ = false;
};

// A disk that fills in the middle of the text (a file size limit of 100 kB
// against an OFF several times longer, written in blocks larger than the stream's
// buffer, the first of which is written only in part): the reason is named,
// the old file keeps its bytes and no temporary is left.
TEST_F(WriteFile, AFileSizeLimitMidWriteLeavesTheOldFileAndNoTemporary) {
  const ConvexPolyhedron sphere = shapes::geodesic_sphere(5);
  put(file("big.off"), "old\n");
  {
    FileSizeLimit limit(100000);
    if (!limit.ok()) GTEST_SKIP() << "cannot lower RLIMIT_FSIZE";
    EXPECT_TRUE(throws_error([&] { write_file(file("big.off"), sphere); }, ErrorCategory::io,
                             {"cannot write '" + file("big.off").string() + "': File too large"}));
  }
  EXPECT_EQ(slurp(file("big.off")), "old\n");
  EXPECT_EQ(names(), std::vector<std::string>{"big.off"});
}

// Written through blocks larger than the stream's buffer and through small
// ones, a file holds the bytes the stream writer makes; the times reported
// are those of this call, the wait for the disk a part of the whole.
TEST_F(WriteFile, AFileHoldsTheStreamWritersBytesAndItsTimesAreReported) {
  const ConvexPolyhedron sphere = shapes::geodesic_sphere(5);
  for (const FileFormat format : {FileFormat::off, FileFormat::obj, FileFormat::ply, FileFormat::stl}) {
    std::ostringstream expected;
    write(expected, sphere, format, Coordinates::exact, VertexOrder::canonical);
    ASSERT_GT(expected.str().size(), std::size_t{1} << 17);
    WriteTimes times{std::chrono::hours(1), std::chrono::hours(1)};
    write_file(file("out"), sphere, format, Coordinates::exact, VertexOrder::canonical, &times);
    EXPECT_EQ(slurp(file("out")), expected.str()) << static_cast<int>(format);
    EXPECT_GT(times.total.count(), 0);
    EXPECT_LE(times.sync, times.total);
  }
  // In place (no temporary, no synchronisation): no wait for the disk.
  WriteTimes times{std::chrono::hours(1), std::chrono::hours(1)};
  write_file("/dev/null", shapes::cube(), FileFormat::off, Coordinates::exact, VertexOrder::as_is,
             &times);
  EXPECT_EQ(times.sync.count(), 0);
  EXPECT_LT(times.total, std::chrono::hours(1));
}

TEST_F(WriteFile, AnExplicitFormatNeedsNoExtension) {
  write_file(file("plain"), shapes::cube(), FileFormat::obj);
  EXPECT_EQ(slurp(file("plain")).substr(0, 2), "v ");
  std::ifstream in(file("plain"), std::ios::binary);
  EXPECT_EQ(read_obj(in, "plain").points.size(), 8u);
  EXPECT_TRUE(throws_error([&] { write_file(file("plain"), shapes::cube()); }, ErrorCategory::invalid_argument,
                           {"extension"}));
}

// ---- reader messages ---------------------------------------------------------

// Line ends of '\r' alone make the file one line: the error says so.
TEST(ReaderMessages, CarriageReturnOnlyLineEndsAreNamed) {
  std::istringstream off("OFF\r4 4 0\r0 0 0\r1 0 0\r0 1 0\r0 0 1\r3 0 2 1\r3 0 1 3\r3 0 3 2\r3 1 2 3\r");
  EXPECT_TRUE(throws_error([&] { read_off(off, "mac.off"); }, ErrorCategory::parse,
                           {"mac.off:1:", "carriage return", "'\\r' alone"}));
  std::istringstream obj("v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r");
  EXPECT_TRUE(throws_error([&] { read_obj(obj, "mac.obj"); }, ErrorCategory::parse, {"mac.obj:1:", "carriage return"}));
  // "\r\n" is fine, and so is a '\r' that ends the last line.
  std::istringstream dos("OFF\r\n4 4 0\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n0 0 1\r\n3 0 2 1\r\n3 0 1 3\r\n3 0 3 2\r\n3 1 2 3\r");
  EXPECT_EQ(read_off(dos, "dos.off").num_faces(), 4u);
}

// The format is free-form: the counts may stand on lines of their own.
TEST(ReaderMessages, OffCountsOnSeveralLinesAreAccepted) {
  const std::string body = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  for (const std::string header : {"OFF 4 4 6\n", "OFF\n4 4 6\n", "OFF\n4\n4 6\n", "OFF\n4\n4\n6\n", "OFF 4\n4\n",
                                   "OFF\n4\n# faces\n4\n\n", "OFF\n4\n4\n"}) {
    SCOPED_TRACE(header);
    std::istringstream in(header + body);
    PolygonSoup soup = read_off(in, "free.off");
    EXPECT_EQ(soup.points.size(), 4u);
    EXPECT_EQ(soup.num_faces(), 4u);
  }
  std::istringstream missing("OFF\n4\n");
  EXPECT_TRUE(throws_error([&] { read_off(missing, "m.off"); }, ErrorCategory::parse,
                           {"unexpected end of input", "face count"}));
}

}  // namespace
}  // namespace cvms
