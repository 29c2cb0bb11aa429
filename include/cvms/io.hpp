// SPDX-License-Identifier: MIT
// Exact readers and writers for OFF, OBJ and STL. Readers never trust a count
// in a header for allocation beyond what the input can hold, and report every
// malformation as Error(parse) naming the source and line (text) or byte
// offset (binary). Writers write exact coordinates unless asked otherwise.
#pragma once

#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <string>
#include <string_view>

#include "cvms/polygon_soup.hpp"

namespace cvms {

/// Caps that protect against absurd or lying inputs; exceeding one raises
/// Error(limit).
struct ReadLimits {
  std::uint64_t max_vertices = 50'000'000;
  std::uint64_t max_faces = 100'000'000;
  std::uint64_t max_bytes = std::uint64_t{4} << 30;  ///< 4 GiB
};

enum class FileFormat { off, obj, stl };

/// The format named by a path's extension (.off .obj .stl, any case).
/// \throw Error(invalid_argument) for anything else.
FileFormat format_from_extension(const std::filesystem::path& path);

/// Readers. `source` names the input in error messages (a file name, "<stdin>").
PolygonSoup read_off(std::istream& in, std::string_view source, const ReadLimits& limits = {});
PolygonSoup read_obj(std::istream& in, std::string_view source, const ReadLimits& limits = {});
/// ASCII or binary STL (detected from the content); float32 coordinates are
/// converted exactly; vertices shared between triangles are merged by exact position.
PolygonSoup read_stl(std::istream& in, std::string_view source, const ReadLimits& limits = {});
PolygonSoup read(std::istream& in, FileFormat format, std::string_view source,
                 const ReadLimits& limits = {});
/// Reads a file in the format of its extension. \throw Error(io) if it cannot be opened.
PolygonSoup read_file(const std::filesystem::path& path, const ReadLimits& limits = {});

/// Points only, for hulls: OFF/OBJ vertices or one "x y z" per line
/// ('#' comments and blank lines allowed).
std::vector<Vec3> read_points(std::istream& in, std::string_view source,
                              const ReadLimits& limits = {});

enum class Coordinates {
  exact,   ///< exact decimals or p/q, see to_string(const Rational&)
  double_  ///< the nearest double, printed with enough digits to round-trip
};

void write_off(std::ostream& out, const PolygonSoup& soup, Coordinates coordinates = Coordinates::exact);
void write_obj(std::ostream& out, const PolygonSoup& soup, Coordinates coordinates = Coordinates::exact);
/// Binary STL with fan-triangulated faces (float32, so always rounded).
void write_stl(std::ostream& out, const PolygonSoup& soup);
void write(std::ostream& out, const PolygonSoup& soup, FileFormat format,
           Coordinates coordinates = Coordinates::exact);
/// \throw Error(io) if the file cannot be written.
void write_file(const std::filesystem::path& path, const PolygonSoup& soup,
                Coordinates coordinates = Coordinates::exact);

}  // namespace cvms
