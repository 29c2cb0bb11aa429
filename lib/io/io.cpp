// SPDX-License-Identifier: MIT
// Format dispatch (by file extension), file reading and writing with io
// errors, the point-list reader used for hulls (OFF, OBJ or "x y z" lines),
// and the polyhedron-level calls that put the file name into every error.
#include <cerrno>
#include <chrono>
#include <fstream>
#include <system_error>
#include <utility>

#include "canonical_view.hpp"
#include "face_lists.hpp"
#include "mesh_access.hpp"
#include "file_output.hpp"
#include "float_coordinates.hpp"
#include "io_reader.hpp"

namespace cvms {

FileFormat format_from_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  if (ext == ".off") return FileFormat::off;
  if (ext == ".obj") return FileFormat::obj;
  if (ext == ".stl") return FileFormat::stl;
  if (ext == ".ply") return FileFormat::ply;
  throw Error(ErrorCategory::invalid_argument, "cannot tell the format of '" + path.string() +
                                                   "' from its extension (expected .off, .obj, .stl or .ply)");
}

PolygonSoup read(std::istream& in, FileFormat format, std::string_view source, const ReadLimits& limits) {
  switch (format) {
    case FileFormat::off:
      return read_off(in, source, limits);
    case FileFormat::obj:
      return read_obj(in, source, limits);
    case FileFormat::stl:
      return read_stl(in, source, limits);
    case FileFormat::ply:
      return read_ply(in, source, limits);
  }
  throw Error(ErrorCategory::invalid_argument, "unknown file format");
}

PolygonSoup read_file(const std::filesystem::path& path, const ReadLimits& limits) {
  FileFormat format = format_from_extension(path);
  std::ifstream in = io_detail::open_input_file(path);
  return read(in, format, path.string(), limits);
}

std::ifstream io_detail::open_input_file(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw Error(ErrorCategory::io, "cannot read '" + path.string() + "': it is a directory");
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    int error = errno;
    throw Error(ErrorCategory::io,
                "cannot open '" + path.string() + "'" +
                    (error != 0 ? ": " + std::generic_category().message(error) : std::string()));
  }
  return in;
}

std::vector<Vec3> read_points(std::istream& in, std::string_view source, const ReadLimits& limits) {
  using namespace io_detail;
  // A PLY body may be binary, which the line reader refuses: a PLY is told
  // by its first byte (no other input read here starts with 'p').
  if (std::streambuf* buffer = in.rdbuf(); buffer != nullptr && in.good() && buffer->sgetc() == 'p')
    return read_ply(in, source, limits).points;
  LineReader reader(in, source, limits);
  std::string_view line;
  std::string_view first;
  while (reader.next(line)) {
    first = Tokenizer(line).next();
    if (!first.empty()) break;
  }
  if (first.empty()) {
    if (reader.line_number() == 0) throw Error(ErrorCategory::parse, std::string(source) + ": empty input");
    reader.fail("no points in the input");
  }
  reader.unread();
  if (is_off_keyword(first)) return parse_off(reader).points;
  if (first == "v" || first == "vt" || first == "vn" || first == "f" || first == "o" || first == "g" ||
      first == "mtllib" || first == "usemtl" || first == "s")
    return parse_obj(reader).points;

  PointBuffer points;
  while (reader.next(line)) {
    Tokenizer tokens(line);
    std::string_view x = tokens.next();
    if (x.empty()) continue;
    const std::uint64_t index = points.size();
    check_vertex_limit(reader, index + 1);
    bool first_token = true;
    parse_point(
        reader, [&] { return std::exchange(first_token, false) ? x : tokens.next(); }, points.append(),
        "point", index);
    if (!tokens.at_end())
      reader.fail("point " + std::to_string(index) + " has more than 3 values: " + quote(tokens.next()));
  }
  return points.take();
}

namespace {

void write_view(std::ostream& out, const io_detail::SoupView& soup, FileFormat format, Coordinates coordinates) {
  io_detail::check_soup_coordinates(coordinates);
  switch (format) {
    case FileFormat::off:
      return io_detail::write_off_view(out, soup, coordinates);
    case FileFormat::obj:
      return io_detail::write_obj_view(out, soup, coordinates);
    case FileFormat::stl:
      return io_detail::write_stl_view(out, soup);
    case FileFormat::ply:
      return io_detail::write_ply_view(out, soup, coordinates);
  }
  throw Error(ErrorCategory::invalid_argument, "unknown file format");
}

void write_view_to_file(const std::filesystem::path& path, const io_detail::SoupView& soup, FileFormat format,
                        Coordinates coordinates, WriteTimes* times = nullptr) {
  try {
    io_detail::write_atomically(
        path, [&](std::ostream& out) { write_view(out, soup, format, coordinates); }, times);
  } catch (const Error& e) {
    // write_atomically names the file in its io errors; the stream writers
    // name a face, index or coordinate, never the file.
    if (e.category() == ErrorCategory::io) throw;
    throw Error(e.category(), path.string() + ": " + e.message());
  }
}

// view in the numbering asked for, the canonical one read from numbering.
io_detail::SoupView numbered(const io_detail::SoupView& view, VertexOrder order,
                             io_detail::CanonicalNumbering& numbering) {
  return order == VertexOrder::canonical ? io_detail::canonical_view(view, numbering) : view;
}

void write_polyhedron_to_file(const std::filesystem::path& path, const ConvexPolyhedron& p, FileFormat format,
                              Coordinates coordinates, VertexOrder order, WriteTimes* times = nullptr) {
  const auto round = [&p](FloatMode mode) { return round_to_doubles(p, mode); };
  io_detail::CanonicalNumbering numbering;
  if (const auto rounded = io_detail::rounded_soup(format, coordinates, path.string(), round))
    return write_view_to_file(path, numbered(io_detail::SoupView::of(*rounded), order, numbering), format,
                              Coordinates::double_, times);
  detail::FaceLists faces;
  write_view_to_file(path, numbered(io_detail::polyhedron_view(p, format, faces), order, numbering), format,
                     coordinates, times);
}

}  // namespace

io_detail::SoupView io_detail::polyhedron_view(const ConvexPolyhedron& p, FileFormat format, detail::FaceLists& faces) {
  faces = detail::face_lists(p.mesh());
  if (const detail::DyadicPoints* packed = MeshAccess::packed_positions(p.mesh()); packed != nullptr && format != FileFormat::stl)
    return {{}, faces.offsets, faces.indices, packed, {}};
  return {p.mesh().positions(), faces.offsets, faces.indices, nullptr, {}};
}

void write(std::ostream& out, const PolygonSoup& soup, FileFormat format, Coordinates coordinates) {
  write_view(out, io_detail::SoupView::of(soup), format, coordinates);
}

void write(std::ostream& out, const ConvexPolyhedron& p, FileFormat format, Coordinates coordinates,
           VertexOrder order) {
  const auto round = [&p](FloatMode mode) { return round_to_doubles(p, mode); };
  io_detail::CanonicalNumbering numbering;
  if (const auto rounded = io_detail::rounded_soup(format, coordinates, {}, round))
    return write_view(out, numbered(io_detail::SoupView::of(*rounded), order, numbering), format,
                      Coordinates::double_);
  detail::FaceLists faces;
  write_view(out, numbered(io_detail::polyhedron_view(p, format, faces), order, numbering), format, coordinates);
}

void write_file(const std::filesystem::path& path, const PolygonSoup& soup, FileFormat format,
                Coordinates coordinates) {
  write_view_to_file(path, io_detail::SoupView::of(soup), format, coordinates);
}

void write_file(const std::filesystem::path& path, const PolygonSoup& soup, Coordinates coordinates) {
  write_file(path, soup, format_from_extension(path), coordinates);
}

void write_file(const std::filesystem::path& path, const ConvexPolyhedron& p, Coordinates coordinates,
                VertexOrder order) {
  write_polyhedron_to_file(path, p, format_from_extension(path), coordinates, order);
}

void write_file(const std::filesystem::path& path, const ConvexPolyhedron& p, FileFormat format,
                Coordinates coordinates, VertexOrder order, WriteTimes* times) {
  const auto start = std::chrono::steady_clock::now();
  write_polyhedron_to_file(path, p, format, coordinates, order, times);
  if (times != nullptr) times->total = std::chrono::steady_clock::now() - start;
}

ConvexPolyhedron to_polyhedron(PolygonSoup soup, std::string_view source) {
  try {
    return ConvexPolyhedron::from_soup(std::move(soup));
  } catch (const Error& e) {
    // from_soup's messages name elements of the soup, never its source.
    throw Error(e.category(), std::string(source) + ": " + e.message());
  }
}

ConvexPolyhedron read_polyhedron(const std::filesystem::path& path, const ReadLimits& limits) {
  // read_file's own errors already name the file (and the line).
  return to_polyhedron(read_file(path, limits), path.string());
}

}  // namespace cvms
