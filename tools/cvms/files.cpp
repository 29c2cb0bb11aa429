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

ConvexPolyhedron read_polyhedron(const std::string& path) {
  if (is_std_stream(path)) return to_polyhedron(read_soup(path), input_name(path));
  return cvms::read_polyhedron(path);
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
  if (!is_std_stream(path)) return write_file(path, p, coordinates);
  write_off(std::cout, p.to_soup(), coordinates);
  std::cout.flush();
  if (!std::cout) throw Error(ErrorCategory::io, "<stdout>: write failed");
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
