// SPDX-License-Identifier: MIT
// File access for the cvms tool (see files.hpp).
#include "files.hpp"

#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "cvms/error.hpp"

namespace cvms::cli {
namespace {

bool is_std_stream(const std::string& path) { return path == "-"; }

// Library errors raised after parsing name a face or edge but not the file:
// say which file they are about, without repeating a name already there.
[[noreturn]] void rethrow_naming(const Error& e, const std::string& name) {
  std::string message = e.what();
  if (message.find(name) != std::string::npos) throw e;
  // what() is "<category>: <message>"; keep the category first.
  std::string prefix = std::string(to_string(e.category())) + ": ";
  if (message.rfind(prefix, 0) == 0) message.erase(0, prefix.size());
  throw Error(e.category(), name + ": " + message);
}

std::ifstream open_input(const std::string& path) {
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    int error = errno;
    throw Error(ErrorCategory::io,
                "cannot open '" + path + "'" + (error != 0 ? std::string(": ") + std::strerror(error) : ""));
  }
  return in;
}

}  // namespace

std::string input_name(const std::string& path) { return is_std_stream(path) ? "<stdin>" : path; }

PolygonSoup read_soup(const std::string& path) {
  if (is_std_stream(path)) return read_off(std::cin, input_name(path));
  return read_file(path);
}

ConvexPolyhedron read_polyhedron(const std::string& path) { return to_polyhedron(read_soup(path), path); }

ConvexPolyhedron to_polyhedron(PolygonSoup soup, const std::string& path) {
  try {
    return ConvexPolyhedron::from_soup(std::move(soup));
  } catch (const Error& e) {
    rethrow_naming(e, input_name(path));
  }
}

std::vector<Vec3> read_point_cloud(const std::string& path) {
  if (is_std_stream(path)) return read_points(std::cin, input_name(path));
  std::ifstream in = open_input(path);
  std::string ext = path.size() >= 4 ? path.substr(path.size() - 4) : "";
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".stl") return read_stl(in, path).points;
  return read_points(in, path);
}

void write_polyhedron(const std::string& path, const ConvexPolyhedron& p, Coordinates coordinates) {
  PolygonSoup soup = p.to_soup();
  if (is_std_stream(path)) {
    write_off(std::cout, soup, coordinates);
    std::cout.flush();
    if (!std::cout) throw Error(ErrorCategory::io, "<stdout>: write failed");
    return;
  }
  try {
    write_file(path, soup, coordinates);
  } catch (const Error& e) {
    rethrow_naming(e, path);
  }
}

void check_output_directory(const std::string& path) {
  if (is_std_stream(path)) return;
  std::filesystem::path dir = std::filesystem::path(path).parent_path();
  std::error_code ec;
  if (!dir.empty() && !std::filesystem::is_directory(dir, ec))
    throw Error(ErrorCategory::io, "cannot write '" + path + "': no directory '" + dir.string() + "'");
}

std::string check_mesh_path(const std::string& path) {
  if (is_std_stream(path)) return {};
  try {
    (void)format_from_extension(path);
    return {};
  } catch (const Error&) {
    return "'" + path + "': expected '-' or a file ending in .off, .obj or .stl";
  }
}

}  // namespace cvms::cli
