// SPDX-License-Identifier: MIT
// File access for the cvms tool (see files.hpp).
#include "files.hpp"

#include <fcntl.h>
#include <sys/stat.h>

#include <cctype>
#include <chrono>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "cvms/error.hpp"
#include "cvms/halfspace_io.hpp"
#include "input_memory.hpp"
#include "usage_error.hpp"

namespace cvms::cli {
namespace {

std::string reason(int error) { return error != 0 ? std::string(": ") + std::strerror(error) : ""; }

// Reads from stdin with `read`; a read error of the stream (not its end) is
// Error(io) with the reason, whatever the reader made of the short input.
template <class Read>
auto read_stdin(Read&& read) {
  check_stdin();
  errno = 0;
  try {
    return read();
  } catch (const Error&) {
    const int error = errno;
    if (std::ferror(stdin)) throw Error(ErrorCategory::io, "cannot read standard input" + reason(error));
    throw;
  }
}

// /dev/null, /dev/stdout, /dev/full, ...: devices have no extension.
bool is_device_path(const std::string& path) {
  return path.rfind("/dev/", 0) == 0 && std::filesystem::path(path).extension().empty();
}

std::vector<Vec3> read_cdd_points_file(const std::string& path, const ReadLimits& limits) {
  std::ifstream in = open_input(path);
  return read_cdd_points(in, path, limits);
}

}  // namespace

void check_stdin() {
  struct stat info {};
  if (::fstat(0, &info) != 0) throw Error(ErrorCategory::io, "cannot read standard input" + reason(errno));
  if (S_ISDIR(info.st_mode)) throw Error(ErrorCategory::io, "cannot read standard input: it is a directory");
  const int flags = ::fcntl(0, F_GETFL);
  if (flags >= 0 && (flags & O_ACCMODE) == O_WRONLY)
    throw Error(ErrorCategory::io, "cannot read standard input: it is open for writing only");
}

std::ifstream open_input(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw Error(ErrorCategory::io, "cannot read '" + path + "': it is a directory");
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    int error = errno;
    throw Error(ErrorCategory::io, "cannot open '" + path + "'" + reason(error));
  }
  return in;
}

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

bool is_cdd_points_path(const std::string& path) { return !is_std_stream(path) && lower_extension(path) == ".ext"; }

bool is_std_stream(const std::string& path) { return path == "-"; }

std::string input_name(const std::string& path) { return is_std_stream(path) ? "<stdin>" : path; }

ReadLimits& read_limits() {
  static ReadLimits limits;
  return limits;
}

std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte != 0x7f) {
      out += c;
    } else {
      constexpr const char* hex = "0123456789abcdef";
      out += "\\x";
      out += hex[byte >> 4];
      out += hex[byte & 15];
    }
  }
  return out;
}

FileFormat output_format(const std::string& path, const std::string& format) {
  if (format == "off") return FileFormat::off;
  if (format == "obj") return FileFormat::obj;
  if (format == "stl") return FileFormat::stl;
  if (format == "ply") return FileFormat::ply;
  if (!format.empty()) throw UsageError("--format must be off, obj, stl or ply, not '" + format + "'");
  if (is_std_stream(path) || is_device_path(path)) return FileFormat::off;
  try {
    return format_from_extension(path);
  } catch (const Error&) {
    throw UsageError("cannot tell the format of '" + path +
                     "' from its extension (.off, .obj, .stl or .ply): give --format off|obj|stl|ply");
  }
}

PolygonSoup read_soup(const std::string& path) {
  const InputCost cost = is_cdd_points_path(path) ? InputCost::rows_or_points : InputCost::mesh;
  return read_within_budget(path, cost, [&](const ReadLimits& limits) {
    if (is_std_stream(path)) return read_stdin([&] { return read_off(std::cin, input_name(path), limits); });
    if (is_cdd_points_path(path)) {
      PolygonSoup soup;
      soup.points = read_cdd_points_file(path, limits);
      return soup;
    }
    return read_file(path, limits);
  });
}

ConvexPolyhedron read_polyhedron(const std::string& path) {
  if (is_std_stream(path)) return to_polyhedron(read_soup(path), input_name(path));
  return read_within_budget(path, InputCost::mesh,
                            [&](const ReadLimits& limits) { return cvms::read_polyhedron(path, limits); });
}

HalfspaceSystem read_halfspace_rows(const std::string& path) {
  return read_within_budget(path, InputCost::rows_or_points, [&](const ReadLimits& limits) {
    if (is_std_stream(path))
      return read_stdin(
          [&] { return read_halfspaces(std::cin, HalfspaceFormat::cdd, input_name(path), limits); });
    if (is_cdd_points_path(path)) {
      // Read as cdd, so that its V-representation line is named, not a row error.
      std::ifstream in = open_input(path);
      return read_halfspaces(in, HalfspaceFormat::cdd, path, limits);
    }
    return read_halfspace_file(path, limits);
  });
}

std::vector<Vec3> read_point_cloud(const std::string& path) {
  const std::string ext = lower_extension(path);
  const bool mesh = !is_std_stream(path) && (ext == ".off" || ext == ".obj" || ext == ".stl" || ext == ".ply");
  return read_within_budget(
      path, mesh ? InputCost::mesh : InputCost::rows_or_points, [&](const ReadLimits& limits) {
        if (is_std_stream(path))
          return read_stdin([&] { return read_points(std::cin, input_name(path), limits); });
        if (is_cdd_points_path(path)) return read_cdd_points_file(path, limits);
        std::ifstream in = open_input(path);
        if (ext == ".stl") return read_stl(in, path, limits).points;
        if (ext == ".ply") return read_ply(in, path, limits).points;
        return read_points(in, path, limits);
      });
}

void write_polyhedron(const std::string& path, const ConvexPolyhedron& p, Coordinates coordinates,
                      const std::string& format, VertexOrder order, WriteTimes* times) {
  const FileFormat chosen = output_format(path, format);
  if (!is_std_stream(path)) return write_file(path, p, chosen, coordinates, order, times);
  const auto start = std::chrono::steady_clock::now();
  write_stdout([&](std::ostream& out) { write(out, p, chosen, coordinates, order); });
  if (times != nullptr) *times = {std::chrono::steady_clock::now() - start, {}};
}

void write_soup(const std::string& path, const PolygonSoup& soup, Coordinates coordinates,
                const std::string& format) {
  const FileFormat chosen = output_format(path, format);
  if (!is_std_stream(path)) return write_file(path, soup, chosen, coordinates);
  write_stdout([&](std::ostream& out) { write(out, soup, chosen, coordinates); });
}

void write_stdout(const std::function<void(std::ostream&)>& write) {
  errno = 0;
  try {
    write(std::cout);
    std::cout.flush();
  } catch (const Error& e) {
    if (e.category() != ErrorCategory::io) throw;
  }
  const int error = errno;
  if (!std::cout) throw Error(ErrorCategory::io, "cannot write standard output" + reason(error));
}

void finish_stdout() {
  errno = 0;
  std::cout.flush();
  int error = errno;
  const bool flushed = std::fflush(stdout) == 0;
  if (error == 0) error = errno;
  if (!std::cout || !flushed || std::ferror(stdout) != 0)
    throw Error(ErrorCategory::io, "cannot write standard output" + reason(error));
}

void check_output_directory(const std::string& path) {
  if (is_std_stream(path)) return;
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw Error(ErrorCategory::io, "cannot write '" + path + "': it is a directory");
  std::filesystem::path dir = std::filesystem::path(path).parent_path();
  if (!dir.empty() && !std::filesystem::is_directory(dir, ec))
    throw Error(ErrorCategory::io, "cannot write '" + path + "': no directory '" + dir.string() + "'");
}

void check_output(const std::string& path, const std::string& format) {
  (void)output_format(path, format);
  check_output_directory(path);
}

Coordinates coordinates_of(const std::string& float_output) {
  if (float_output.empty()) return Coordinates::exact;
  return float_output == "outer" ? Coordinates::double_outer : Coordinates::double_;
}

std::string check_mesh_path(const std::string& path) {
  if (is_std_stream(path) || is_cdd_points_path(path)) return {};
  try {
    (void)format_from_extension(path);
    return {};
  } catch (const Error&) {
    return "'" + printable(path) + "': expected '-' or a file ending in .off, .obj, .stl, .ply or .ext";
  }
}

}  // namespace cvms::cli
