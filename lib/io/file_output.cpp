// SPDX-License-Identifier: MIT
// Atomic file output (see file_output.hpp): a temporary file created next to
// the target with O_EXCL (mode 0666, so the kernel applies the umask, as for
// any new file; the replaced file's mode is copied onto it), written through
// a stream buffer over the descriptor (not stdio) so that every failure keeps
// its errno, then synchronised, closed and renamed over the target. The
// writers hand over their text in blocks of tens of kilobytes: a block that
// does not fit the buffer's free space goes to write() as it is, so that
// the text is copied once, into the kernel, not twice.
#include "file_output.hpp"

#include <cerrno>
#include <chrono>
#include <cstring>
#include <random>
#include <string_view>
#include <streambuf>
#include <system_error>

#include "cvms/error.hpp"

#if __has_include(<unistd.h>)
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#define CVMS_POSIX_FILES 1
#else
#include <fstream>
#endif

namespace cvms::io_detail {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& why) {
  throw Error(ErrorCategory::io, "cannot write '" + path.string() + "': " + why);
}

// A fresh name in the target's directory: ".<name>.cvms-<random>.tmp".
std::filesystem::path temporary_name(const std::filesystem::path& target) {
  static constexpr char digits[] = "0123456789abcdefghijklmnopqrstuvwxyz";
  std::random_device device;
  std::string suffix;
  for (int i = 0; i < 12; ++i) suffix += digits[device() % 36];
  // Appended piece by piece: "literal" + std::string&& sets off GCC 12's
  // false -Wrestrict (GCC bug 105329) in a plain Release build.
  std::string name = ".";
  name += target.filename().string();
  name += ".cvms-";
  name += suffix;
  name += ".tmp";
  return target.parent_path() / name;
}

#ifdef CVMS_POSIX_FILES

std::string reason(int error) { return std::generic_category().message(error); }

// The descriptor a path stands for, for the aliases of this process's own
// descriptors (/dev/stdout, /dev/stderr, /dev/fd/N, /proc/self/fd/N), or -1.
// Written through a duplicate, never reopened: reopening would truncate or
// lose O_APPEND of a file the shell redirected stdout to.
int descriptor_alias(const std::filesystem::path& path) {
  const std::string text = path.lexically_normal().string();
  if (text == "/dev/stdout") return 1;
  if (text == "/dev/stderr") return 2;
  for (std::string_view prefix : {"/dev/fd/", "/proc/self/fd/"}) {
    if (text.rfind(prefix, 0) != 0 || text.size() == prefix.size() || text.size() > prefix.size() + 6)
      continue;
    int fd = 0;
    for (char c : text.substr(prefix.size())) {
      if (c < '0' || c > '9') return -1;
      fd = fd * 10 + (c - '0');
    }
    return fd;
  }
  return -1;
}

// An output stream buffer over a file descriptor that remembers the errno of
// the first failed write; the caller checks failed() after flushing.
class DescriptorBuffer : public std::streambuf {
 public:
  explicit DescriptorBuffer(int fd) : fd_(fd) { setp(buffer_, buffer_ + sizeof buffer_); }
  DescriptorBuffer(const DescriptorBuffer&) = delete;
  DescriptorBuffer& operator=(const DescriptorBuffer&) = delete;
  ~DescriptorBuffer() override = default;
  [[nodiscard]] int error() const noexcept { return error_; }

 protected:
  int_type overflow(int_type c) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return drain() ? 0 : -1; }
  // A block larger than the free space: what is buffered, then the block,
  // straight from the caller's memory.
  std::streamsize xsputn(const char_type* s, std::streamsize n) override {
    if (n <= epptr() - pptr()) {
      std::memcpy(pptr(), s, static_cast<std::size_t>(n));
      pbump(static_cast<int>(n));
      return n;
    }
    if (!drain() || !write_all(s, static_cast<std::size_t>(n))) return 0;
    return n;
  }

 private:
  bool write_all(const char* p, std::size_t size) {
    const char* const end = p + size;
    while (error_ == 0 && p < end) {
      const ssize_t n = ::write(fd_, p, static_cast<std::size_t>(end - p));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) error_ = n < 0 ? errno : EIO;
      else p += n;
    }
    return error_ == 0;
  }
  bool drain() {
    const bool written = write_all(pbase(), static_cast<std::size_t>(pptr() - pbase()));
    setp(buffer_, buffer_ + sizeof buffer_);
    return written;
  }
  int fd_;
  int error_ = 0;
  char buffer_[1 << 16];
};

// Writes through fd; a write error becomes Error(io) with its reason.
void write_to(int fd, const std::filesystem::path& path, const std::function<void(std::ostream&)>& write) {
  DescriptorBuffer buffer(fd);
  std::ostream out(&buffer);
  try {
    write(out);
  } catch (const Error& e) {
    // The writers report a failed stream as Error(io), naming neither the
    // file nor the reason.
    if (e.category() == ErrorCategory::io)
      fail(path, buffer.error() != 0 ? reason(buffer.error()) : "write failed");
    throw;
  }
  out.flush();
  if (buffer.error() != 0) fail(path, reason(buffer.error()));
  if (!out) fail(path, "write failed");
}

void close_or_fail(int fd, const std::filesystem::path& path) {
  if (::close(fd) != 0 && errno != EINTR) fail(path, reason(errno));
}

void write_in_place(const std::filesystem::path& path, int alias,
                    const std::function<void(std::ostream&)>& write) {
  const int fd =
      alias >= 0 ? ::fcntl(alias, F_DUPFD_CLOEXEC, 0) : ::open(path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
  if (fd < 0) fail(path, reason(errno));
  try {
    write_to(fd, path, write);
  } catch (...) {
    ::close(fd);
    throw;
  }
  close_or_fail(fd, path);
}

// Removes the temporary file unless released (after the rename).
struct TemporaryFile {
  std::filesystem::path path;
  bool owned = true;
  ~TemporaryFile() {
    if (owned) ::unlink(path.c_str());
  }
};

// Makes the rename durable; best effort (some file systems refuse to sync a
// directory, and the new content is already safe on disk).
void sync_directory(const std::filesystem::path& target) {
  const std::filesystem::path dir = target.parent_path().empty() ? "." : target.parent_path();
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  (void)::fsync(fd);
  ::close(fd);
}

void replace_atomically(const std::filesystem::path& target, const struct stat* existing,
                        const std::function<void(std::ostream&)>& write, WriteTimes* times) {
  int fd = -1;
  TemporaryFile temporary;
  for (int attempt = 0; fd < 0; ++attempt) {
    temporary.path = temporary_name(target);
    fd = ::open(temporary.path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0 && (errno != EEXIST || attempt == 100)) {
      temporary.owned = false;
      const std::filesystem::path dir = target.parent_path().empty() ? "." : target.parent_path();
      fail(target, "cannot create a temporary file in '" + dir.string() + "': " + reason(errno));
    }
  }
  try {
    if (existing != nullptr) (void)::fchmod(fd, existing->st_mode & 07777);  // best effort
    write_to(fd, target, write);
  } catch (...) {
    ::close(fd);
    throw;
  }
  // On disk before the rename: otherwise a crash just after it could leave
  // the target empty, the very loss the temporary is there to prevent.
  const auto sync_start = std::chrono::steady_clock::now();
  if (::fsync(fd) != 0 && errno != EINVAL) {
    const int error = errno;
    ::close(fd);
    fail(target, reason(error));
  }
  close_or_fail(fd, target);
  if (::rename(temporary.path.c_str(), target.c_str()) != 0) fail(target, reason(errno));
  temporary.owned = false;
  sync_directory(target);
  if (times != nullptr) times->sync = std::chrono::steady_clock::now() - sync_start;
}

}  // namespace

namespace {

void write_to_target(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write,
                     WriteTimes* times) {
  if (const int alias = descriptor_alias(path); alias >= 0) return write_in_place(path, alias, write);
  struct stat info {};
  const bool exists = ::stat(path.c_str(), &info) == 0;
  if (exists && S_ISDIR(info.st_mode)) fail(path, "it is a directory");
  if (exists && !S_ISREG(info.st_mode)) return write_in_place(path, -1, write);
  // A file the caller may not write stays so: renaming over it would need
  // only the directory's permission.
  if (exists && ::access(path.c_str(), W_OK) != 0) fail(path, reason(errno));
  // Through a symlink, replace the file it names, not the link.
  std::error_code ec;
  std::filesystem::path target = exists ? std::filesystem::canonical(path, ec) : path;
  if (ec) target = path;
  replace_atomically(target, exists ? &info : nullptr, write, times);
}

}  // namespace

void write_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write,
                      WriteTimes* times) {
  if (times != nullptr) times->sync = {};
  write_to_target(path, write, times);
}

#else  // no POSIX: the same steps with the standard library (no modes, no reasons)

}  // namespace

void write_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write,
                      WriteTimes* times) {
  if (times != nullptr) times->sync = {};  // no synchronisation here to time
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) fail(path, "it is a directory");
  const std::filesystem::path temporary = temporary_name(path);
  try {
    {
      std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
      if (!out) fail(path, "cannot create a temporary file");
      write(out);  // closed (so removable) when an exception leaves this scope
      out.close();
      if (!out) fail(path, "write failed");
    }
    std::filesystem::rename(temporary, path, ec);
    if (ec) fail(path, ec.message());
  } catch (...) {
    std::filesystem::remove(temporary, ec);
    throw;
  }
}

#endif

}  // namespace cvms::io_detail
