// SPDX-License-Identifier: MIT
// PLY reader and writer. The reader takes the header (ply_header.cpp), then
// walks the elements in file order, record by record, property by
// property, through AsciiValues or BinaryValues (ply_values.cpp): x, y and z
// of "vertex" become exact coordinates, the index list of "face" a face,
// everything else is skipped by its size (binary) or checked as numbers and
// dropped (ASCII). Counts were checked against ReadLimits with the header;
// storage grows with the records read, never with a declared count.
//
// The writer writes ASCII with exact decimals (Coordinates::exact), or
// binary little-endian doubles for every rounding mode: a binary double is
// read back as exactly that double, where the shortest decimal of a double
// would be read back (by this exact reader) as the decimal, not the double.
// A rational without a finite decimal expansion (1/3) has no PLY spelling
// at all, so the exact mode refuses it rather than round it silently.
#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <string>

#include "io_reader.hpp"
#include "io_writer.hpp"
#include "ply_header.hpp"
#include "ply_values.hpp"

namespace cvms {
namespace io_detail {
namespace {

// The smallest record of an element in a binary body: its scalars and the
// counts of its lists.
std::uint64_t min_record_size(const PlyElement& e) {
  std::uint64_t size = 0;
  for (const PlyProperty& p : e.properties) size += ply_size(p.is_list ? p.count_type : p.type);
  return size;
}

template <class Values>
class RecordWalk {
 public:
  RecordWalk(Values& values, const PlyHeader& header) : values_(values), header_(header) {}

  PolygonSoup read(PointBuffer& points) {
    for (const PlyElement& e : header_.elements) {
      // A record without properties takes no byte: nothing to walk, however
      // large the count.
      if (e.properties.empty()) continue;
      if (e.name == "vertex")
        read_vertices(e, points);
      else if (e.name == "face")
        read_faces(e);
      else
        skip_element(e);
    }
    values_.finish();
    soup_.points = points.take();
    return std::move(soup_);
  }

 private:
  void read_vertices(const PlyElement& e, PointBuffer& points) {
    for (std::uint64_t v = 0; v < e.count; ++v) {
      Vec3& p = points.append();
      for (const PlyProperty& q : e.properties) {
        const ValueName name{q.name.c_str(), "vertex", v};
        switch (q.role) {
          case PlyRole::x:
            values_.number(q.type, {"x coordinate", "vertex", v}, p.x);
            break;
          case PlyRole::y:
            values_.number(q.type, {"y coordinate", "vertex", v}, p.y);
            break;
          case PlyRole::z:
            values_.number(q.type, {"z coordinate", "vertex", v}, p.z);
            break;
          default:
            skip(q, name);
        }
      }
    }
  }

  void read_faces(const PlyElement& e) {
    soup_.face_offsets.reserve(safe_reserve(e.count) + 1);  // after the leading 0 of an empty soup
    soup_.face_indices.reserve(safe_reserve(e.count) * 3);
    for (std::uint64_t f = 0; f < e.count; ++f) {
      for (const PlyProperty& q : e.properties) {
        if (q.role == PlyRole::vertex_indices)
          read_face(q, f);
        else
          skip(q, {q.name.c_str(), "face", f});
      }
      soup_.face_offsets.push_back(static_cast<std::uint32_t>(soup_.face_indices.size()));
    }
  }

  void read_face(const PlyProperty& q, std::uint64_t f) {
    const std::uint64_t n = values_.count(q.count_type, {"index list", "face", f});
    if (n < 3) values_.fail("face " + std::to_string(f) + " has " + std::to_string(n) + " vertices, at least 3 are needed");
    // More corners than vertices repeat one: refused before the list is read.
    if (n > header_.vertices)
      values_.fail("face " + std::to_string(f) + " lists " + std::to_string(n) + " vertices, more than the " +
                   std::to_string(header_.vertices) + " vertices of the input");
    if (soup_.face_indices.size() + n > std::numeric_limits<std::uint32_t>::max())
      values_.fail("face " + std::to_string(f) + " brings the face indices beyond 2^32-1 in total",
                   ErrorCategory::limit);
    for (std::uint64_t k = 0; k < n; ++k) {
      const std::int64_t index = values_.integer(q.type, {"index", "face", f});
      if (index < 0 || static_cast<std::uint64_t>(index) >= header_.vertices)
        values_.fail("face " + std::to_string(f) + " has index " + std::to_string(index) + " but there are " +
                     std::to_string(header_.vertices) + " vertices");
      soup_.face_indices.push_back(static_cast<std::uint32_t>(index));
    }
  }

  void skip(const PlyProperty& q, const ValueName& name) {
    if (q.is_list)
      values_.skip_list(q, name);
    else
      values_.skip(q.type, name);
  }

  void skip_element(const PlyElement& e) {
    if (Values::is_binary() && e.fixed_size() != 0)
      return values_.skip_records(e.count, e.fixed_size(), "element " + quote(e.name));
    for (std::uint64_t r = 0; r < e.count; ++r)
      for (const PlyProperty& q : e.properties) skip(q, {q.name.c_str(), e.name.c_str(), r});
  }

  Values& values_;
  const PlyHeader& header_;
  PolygonSoup soup_;
};

const PlyElement* vertex_element(const PlyHeader& header) {
  for (const PlyElement& e : header.elements)
    if (e.name == "vertex") return &e;
  return nullptr;
}

PolygonSoup read_ascii_body(std::istream& in, std::string_view source, const ReadLimits& limits,
                            const PlyHeader& header) {
  LineReader reader(in, source, limits, LineReader::Continuation{header.lines, header.bytes});
  // An ASCII vertex holds at least "0 0 0\n".
  constexpr std::uint64_t min_vertex_bytes = 6;
  PointBuffer points(PointBuffer::Declared{reader.reserve_for(header.vertices, min_vertex_bytes)});
  AsciiValues values(reader);
  return RecordWalk<AsciiValues>(values, header).read(points);
}

PolygonSoup read_binary_body(ByteSource& bytes, const PlyHeader& header) {
  std::size_t reserve = safe_reserve(header.vertices);
  if (const std::optional<std::uint64_t> left = bytes.size_at_start(); left) {
    const std::uint64_t record = std::max<std::uint64_t>(min_record_size(*vertex_element(header)), 1);
    reserve = static_cast<std::size_t>(std::min(header.vertices, *left / record + 1));
  }
  PointBuffer points(PointBuffer::Declared{reserve});
  BinaryValues values(bytes, header.encoding == PlyEncoding::binary_big_endian);
  return RecordWalk<BinaryValues>(values, header).read(points);
}

// ---- writing ----

// Whether a rational has a finite decimal expansion: its denominator (in
// lowest terms) has no prime factor but 2 and 5.
bool has_finite_decimal(const Rational& value) {
  mpz_class d = value.get_den();
  mpz_tdiv_q_2exp(d.get_mpz_t(), d.get_mpz_t(), mpz_scan1(d.get_mpz_t(), 0));
  mpz_class five = 5;
  mpz_remove(d.get_mpz_t(), d.get_mpz_t(), five.get_mpz_t());
  return d == 1;
}

void check_decimal(const SoupView& soup) {
  if (soup.packed != nullptr) return;  // dyadic: finite decimals
  for (std::size_t j = 0; j < soup.points.size(); ++j)
    for (int k = 0; k < 3; ++k)
      if (!has_finite_decimal(soup.point(j)[k]))
        throw Error(ErrorCategory::invalid_argument,
                    "vertex " + std::to_string(j) + " has coordinate " + to_string(soup.point(j)[k]).substr(0, 40) +
                        ", which has no finite decimal expansion: PLY holds numbers only (write it rounded to "
                        "doubles, or exactly as OFF or OBJ)");
}

double rounded(const Rational& value) {
  const double d = to_double_nearest(value);
  if (!std::isfinite(d))
    throw Error(ErrorCategory::invalid_argument,
                "coordinate " + to_string(value).substr(0, 40) + " is beyond the range of double");
  return d;
}

// The index list type: uchar counts when every face fits (what most
// readers expect), else uint; int indices unless there are more than 2^31-1 points.
struct FaceLayout {
  bool wide_counts = false;
  bool unsigned_indices = false;
};

FaceLayout face_layout(const SoupView& soup) {
  FaceLayout layout;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) layout.wide_counts |= soup.face(f).size() > 255;
  layout.unsigned_indices = soup.num_points() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max());
  return layout;
}

void write_header(TextWriter& w, const SoupView& soup, bool binary, const FaceLayout& layout) {
  w.text(binary ? "ply\nformat binary_little_endian 1.0\n" : "ply\nformat ascii 1.0\n");
  w.text(binary ? "comment cvms: coordinates rounded to the nearest doubles\n"
                : "comment cvms: exact decimal coordinates\n");
  w.text("element vertex ").integer(soup.num_points()).byte('\n');
  w.text("property double x\nproperty double y\nproperty double z\n");
  w.text("element face ").integer(soup.num_faces()).byte('\n');
  w.text(layout.wide_counts ? "property list uint " : "property list uchar ");
  w.text(layout.unsigned_indices ? "uint vertex_indices\n" : "int vertex_indices\n");
  w.text("end_header\n");
}

void write_ascii_body(TextWriter& w, const SoupView& soup) {
  for (std::size_t j = 0; j < soup.num_points(); ++j) w.point(soup, j, Coordinates::exact).byte('\n');
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    auto face = soup.face(f);
    w.integer(face.size());
    for (std::uint32_t i : face) w.byte(' ').integer(i);
    w.byte('\n');
  }
}

void put_u64_le(TextWriter& w, std::uint64_t bits) {
  w.u32_le(static_cast<std::uint32_t>(bits)).u32_le(static_cast<std::uint32_t>(bits >> 32));
}

void write_binary_body(TextWriter& w, const SoupView& soup, const std::vector<double>& xyz, const FaceLayout& layout) {
  for (double d : xyz) put_u64_le(w, std::bit_cast<std::uint64_t>(d));
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    auto face = soup.face(f);
    if (layout.wide_counts)
      w.u32_le(static_cast<std::uint32_t>(face.size()));
    else
      w.byte(static_cast<char>(face.size()));
    for (std::uint32_t i : face) w.u32_le(i);
  }
}

// Every coordinate rounded, before a byte is written.
std::vector<double> rounded_coordinates(const SoupView& soup) {
  std::vector<double> xyz;
  xyz.reserve(3 * soup.num_points());
  Rational scratch;
  for (std::size_t j = 0; j < soup.num_points(); ++j) {
    for (int k = 0; k < 3; ++k) {
      if (soup.packed == nullptr) {
        xyz.push_back(rounded(soup.point(j)[k]));
        continue;
      }
      detail::unpack_dyadic(soup.packed_coordinate(j, k), scratch);
      xyz.push_back(rounded(scratch));
    }
  }
  return xyz;
}

}  // namespace

void write_ply_view(std::ostream& out, const SoupView& soup, Coordinates coordinates) {
  check_soup_for_writing(soup, 3);
  const FaceLayout layout = face_layout(soup);
  TextWriter w(out);
  if (coordinates == Coordinates::exact) {
    check_decimal(soup);
    write_header(w, soup, false, layout);
    write_ascii_body(w, soup);
  } else {
    const std::vector<double> xyz = rounded_coordinates(soup);
    write_header(w, soup, true, layout);
    write_binary_body(w, soup, xyz, layout);
  }
  w.finish();
}

}  // namespace io_detail

PolygonSoup read_ply(std::istream& in, std::string_view source, const ReadLimits& limits) {
  using namespace io_detail;
  ByteSource bytes(in, source, limits.max_bytes);
  const PlyHeader header = read_ply_header(bytes, limits);
  if (header.encoding == PlyEncoding::ascii) return read_ascii_body(in, source, limits, header);
  return read_binary_body(bytes, header);
}

void write_ply(std::ostream& out, const PolygonSoup& soup, Coordinates coordinates) {
  io_detail::write_ply_view(out, io_detail::SoupView::of(soup), coordinates);
}

}  // namespace cvms
