// SPDX-License-Identifier: MIT
// cdd's H- and V-representation files and the plain half-space text form
// (cvms/halfspace_io.hpp), on the bounded line reader of the io layer.
#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <deque>
#include <fstream>
#include <limits>
#include <ostream>
#include <string>
#include <system_error>

#include "cvms/halfspace_io.hpp"
#include "file_output.hpp"
#include "io_reader.hpp"

namespace cvms {

namespace {

using io_detail::LineReader;
using io_detail::Tokenizer;

constexpr const char* number_names[4] = {"first number", "second number", "third number", "fourth number"};

// The numbers of one cdd row: exactly `columns` (3 in the plane, 4 in
// space), parsed in place.
void read_row(LineReader& reader, std::string_view line, std::uint64_t index, const char* element, int columns,
              std::array<Rational, 4>& row) {
  Tokenizer tokens(line, false);
  const std::string count = std::to_string(columns);
  for (int k = 0; k < columns; ++k) {
    const std::string_view token = tokens.next();
    if (token.empty()) reader.fail(std::string(element) + " " + std::to_string(index) + " has fewer than " + count + " numbers");
    io_detail::parse_number(reader, token, {number_names[k], element, index}, row[static_cast<std::size_t>(k)]);
  }
  if (!tokens.at_end()) reader.fail(std::string(element) + " " + std::to_string(index) + " has more than " + count + " numbers");
}

// The numbers of one row of a plain file, whose dimension its first row
// sets: `columns` is 0 before that row and then the count every later row
// must have. `low` and `high` are the counts of the plane and of space.
void read_plain_row(LineReader& reader, std::string_view line, std::uint64_t index, const char* element, int low,
                    int high, int& columns, std::array<Rational, 4>& row) {
  Tokenizer tokens(line, false);
  int k = 0;
  for (std::string_view token = tokens.next(); !token.empty(); token = tokens.next(), ++k) {
    if (k == high) reader.fail(std::string(element) + " " + std::to_string(index) + " has more than " + std::to_string(high) + " numbers");
    io_detail::parse_number(reader, token, {number_names[k], element, index}, row[static_cast<std::size_t>(k)]);
  }
  if (k < low) reader.fail(std::string(element) + " " + std::to_string(index) + " has fewer than " + std::to_string(low) + " numbers");
  if (columns == 0) columns = k;
  if (k != columns) {
    reader.fail(std::string(element) + " " + std::to_string(index) + " has " + std::to_string(k) + " numbers, row 1 has " +
                std::to_string(columns) + ": a file is in the plane (" + std::to_string(low) + " numbers a row) or in space (" +
                std::to_string(high) + ") throughout");
  }
}

bool is_comment_or_blank(std::string_view line) {
  const auto first = line.find_first_not_of(" \t\r");
  return first == std::string_view::npos || line[first] == '*';
}

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

// Whether token is `word` (given in lower case) in any case, without the
// string lower() makes: asked once per row ("end"?).
bool is_word(std::string_view token, std::string_view word) {
  return token.size() == word.size() &&
         std::equal(token.begin(), token.end(), word.begin(),
                    [](unsigned char t, char w) { return std::tolower(t) == static_cast<unsigned char>(w); });
}

// The rows of a cdd file and its linearity indices (1-based, checked). A
// deque: rows are parsed in place and never relocated (a vector's growth
// would copy them all, as a Rational's move may allocate; the header's
// count is not trusted for a reservation).
struct CddBody {
  std::deque<std::array<Rational, 4>> rows;
  int columns = 4;  ///< 4 in space, 3 in the plane z = 0
  std::vector<std::uint64_t> linearity;
};

// Numbers are quoted as written: parse_unsigned saturates at 2^64-1, which
// would misreport a larger one. An index of 2^64-1 or more is never a row
// (the header's count is at most a ReadLimits count).
void read_linearity(LineReader& reader, Tokenizer& tokens, CddBody& body) {
  const std::string_view count_token = tokens.next();
  const auto count = io_detail::parse_unsigned(count_token);
  if (!count) reader.fail("linearity: expected the number of indices");
  const std::string announced = io_detail::typed(count_token);
  for (std::uint64_t i = 0; i < *count; ++i) {
    const std::string_view token = tokens.next();
    const auto index = io_detail::parse_unsigned(token);
    if (!index) reader.fail("linearity: expected " + announced + " row indices");
    if (*index == std::numeric_limits<std::uint64_t>::max())
      reader.fail("linearity index " + io_detail::typed(token) + " is not a row");
    body.linearity.push_back(*index);
  }
  if (!tokens.at_end()) reader.fail("linearity: more indices than the " + announced + " announced");
}

CddBody read_cdd(LineReader& reader, const char* wanted, const char* other, std::uint64_t max_rows,
                 const char* element) {
  CddBody body;
  std::string_view line;
  bool begun = false;
  while (reader.next(line)) {
    if (is_comment_or_blank(line)) continue;
    Tokenizer tokens(line, false);
    const std::string word = lower(tokens.next());
    if (word == "begin") {
      begun = true;
      break;
    }
    if (word == lower(other)) reader.fail(std::string("this is a ") + other + ", expected a " + wanted);
    if (word == "linearity") read_linearity(reader, tokens, body);
    // Anything else before begin is a name or a cdd option: ignored.
  }
  if (!begun) {
    if (reader.line_number() == 0) reader.fail("empty input (no 'begin' line)");
    reader.fail("no 'begin' line");
  }
  std::uint64_t declared = 0;
  for (;;) {
    if (!reader.next(line)) reader.fail("end of input before the 'm n type' line");
    if (is_comment_or_blank(line)) continue;
    Tokenizer tokens(line, false);
    const std::string_view m = tokens.next(), n = tokens.next();
    const std::string type = lower(tokens.next());
    const auto rows = io_detail::parse_unsigned(m);
    if (!rows || (n != "4" && n != "3") || (type != "integer" && type != "rational" && type != "real") ||
        !tokens.at_end()) {
      reader.fail("expected 'm 4 integer|rational|real' (3-D: 4 columns; 2-D: 3), got " + io_detail::quote(line));
    }
    body.columns = n == "3" ? 3 : 4;
    if (*rows > max_rows) reader.fail("header announces " + io_detail::typed(m) + " rows, beyond the limit", ErrorCategory::limit);
    declared = *rows;
    break;
  }
  bool ended = false;
  while (reader.next(line)) {
    if (is_comment_or_blank(line)) continue;
    if (is_word(Tokenizer(line, false).next(), "end")) {
      ended = true;
      break;
    }
    if (body.rows.size() == declared) reader.fail("more rows than the " + std::to_string(declared) + " of the header");
    const std::uint64_t index = body.rows.size() + 1;  // before the row is added
    read_row(reader, line, index, element, body.columns, body.rows.emplace_back());
  }
  if (!ended) reader.fail("no 'end' line");
  if (body.rows.size() != declared) {
    reader.fail(std::to_string(body.rows.size()) + " rows before 'end', the header says " + std::to_string(declared));
  }
  while (reader.next(line)) {
    if (is_comment_or_blank(line)) continue;
    Tokenizer tokens(line, false);
    if (lower(tokens.next()) == "linearity") read_linearity(reader, tokens, body);
  }
  for (const std::uint64_t i : body.linearity) {
    if (i == 0 || i > declared) reader.fail("linearity index " + std::to_string(i) + " is not a row (1 to " + std::to_string(declared) + ")");
  }
  return body;
}

// Appends the row a·x <= b whose numbers are in `numbers` (a in the columns
// normal[0..2], where -1 stands for a zero coefficient, b in column
// `offset`), taking them over: a row default-constructed in place and
// swapped with them makes one fresh Rational per number, where building a
// row from moved numbers and moving it into the vector makes two or three (a
// moved-from Rational is re-initialised, which allocates).
void take_row(std::array<Rational, 4>& numbers, const int (&normal)[3], int offset, std::vector<HalfspaceRow>& rows) {
  HalfspaceRow& row = rows.emplace_back();
  for (int m = 0; m < 3; ++m)
    if (normal[m] >= 0) mpq_swap(row.normal[m].get_mpq_t(), numbers[static_cast<std::size_t>(normal[m])].get_mpq_t());
  mpq_swap(row.offset.get_mpq_t(), numbers[static_cast<std::size_t>(offset)].get_mpq_t());
}

// The rows of a file of the plane describe a polygon in z = 0 (the file
// comment of cvms/halfspace_io.hpp): that plane is one more equality.
HalfspaceFile in_dimension(HalfspaceSystem system, int columns_in_space, int columns) {
  HalfspaceFile file;
  file.dimension = columns == columns_in_space ? 3 : 2;
  if (file.dimension == 2) system.equalities.insert(system.equalities.begin(), HalfspaceRow{{0, 0, 1}, 0});
  file.system = std::move(system);
  return file;
}

HalfspaceFile read_cdd_halfspaces(LineReader& reader) {
  CddBody body = read_cdd(reader, "H-representation", "V-representation", reader.limits().max_faces, "row");
  std::vector<bool> equality(body.rows.size(), false);
  for (const std::uint64_t i : body.linearity) equality[i - 1] = true;
  HalfspaceSystem system;
  // Counted, not trusted from the header: a reallocation would copy every
  // row (a Rational's move may allocate, so vector growth copies).
  const auto equalities = static_cast<std::size_t>(std::count(equality.begin(), equality.end(), true));
  system.equalities.reserve(equalities + 1);
  system.inequalities.reserve(body.rows.size() - equalities);
  const int columns = body.columns;
  for (std::size_t i = 0; i < body.rows.size(); ++i) {
    auto& r = body.rows[i];
    // a = −c, negated in place: a negated copy would allocate every number again.
    for (std::size_t k = 1; k < static_cast<std::size_t>(columns); ++k) mpq_neg(r[k].get_mpq_t(), r[k].get_mpq_t());
    auto& rows = equality[i] ? system.equalities : system.inequalities;
    if (columns == 4)
      take_row(r, {1, 2, 3}, 0, rows);
    else
      take_row(r, {1, 2, -1}, 0, rows);
  }
  return in_dimension(std::move(system), 4, columns);
}

// A plain file of rows (a b c d, or a b c in the plane) or of points (x y z,
// or x y in the plane), `high` or `high - 1` numbers a row, parsed in place
// into a deque, then moved once into vectors reserved from the count read
// (as read_cdd: no relocation copies). At most `max_rows` rows.
struct PlainBody {
  std::deque<std::array<Rational, 4>> rows;
  int columns = 0;
};

PlainBody read_plain(LineReader& reader, const char* element, int high, std::uint64_t max_rows) {
  PlainBody body;
  std::string_view line;
  while (reader.next(line)) {
    if (Tokenizer(line).at_end()) continue;
    if (body.rows.size() >= max_rows) reader.fail(std::string("more ") + element + "s than the limit", ErrorCategory::limit);
    const auto end = line.find('#');
    const std::uint64_t index = body.rows.size() + 1;  // before the row is added
    read_plain_row(reader, line.substr(0, end), index, element, high - 1, high, body.columns, body.rows.emplace_back());
  }
  // No rows would be the whole space (or no points): an empty or truncated
  // file, not a set.
  if (body.rows.empty()) {
    if (reader.line_number() == 0) reader.fail(std::string("empty input (no ") + element + "s)");
    reader.fail(std::string("no ") + element + "s, only comments and blank lines");
  }
  return body;
}

HalfspaceFile read_plain_halfspaces(LineReader& reader) {
  PlainBody body = read_plain(reader, "row", 4, reader.limits().max_faces);
  HalfspaceSystem system;
  system.equalities.reserve(1);
  system.inequalities.reserve(body.rows.size());
  for (std::array<Rational, 4>& r : body.rows) {
    if (body.columns == 4)
      take_row(r, {0, 1, 2}, 3, system.inequalities);
    else
      take_row(r, {0, 1, -1}, 2, system.inequalities);
  }
  return in_dimension(std::move(system), 4, body.columns);
}

std::ifstream open_for_reading(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw Error(ErrorCategory::io, "cannot read '" + path.string() + "': it is a directory");
  }
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    const int error = errno;
    throw Error(ErrorCategory::io, "cannot open '" + path.string() + "'" +
                                       (error != 0 ? ": " + std::generic_category().message(error) : std::string()));
  }
  return in;
}

bool all_integers(const HalfspaceSystem& system) {
  const auto integer = [](const HalfspaceRow& r) {
    return r.normal.x.get_den() == 1 && r.normal.y.get_den() == 1 && r.normal.z.get_den() == 1 && r.offset.get_den() == 1;
  };
  return std::all_of(system.equalities.begin(), system.equalities.end(), integer) &&
         std::all_of(system.inequalities.begin(), system.inequalities.end(), integer);
}

// Ends a writer: the flushed stream's state. A stream that failed on the
// way (a full disk, a buffer that could not grow) sets its badbit and
// swallows the cause, so that a writer that does not look would report
// lost output as written.
void finish_output(std::ostream& out) {
  try {
    out.flush();
  } catch (const std::ios_base::failure&) {
    throw Error(ErrorCategory::io, "writing the output failed");
  }
  if (!out) throw Error(ErrorCategory::io, "writing the output failed");
}

void write_plain_row(std::ostream& out, const Vec3& a, const Rational& b, int dimension) {
  out << to_string(a.x) << ' ' << to_string(a.y) << ' ';
  if (dimension == 3) out << to_string(a.z) << ' ';
  out << to_string(b) << '\n';
}

void write_cdd_row(std::ostream& out, const HalfspaceRow& r, int dimension) {
  out << to_string(r.offset) << ' ' << to_string(-r.normal.x) << ' ' << to_string(-r.normal.y);
  if (dimension == 3) out << ' ' << to_string(-r.normal.z);
  out << '\n';
}

// Row `r` of a set in the plane z = 0, restricted to that plane (z's
// coefficient dropped, which changes nothing on the plane), primitive, and
// appended unless it holds on the whole plane (0 <= b with b >= 0, 0 == 0)
// or repeats a row already there (restricted equalities of a segment or a
// point may coincide). The set is the intersection of its rows, and all of
// its points have z = 0, so the restricted rows describe it within the plane.
void append_in_plane(const HalfspaceRow& r, bool equality, std::vector<HalfspaceRow>& rows) {
  HalfspaceRow p = primitive_row(HalfspaceRow{{r.normal.x, r.normal.y, 0}, r.offset});
  const bool flat = sgn(p.normal.x) == 0 && sgn(p.normal.y) == 0;
  if (flat && (equality ? sgn(p.offset) == 0 : sgn(p.offset) >= 0)) return;
  if (std::find(rows.begin(), rows.end(), p) != rows.end()) return;
  rows.push_back(std::move(p));
}

HalfspaceSystem in_plane(const HalfspaceSystem& system) {
  HalfspaceSystem plane;
  for (const HalfspaceRow& r : system.equalities) append_in_plane(r, true, plane.equalities);
  for (const HalfspaceRow& r : system.inequalities) append_in_plane(r, false, plane.inequalities);
  return plane;
}

void check_dimension(int dimension) {
  if (dimension != 2 && dimension != 3)
    throw Error(ErrorCategory::invalid_argument, "a file's dimension is 2 or 3, not " + std::to_string(dimension));
}

// The vertices of a set written to a file of the plane: each must lie in it.
std::vector<Vec3> vertices_in(const ConvexSet& set, int dimension) {
  check_dimension(dimension);
  std::vector<Vec3> v = set.vertices();
  if (dimension == 2)
    for (const Vec3& p : v)
      if (sgn(p.z) != 0)
        throw Error(ErrorCategory::invalid_argument, "vertex (" + to_string(p.x) + ", " + to_string(p.y) + ", " +
                                                         to_string(p.z) + ") is not in the plane z = 0 of a 2-D file");
  return v;
}

bool integer_points(const std::vector<Vec3>& v) {
  return std::all_of(v.begin(), v.end(), [](const Vec3& p) {
    return p.x.get_den() == 1 && p.y.get_den() == 1 && p.z.get_den() == 1;
  });
}

void write_system(std::ostream& out, const HalfspaceSystem& system, HalfspaceFormat format, int dimension) {
  if (format == HalfspaceFormat::plain) {
    out << (dimension == 3 ? "# a b c d: a*x + b*y + c*z <= d\n" : "# a b c: a*x + b*y <= c\n");
    for (const HalfspaceRow& r : system.equalities) {
      write_plain_row(out, r.normal, r.offset, dimension);
      write_plain_row(out, -r.normal, -r.offset, dimension);
    }
    for (const HalfspaceRow& r : system.inequalities) write_plain_row(out, r.normal, r.offset, dimension);
    return;
  }
  out << "H-representation\n";
  if (!system.equalities.empty()) {
    out << "linearity " << system.equalities.size();
    for (std::size_t i = 1; i <= system.equalities.size(); ++i) out << ' ' << i;
    out << '\n';
  }
  out << "begin\n"
      << system.equalities.size() + system.inequalities.size() << ' ' << dimension + 1 << ' '
      << (all_integers(system) ? "integer" : "rational") << '\n';
  for (const HalfspaceRow& r : system.equalities) write_cdd_row(out, r, dimension);
  for (const HalfspaceRow& r : system.inequalities) write_cdd_row(out, r, dimension);
  out << "end\n";
}

}  // namespace

HalfspaceFormat halfspace_format_from_extension(const std::filesystem::path& path) {
  return lower(path.extension().string()) == ".ine" ? HalfspaceFormat::cdd : HalfspaceFormat::plain;
}

HalfspaceFile read_halfspaces_of_any_dimension(std::istream& in, HalfspaceFormat format, std::string_view source,
                                               const ReadLimits& limits) {
  LineReader reader(in, source, limits);
  return format == HalfspaceFormat::cdd ? read_cdd_halfspaces(reader) : read_plain_halfspaces(reader);
}

HalfspaceSystem read_halfspaces(std::istream& in, HalfspaceFormat format, std::string_view source,
                                const ReadLimits& limits) {
  return read_halfspaces_of_any_dimension(in, format, source, limits).system;
}

HalfspaceFile read_halfspace_file_of_any_dimension(const std::filesystem::path& path, const ReadLimits& limits) {
  std::ifstream in = open_for_reading(path);
  return read_halfspaces_of_any_dimension(in, halfspace_format_from_extension(path), path.string(), limits);
}

HalfspaceSystem read_halfspace_file(const std::filesystem::path& path, const ReadLimits& limits) {
  return read_halfspace_file_of_any_dimension(path, limits).system;
}

void write_halfspaces(std::ostream& out, const HalfspaceSystem& system, HalfspaceFormat format, int dimension) {
  check_dimension(dimension);
  if (dimension == 3)
    write_system(out, system, format, 3);
  else
    write_system(out, in_plane(system), format, 2);
  finish_output(out);
}

void write_halfspace_file(const std::filesystem::path& path, const HalfspaceSystem& system, int dimension) {
  check_dimension(dimension);
  const HalfspaceFormat format = halfspace_format_from_extension(path);
  io_detail::write_atomically(path, [&](std::ostream& out) { write_halfspaces(out, system, format, dimension); });
}

PointFile read_cdd_points_of_any_dimension(std::istream& in, std::string_view source, const ReadLimits& limits) {
  LineReader reader(in, source, limits);
  const CddBody body = read_cdd(reader, "V-representation", "H-representation", limits.max_vertices, "vertex");
  if (!body.linearity.empty()) reader.fail("linearity in a V-representation describes lines: unbounded sets are not supported");
  PointFile file;
  file.dimension = body.columns - 1;
  file.points.reserve(body.rows.size());
  for (std::size_t i = 0; i < body.rows.size(); ++i) {
    const auto& r = body.rows[i];
    if (r[0] != 1) {
      throw Error(ErrorCategory::parse, std::string(source) + ": vertex " + std::to_string(i + 1) +
                                            (r[0] == 0 ? " is a ray (first number 0): unbounded sets are not supported"
                                                       : " does not start with 1"));
    }
    file.points.push_back(Vec3{r[1], r[2], file.dimension == 3 ? r[3] : Rational(0)});
  }
  return file;
}

std::vector<Vec3> read_cdd_points(std::istream& in, std::string_view source, const ReadLimits& limits) {
  return read_cdd_points_of_any_dimension(in, source, limits).points;
}

void write_cdd_points(std::ostream& out, const ConvexSet& set, int dimension) {
  const std::vector<Vec3> v = vertices_in(set, dimension);
  out << "V-representation\nbegin\n"
      << v.size() << ' ' << dimension + 1 << ' ' << (integer_points(v) ? "integer" : "rational") << '\n';
  for (const Vec3& p : v) {
    out << "1 " << to_string(p.x) << ' ' << to_string(p.y);
    if (dimension == 3) out << ' ' << to_string(p.z);
    out << '\n';
  }
  out << "end\n";
  finish_output(out);
}

void write_cdd_points_file(const std::filesystem::path& path, const ConvexSet& set, int dimension) {
  check_dimension(dimension);
  if (dimension == 2) (void)vertices_in(set, dimension);  // before the file is touched
  io_detail::write_atomically(path, [&](std::ostream& out) { write_cdd_points(out, set, dimension); });
}

PointFile read_plain_points(std::istream& in, std::string_view source, const ReadLimits& limits) {
  LineReader reader(in, source, limits);
  PlainBody body = read_plain(reader, "point", 3, limits.max_vertices);
  PointFile file;
  file.dimension = body.columns;
  file.points.reserve(body.rows.size());
  for (auto& r : body.rows) {
    Vec3& p = file.points.emplace_back();
    mpq_swap(p.x.get_mpq_t(), r[0].get_mpq_t());
    mpq_swap(p.y.get_mpq_t(), r[1].get_mpq_t());
    if (file.dimension == 3) mpq_swap(p.z.get_mpq_t(), r[2].get_mpq_t());
  }
  return file;
}

void write_plain_points(std::ostream& out, const ConvexSet& set, int dimension) {
  const std::vector<Vec3> v = vertices_in(set, dimension);
  if (v.empty()) throw Error(ErrorCategory::invalid_argument, "the empty set has no points to write (write its half-spaces)");
  for (const Vec3& p : v) {
    out << to_string(p.x) << ' ' << to_string(p.y);
    if (dimension == 3) out << ' ' << to_string(p.z);
    out << '\n';
  }
  finish_output(out);
}

void write_plain_points_file(const std::filesystem::path& path, const ConvexSet& set, int dimension) {
  check_dimension(dimension);
  if (dimension == 2) (void)vertices_in(set, dimension);  // before the file is touched
  if (set.empty())
    throw Error(ErrorCategory::invalid_argument, path.string() + ": the empty set has no points to write (write its half-spaces)");
  io_detail::write_atomically(path, [&](std::ostream& out) { write_plain_points(out, set, dimension); });
}

}  // namespace cvms
