// SPDX-License-Identifier: MIT
// The header of a PLY file (Greg Turk's polygon file format): its encoding
// and its elements, each a count of records made of scalar and list
// properties of eight numeric types. The reader keeps the element layout
// only; the body readers (io_ply.cpp) walk it record by record.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "io_reader.hpp"

namespace cvms::io_detail {

/// The numeric types of PLY, by their sizes (char and int8 are the same type).
enum class PlyType : std::uint8_t { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

/// Bytes of one value of `type` in a binary body.
std::size_t ply_size(PlyType type) noexcept;
/// True for the six integer types.
bool ply_is_integer(PlyType type) noexcept;
/// The name the header used for a type ("uchar", "float32", ...), for messages.
const char* ply_name(PlyType type) noexcept;

enum class PlyEncoding : std::uint8_t { ascii, binary_little_endian, binary_big_endian };

/// What a property is to the reader: a vertex coordinate, the index list of
/// a face, or anything else (skipped by size).
enum class PlyRole : std::uint8_t { skip, x, y, z, vertex_indices };

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::float32;  ///< a scalar's type, or a list's item type
  bool is_list = false;
  PlyType count_type = PlyType::uint8;  ///< a list's count type (an integer type)
  PlyRole role = PlyRole::skip;
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
  std::uint64_t line = 0;  ///< the header line that declared it
  /// Bytes of one record in a binary body when it holds no list, else 0.
  [[nodiscard]] std::uint64_t fixed_size() const noexcept;
};

struct PlyHeader {
  PlyEncoding encoding = PlyEncoding::ascii;
  std::vector<PlyElement> elements;
  std::uint64_t vertices = 0;  ///< the count of element "vertex"
  std::uint64_t faces = 0;     ///< the count of element "face", 0 without one
  std::uint64_t lines = 0;     ///< lines of the header, "end_header" included
  std::uint64_t bytes = 0;     ///< bytes of the header, its last '\n' included
};

/// Reads the header from the start of `bytes`, leaving it at the first byte
/// of the body. Each line and the header as a whole are bounded by
/// limits.max_line_bytes; the vertex and face counts are checked against
/// the limits here, before anything is allocated for them.
/// \throw Error(parse) naming "<source>:<line>" for a malformed header;
/// \throw Error(limit) for a count or a line beyond the limits.
PlyHeader read_ply_header(ByteSource& bytes, const ReadLimits& limits);

}  // namespace cvms::io_detail
