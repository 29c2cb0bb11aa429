// SPDX-License-Identifier: MIT
// See mesh_input.hpp.
#include "mesh_input.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <istream>
#include <cstring>
#include <streambuf>

#include "cvms/error.hpp"
#include "files.hpp"
#include "input_memory.hpp"
#include "pieces_files.hpp"

namespace cvms::cli {
namespace {

std::string with_reason(const std::string& what, int error) {
  return error != 0 ? what + ": " + std::strerror(error) : what;
}

// Appends what fd holds, up to `most` bytes in all; a regular file's size
// is the first request, so that it takes one read().
void read_all(int fd, std::uint64_t most, std::uint64_t expected, std::string& out, const std::string& name) {
  constexpr std::uint64_t chunk = std::uint64_t{1} << 16;
  // Room for the whole file and the read that finds its end, without a
  // reallocation that would copy it.
  out.reserve(static_cast<std::size_t>(std::min(most, expected + chunk)));
  for (;;) {
    const std::uint64_t want =
        std::min(most - out.size(), std::max(chunk, expected + 1 - std::min<std::uint64_t>(expected, out.size())));
    if (want == 0) return;
    const std::size_t old = out.size();
    out.resize(old + want);
    const ssize_t got = ::read(fd, out.data() + old, want);
    if (got < 0 && errno == EINTR) {
      out.resize(old);
      continue;
    }
    if (got < 0) {
      const int error = errno;
      out.resize(old);
      throw Error(ErrorCategory::io, with_reason("cannot read " + name, error));
    }
    out.resize(old + static_cast<std::size_t>(got));
    if (got == 0) return;
  }
}

// An input stream buffer over bytes held elsewhere: the reader copies from
// them as from a file.
class BytesBuffer : public std::streambuf {
 public:
  explicit BytesBuffer(const std::string& bytes) {
    char* begin = const_cast<char*>(bytes.data());  // never written: no put area
    setg(begin, begin, begin + bytes.size());
  }
};

}  // namespace

MeshInput read_mesh_input(const std::string& path) {
  MeshInput input{path, is_std_stream(path) ? FileFormat::off : format_from_extension(path),
                  input_read_limits(path, InputCost::mesh), {}};
  const std::uint64_t most = input.limits.max_bytes == UINT64_MAX ? UINT64_MAX : input.limits.max_bytes + 1;
  if (is_std_stream(path)) {
    check_stdin();
    struct stat info {};
    if (::fstat(0, &info) != 0) throw Error(ErrorCategory::io, with_reason("cannot read standard input", errno));
    read_all(0, most, S_ISREG(info.st_mode) ? static_cast<std::uint64_t>(info.st_size) : 0, input.bytes,
             "standard input");
    return input;
  }
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw Error(ErrorCategory::io, with_reason("cannot open '" + path + "'", errno));
  struct stat info {};
  try {
    if (::fstat(fd, &info) != 0) throw Error(ErrorCategory::io, with_reason("cannot read '" + path + "'", errno));
    if (S_ISDIR(info.st_mode)) throw Error(ErrorCategory::io, "cannot read '" + path + "': it is a directory");
    read_all(fd, most, S_ISREG(info.st_mode) ? static_cast<std::uint64_t>(info.st_size) : 0, input.bytes,
             "'" + path + "'");
  } catch (...) {
    ::close(fd);
    throw;
  }
  ::close(fd);
  return input;
}

PolygonSoup parse_soup(const MeshInput& input) {
  BytesBuffer buffer(input.bytes);
  std::istream in(&buffer);
  try {
    return read(in, input.format, input_name(input.path), input.limits);
  } catch (const Error& e) {
    rethrow_with_memory_hint(e, input.limits, InputCost::mesh);
  }
}

ConvexUnion read_pieces_text(const MeshInput& input) {
  BytesBuffer buffer(input.bytes);
  std::istream in(&buffer);
  try {
    return read_pieces(in, input_name(input.path), input.limits);
  } catch (const Error& e) {
    rethrow_with_memory_hint(e, input.limits, InputCost::mesh);
  }
}

bool holds_pieces(const MeshInput& input) {
  return input.format == FileFormat::obj && !is_std_stream(input.path) && is_pieces_text(input.bytes);
}

}  // namespace cvms::cli
