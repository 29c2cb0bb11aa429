// SPDX-License-Identifier: MIT
/// \file
/// Exact readers and writers for OFF, OBJ, STL and PLY. Readers never trust a count
/// in a header for allocation beyond what the input can hold, and report every
/// malformation as Error(parse) naming the source and line (text) or byte
/// offset (binary). Writers write exact coordinates unless asked otherwise.
///
/// For convex polyhedra, one call each way (the format is the extension's):
/// \code
/// cvms::ConvexPolyhedron p = cvms::read_polyhedron("part.obj");  // read + validate
/// cvms::write_file("part.off", p);                               // exact coordinates
/// \endcode
/// The soup-level functions below (read_file, read_off, ..., write_off) are for
/// meshes that are not, or not yet, convex polyhedra, and for streams.
///
/// What the readers accept and reject (each case has a test in test/io_*_test.cpp):
///  - Numbers are parsed exactly (try_parse_rational): integers, decimals with
///    an optional exponent, and p/q ("1e400" is the exact integer 10^400). A
///    number token longer than ReadLimits::max_number_chars, an exponent
///    beyond +-100000, a numerator or denominator beyond
///    ReadLimits::max_number_bits and numbers beyond
///    ReadLimits::max_number_bits_per_byte in all raise Error(limit) naming
///    the line and the token. "nan", "inf", "1.#INF", "-1.#IND", "1.#QNAN"
///    and the like raise Error(parse) naming the line. Ignored values
///    (colors, normals, OBJ w) follow the same rules.
///  - Text formats are line based; '\n' and "\r\n" end lines (an error on a
///    line that holds a carriage return says that one alone ends no line). A
///    NUL byte in a text format is Error(parse) naming its line and byte
///    offset, raised as soon as it is read (so /dev/zero ends at once); a
///    line longer than ReadLimits::max_line_bytes is Error(limit). Messages name
///    "<source>:<line>: ..." with 1-based lines, OFF vertices/faces 0-based,
///    OBJ vertices/faces 1-based (as in the file); binary STL messages name
///    "<source>: byte <offset>: ...".
///  - A 0-byte input is Error(parse) "empty input"; one with only blanks and
///    comments is Error(parse) "unexpected end of input" (OFF, points) or "no
///    OBJ statements"; an OBJ without any `v` is Error(parse). A header
///    declaring zero elements is fine and gives an empty soup (Mesh::from_soup
///    rejects it later). A leading UTF-8 byte order mark is skipped.
///  - Faces with fewer than 3 vertices and face indices out of range are
///    Error(parse) naming the line. Repeated indices and other topological
///    problems are left to Mesh::from_soup.
///  - A count in a header above ReadLimits raises Error(limit) at once, even
///    if the input is too short to hold it; a count within the limits that the
///    input does not hold raises Error(parse) "unexpected end of input" naming
///    the line. Nothing is reserved beyond a small fixed amount before the data
///    is actually read.
///  - OFF: the header keyword is [ST][C][N]OFF (4OFF, nOFF and "OFF BINARY"
///    are rejected); the counts "V F [E]" are free-form: on the keyword's
///    line or on lines of their own (E on F's line, or alone on the next
///    one); E is ignored. One vertex per line: x y z, followed by exactly the values the
///    prefixes announce (ST: 2, C: 3 or 4, N: 3), which are ignored; a plain OFF
///    vertex line with a 4th value is rejected (it may be homogeneous). One face
///    per line: n i_1 .. i_n, then up to 4 numeric color values (ignored).
///    After the last face only blanks and comments may follow; anything else
///    is rejected (a header that undercounts is not silently truncated).
///  - OBJ: `v x y z`, `v x y z w` with w exactly 1 (any other w is rejected,
///    since OBJ's w is a rational-curve weight, not a homogeneous divisor),
///    `v x y z r g b` (colors ignored). `f` takes i, i/t, i//n, i/t/n with
///    positive (possibly forward) or negative (relative) indices, never 0.
///    vt, vn, vp, g, o, s, mg, usemtl, mtllib, usemap, maplib, l, p, bevel,
///    c_interp, d_interp, lod, shadow_obj, trace_obj, call are ignored;
///    free-form geometry (cstype, curv, surf, ...) and unknown statements are
///    rejected. Line continuation with '\' is not supported.
///  - STL: the input is read whole (bounded by max_bytes). It is binary iff it
///    is at least 84 bytes long and exactly 84 + 50 n bytes for the n in its
///    header, even if the header starts with "solid"; otherwise it is ASCII if
///    it starts with "solid", else a binary file whose size does not match its
///    count (Error(parse) naming the byte offset where it is truncated or where
///    the extra bytes start). Non-finite float32 coordinates are rejected; the
///    normals and attribute bytes are ignored. ASCII keywords are matched
///    case-insensitively; several solids in one file are concatenated.
///  - PLY: a header ("ply", "format ascii|binary_little_endian|binary_big_endian
///    1.0", comment, obj_info, element and property lines, "end_header"),
///    then the body. Element "vertex" must have scalar properties x, y
///    and z of any PLY type (char uchar short ushort int uint float double,
///    or int8 ... float64); element "face", if present, a list property
///    vertex_indices or vertex_index of an integer count and index type.
///    Other properties (normals, colors, lists) and other elements are
///    skipped: by size in binary, checked to be numbers in ASCII (NaN and
///    infinity allowed there, since only coordinates are refused for
///    them). ASCII values are tokens across lines, parsed exactly as the
///    other readers do; an ASCII value of an integer type must be an
///    integer in its range. A binary float or double is its exact dyadic
///    value, NaN and infinity refused. The vertex and face counts are
///    checked against ReadLimits on their header line; the header as a
///    whole is bounded by ReadLimits::max_line_bytes. A list count below 3
///    or an index outside the vertices is Error(parse); nothing may follow
///    the last element. Messages name "<source>:<line>: ..." for the header
///    and ASCII bodies, "<source>: byte <offset>: ..." for binary bodies,
///    with vertices and faces 0-based.
///  - Memory stays within a small multiple of the input size and of
///    max_line_bytes: a line is buffered whole, so a single 100 MB line costs
///    about 100-300 MB (set max_line_bytes lower to refuse such inputs early).
///    STL, read whole, reads no more than a binary file's declared size plus
///    1 MiB when the input does not start with "solid". Each number
///    costs about 100 bytes however short its text (a GMP rational and two
///    heap blocks), so one-digit coordinates cost about 48 times their text;
///    the digits of all numbers take at most 32 bytes per input byte
///    (max_number_bits_per_byte). Points are never copied while reading.
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

#include "cvms/convex_polyhedron.hpp"
#include "cvms/float_mesh.hpp"
#include "cvms/polygon_soup.hpp"

namespace cvms {

/// Caps that protect against absurd or lying inputs; exceeding one raises
/// Error(limit).
struct ReadLimits {
  std::uint64_t max_vertices = 50'000'000;           ///< points in a soup (never more than 2^32-1)
  std::uint64_t max_faces = 100'000'000;             ///< faces (STL: triangles) in a soup
  std::uint64_t max_bytes = std::uint64_t{4} << 30;  ///< 4 GiB
  /// Longest line of a text format (OFF, OBJ, points, ASCII STL), in bytes;
  /// a longer one raises Error(limit) as soon as it is seen. A line is
  /// buffered whole, so this bounds the reader's buffer: at most about 3
  /// times the limit is allocated while the buffer grows (by doubling). A
  /// 1,000,000-index face needs about 8 MB, three numbers of
  /// max_number_chars 3 MB.
  std::uint64_t max_line_bytes = std::uint64_t{256} << 20;
  /// Longest accepted number token (digits of one coordinate). Exact values
  /// of a million digits are far beyond anything an exact computation on
  /// sane inputs produces, and parsing them costs superlinear time.
  std::uint64_t max_number_chars = std::uint64_t{1} << 20;
  /// Bits of the numerator and of the denominator of one number, in lowest
  /// terms (p/q: as written). Read off the digit count and the exponent
  /// before the number is built, so "1e99999" (7 bytes, a 332,000-bit
  /// integer) costs nothing. Every double fits with room to spare: its exact
  /// value needs at most 1024 bits above and 1075 below (the 751-digit exact
  /// expansion of 2^-1074), its shortest decimal at most about 1130 below
  /// (4.9406564584124654e-324 is 49406564584124654 / 10^340), 1e-300 and
  /// 1e300 need 997, an exact sum of doubles about 2100.
  std::uint64_t max_number_bits = 4096;
  /// Bits of all the numbers of an input together (numerators plus
  /// denominators, colors and normals included), per byte of the input read
  /// so far; never less than 2^20 bits in all. Honest text stays far below:
  /// "1e308 " is 1025 bits in 6 bytes (171 per byte), "1 " 2 bits in 2.
  /// Bounds the digits of the numbers to 32 bytes per byte of input.
  std::uint64_t max_number_bits_per_byte = 256;
};

/// The mesh file formats cvms reads and writes.
enum class FileFormat {
  off,  ///< Object File Format (.off), the exact format of choice
  obj,  ///< Wavefront OBJ (.obj), vertices and faces only
  stl,  ///< STL (.stl): ASCII or binary on input, binary float32 on output
  ply   ///< PLY (.ply): ASCII or binary on input; ASCII exact or binary doubles on output (write_ply)
};

/// The format named by a path's extension (.off .obj .stl .ply, any case).
/// \throw Error(invalid_argument) for anything else.
FileFormat format_from_extension(const std::filesystem::path& path);

/// Reads an OFF mesh (see the file comment for what is accepted).
/// `source` names the input in error messages (a file name, "<stdin>").
/// \throw Error(parse) naming source and line for malformed input;
/// \throw Error(limit) when a count or number exceeds `limits`.
/// Complexity: linear in the input size (number parsing is exact).
PolygonSoup read_off(std::istream& in, std::string_view source, const ReadLimits& limits = {});
/// Reads the vertices and faces of an OBJ file; as read_off otherwise.
/// \throw Error(parse), Error(limit) as read_off; lines and indices are 1-based.
PolygonSoup read_obj(std::istream& in, std::string_view source, const ReadLimits& limits = {});
/// ASCII or binary STL (detected from the content); float32 coordinates are
/// converted exactly; vertices shared between triangles are merged by exact position.
/// \throw Error(parse) naming the line (ASCII) or byte offset (binary);
/// \throw Error(limit) beyond `limits` (the input is read whole, up to max_bytes).
/// Complexity: O(n log n) in the input size whatever the values (vertices
/// merged by sorting: binary by float bits, ASCII in a balanced tree).
PolygonSoup read_stl(std::istream& in, std::string_view source, const ReadLimits& limits = {});
/// Reads a PLY mesh, ASCII or binary of either byte order (see the file
/// comment); points without a face element give a soup without faces.
/// \throw Error(parse) naming the line (header, ASCII body) or byte offset
///   (binary body);
/// \throw Error(limit) for a vertex or face count beyond `limits` (on its
///   header line, before anything is allocated for it), a header longer
///   than max_line_bytes, an input beyond max_bytes, and as read_off for
///   ASCII numbers.
/// Complexity: linear in the input size.
PolygonSoup read_ply(std::istream& in, std::string_view source, const ReadLimits& limits = {});
/// Dispatches to read_off, read_obj, read_stl or read_ply; their errors.
PolygonSoup read(std::istream& in, FileFormat format, std::string_view source, const ReadLimits& limits = {});
/// Reads a file in the format of its extension, naming it in error messages.
/// \throw Error(invalid_argument) for an unknown extension (format_from_extension);
/// \throw Error(io) if it cannot be opened; the reader's errors otherwise.
PolygonSoup read_file(const std::filesystem::path& path, const ReadLimits& limits = {});

/// Points only, for hulls: OFF/OBJ/PLY vertices or one "x y z" per line
/// ('#' comments and blank lines allowed). The format is chosen by the first
/// token: an OFF keyword, an OBJ statement (v, vt, vn, f, o, g, s, mtllib,
/// usemtl), a first byte 'p' (PLY, read with read_ply), or else a point list. An OFF or OBJ input is read whole (faces
/// are checked like read_off/read_obj do, then dropped).
/// \throw Error(parse), Error(limit) as the readers.
std::vector<Vec3> read_points(std::istream& in, std::string_view source, const ReadLimits& limits = {});

/// How writers print coordinates.
///
/// The two double modes differ from rounding each vertex, which may leave a
/// polyhedron that is no longer convex: a convex polyhedron or set is first
/// rounded as a whole by round_to_doubles (cvms/float_mesh.hpp), whose
/// exact hull of double points has maximal, exactly planar facets in those
/// doubles. The doubles are printed as the shortest decimals that read back
/// to them (std::to_chars), so a reader that parses the text as doubles gets
/// exactly that valid set. Read back by cvms, the text is that decimal
/// exactly ("0.1" is 1/10), not the double itself. A soup, which need not be
/// convex, is rounded vertex by vertex with double_ and refused with
/// double_outer. Binary STL holds float32 and rounds each vertex to float32
/// whatever is asked, except that double_outer is refused there.
enum class Coordinates {
  exact,    ///< exact decimals or p/q, see to_string(const Rational&)
  double_,  ///< FloatMode::nearest: the hull of the nearest doubles (a soup: each vertex's nearest double)
  double_outer  ///< FloatMode::outer: a double polyhedron that contains the exact set (convex sets only)
};

/// How the polyhedron writers number vertices and facets.
enum class VertexOrder {
  as_is,  ///< the polyhedron's own numbering, that of p.to_soup() (no extra work)
  /// One that depends on the set alone, not on how it was computed: the
  /// vertices in lexicographic order of their exact coordinates (x, then y,
  /// then z), each facet starting at its smallest vertex number
  /// (orientation kept), the facets sorted by their vertex numbers. Equal
  /// polyhedra are written as equal bytes (a sum A + B as B + A). In
  /// doubles, the same order of the rounded vertices. Costs a sort of the
  /// vertices (compared by their doubles, exactly on ties) and of the facets,
  /// without copying a coordinate.
  canonical
};

/// Writes an OFF file: the header, one "x y z" line per point, one
/// "n i_1 .. i_n" line per face. Writers take any soup whose faces have >= 3
/// indices, all in range. Numbers are formatted without the stream's locale,
/// so the bytes depend only on the soup; with Coordinates::exact, reading the
/// output back gives the same soup exactly.
/// \throw Error(invalid_argument) for a face with fewer than 3 indices or an
///   index out of range, for a coordinate beyond the double range with
///   Coordinates::double_, and for Coordinates::double_outer (a soup need
///   not be convex: write the convex set instead);
/// \throw Error(io) if the stream fails.
/// Complexity: linear in the size of the output.
void write_off(std::ostream& out, const PolygonSoup& soup, Coordinates coordinates = Coordinates::exact);
/// Writes `v x y z` and `f i j k ...` lines (1-based indices); as write_off otherwise.
/// \throw Error(invalid_argument), Error(io) as write_off.
void write_obj(std::ostream& out, const PolygonSoup& soup, Coordinates coordinates = Coordinates::exact);
/// Binary STL with fan-triangulated faces (float32, so always rounded).
/// \throw Error(invalid_argument) as write_off, and for a coordinate beyond
///   the float32 range; \throw Error(io) if the stream fails.
void write_stl(std::ostream& out, const PolygonSoup& soup);
/// Writes a PLY file with element "vertex" (double x, y, z) and element
/// "face" (a list of uchar counts, uint beyond 255 vertices, and int
/// indices). With Coordinates::exact: ASCII, every coordinate as its exact
/// decimal, so that read_ply gives back the same soup exactly (readers that
/// parse to doubles get the nearest doubles); a coordinate without a finite
/// decimal expansion (1/3: PLY has no p/q) is refused. With any other
/// Coordinates: binary little-endian, each coordinate rounded to the
/// nearest double, so that read_ply gives back exactly those doubles.
/// \throw Error(invalid_argument) as write_off, and for a coordinate
///   without a finite decimal expansion with Coordinates::exact;
/// \throw Error(io) if the stream fails.
/// Complexity: linear in the size of the output.
void write_ply(std::ostream& out, const PolygonSoup& soup, Coordinates coordinates = Coordinates::exact);
/// Dispatches to write_off, write_obj, write_stl (which ignores
/// `coordinates`) or write_ply; their errors.
void write(std::ostream& out, const PolygonSoup& soup, FileFormat format,
           Coordinates coordinates = Coordinates::exact);
/// Writes a polyhedron's vertices and facets (those of p.to_soup()) to a
/// stream, read straight from the polyhedron (no copy of its coordinates);
/// as write(out, p.to_soup(), format, coordinates) otherwise. In doubles
/// (OFF, OBJ), those of round_to_doubles(p, mode): the exact hull of double
/// points, written as write(out, rounded.to_soup(), format,
/// Coordinates::double_) writes it. `order` numbers the vertices and facets
/// written (VertexOrder::canonical: the same bytes for equal polyhedra).
/// \throw Error(invalid_argument) as write_off and round_to_doubles, and
///   for Coordinates::double_outer in STL; \throw Error(io) as write_off.
void write(std::ostream& out, const ConvexPolyhedron& p, FileFormat format,
           Coordinates coordinates = Coordinates::exact, VertexOrder order = VertexOrder::as_is);
/// Writes a file in the format of its extension (format_from_extension).
/// The write is atomic: the bytes go to a new temporary file in the target's
/// directory (".<name>.cvms-<random>.tmp"), which is renamed over the target
/// only once it is complete and closed; on any failure (a coordinate the
/// format cannot hold, a full disk) the temporary is removed and an
/// existing file is left byte-identical. The new file gets the mode of the
/// file it replaces (which must be writable: a read-only file is refused,
/// not replaced), or that of any new file (0666 less the umask); through
/// a symlink, the file it names is replaced. A target that is not a regular
/// file (/dev/null, a FIFO, a terminal) is written in place, and
/// /dev/stdout, /dev/stderr, /dev/fd/N and /proc/self/fd/N through the
/// descriptor they name (so a redirection's O_APPEND is kept).
/// \throw Error(invalid_argument) for an unknown extension, and as the writers
///   with the message prefixed by "<path>: ";
/// \throw Error(io) "cannot write '<path>': <reason>" if the target is a
///   directory, the temporary file cannot be created (an unwritable
///   directory), or a write, close or rename fails (the reason is the
///   system's, e.g. "No space left on device").
void write_file(const std::filesystem::path& path, const PolygonSoup& soup,
                Coordinates coordinates = Coordinates::exact);
/// As write_file(path, soup, coordinates), in the given format whatever the
/// path's extension (for paths without one, such as /dev/stdout).
/// \throw Error(invalid_argument), Error(io) as write_file.
void write_file(const std::filesystem::path& path, const PolygonSoup& soup, FileFormat format,
                Coordinates coordinates = Coordinates::exact);
/// Writes a polyhedron's vertices and facets (p.to_soup()) to a file in the
/// format of its extension, atomically (see write_file for soups); with
/// Coordinates::exact and OFF, OBJ or PLY (whose exact writer refuses a
/// coordinate without a finite decimal), read_polyhedron gives back the
/// same polyhedron. `order` numbers the vertices and facets written
/// (VertexOrder::canonical: the same bytes for equal polyhedra).
/// \throw Error(invalid_argument) for an unknown extension, and (naming the
///   file) for a coordinate beyond the double range with Coordinates::double_
///   or double_outer, for double_outer in STL, or for a coordinate beyond the
///   float32 range in STL; an existing file is left untouched;
/// \throw Error(io) naming the file and the reason if it cannot be written.
/// Complexity: linear in the size of the output.
void write_file(const std::filesystem::path& path, const ConvexPolyhedron& p,
                Coordinates coordinates = Coordinates::exact, VertexOrder order = VertexOrder::as_is);
/// Where the time of one write_file call went, for a caller's report (such as
/// `cvms sum --stats`): the atomic replace waits for the disk, which can take
/// longer than making the text.
struct WriteTimes {
  /// The whole call: the text or bytes made and written, then synchronised.
  std::chrono::nanoseconds total{0};
  /// Of it, waiting for the disk: fsync of the new file before it replaces
  /// the target, the rename, and the fsync of the directory. Zero for a
  /// target written in place (a device, a FIFO, a descriptor's alias).
  std::chrono::nanoseconds sync{0};
};

/// As write_file(path, p, coordinates, order), in the given format whatever
/// the path's extension; with `times`, fills it in once the file is written.
/// \throw Error(invalid_argument), Error(io) as write_file.
void write_file(const std::filesystem::path& path, const ConvexPolyhedron& p, FileFormat format,
                Coordinates coordinates = Coordinates::exact, VertexOrder order = VertexOrder::as_is,
                WriteTimes* times = nullptr);

/// Reads a file in the format of its extension (read_file) and validates it
/// as a convex polyhedron (ConvexPolyhedron::from_soup, which also merges
/// coplanar faces and drops vertices that are not corners). Every error
/// names the file.
/// \throw Error(invalid_argument) for an unknown extension;
/// \throw Error(io) if the file cannot be opened or is a directory;
/// \throw Error(parse), Error(limit) as the reader, naming the file and the
///   line or byte offset;
/// \throw Error(topology), Error(not_convex), Error(degenerate) (and the
///   other errors of from_soup) if the mesh is not a convex polyhedron, the
///   message prefixed by "<path>: " and naming the face, edge or vertex
///   (0-based, in file order).
/// Complexity: linear in the input size, plus from_soup's.
ConvexPolyhedron read_polyhedron(const std::filesystem::path& path, const ReadLimits& limits = {});

/// ConvexPolyhedron::from_soup for a soup read from `source` (a file name,
/// "<stdin>"), with "<source>: " in front of the message of every error:
/// from_soup names faces, edges and vertices but cannot know the file. For a
/// soup from a stream, or one whose counts the caller reads before
/// validating; read_polyhedron does this for files.
/// \throw Error as from_soup (topology, not_convex, degenerate, ...), same
///   category, the message prefixed by "<source>: ".
ConvexPolyhedron to_polyhedron(PolygonSoup soup, std::string_view source);

}  // namespace cvms
