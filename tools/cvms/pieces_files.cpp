// SPDX-License-Identifier: MIT
// See pieces_files.hpp.
#include "pieces_files.hpp"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "cvms/error.hpp"
#include "cvms/predicates.hpp"
#include "cvms/union_io.hpp"
#include "files.hpp"
#include "sizes.hpp"
#include "usage_error.hpp"

namespace cvms::cli {
namespace {

// Whether a line starting at `it` is an `o` statement.
template <class It>
bool object_line(It it, It end) {
  while (it != end && (*it == ' ' || *it == '\t')) ++it;
  if (it == end || *it != 'o') return false;
  ++it;
  return it == end || *it == ' ' || *it == '\t' || *it == '\n' || *it == '\r';
}

std::string describe(const Solid& solid) {
  return "a solid with " + std::to_string(solid.num_reflex_edges()) + " reflex edge" +
         (solid.num_reflex_edges() == 1 ? "" : "s");
}

// Line by line in one pass, without holding a line: two `o` statements end it.
template <class It>
bool has_two_objects(It it, It end) {
  int objects = 0;
  while (it != end) {
    if (object_line(it, end) && ++objects == 2) return true;
    while (it != end && *it != '\n') ++it;
    if (it != end) ++it;
  }
  return false;
}

}  // namespace

bool is_pieces_path(const std::string& path) {
  if (is_std_stream(path) || lower_extension(path) != ".obj") return false;
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  return has_two_objects(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

bool is_pieces_text(std::string_view text) { return has_two_objects(text.begin(), text.end()); }

ConvexUnion read_pieces_file(const std::string& path) {
  return read_within_budget(path, InputCost::mesh,
                            [&](const ReadLimits& limits) { return read_pieces(std::filesystem::path(path), limits); });
}

Solid solid_from_soup(PolygonSoup soup, const std::string& source) {
  try {
    return Solid::from_soup(std::move(soup));
  } catch (const Error& e) {
    throw Error(e.category(), source + ": " + e.message());
  }
}

bool spans_space(const PolygonSoup& soup) {
  const auto& p = soup.points;
  std::size_t second = 1, third = 0;
  while (second < p.size() && p[second] == p[0]) ++second;
  for (std::size_t i = second + 1; i < p.size() && third == 0; ++i)
    if (cross(p[second] - p[0], p[i] - p[0]) != Vec3{}) third = i;
  if (third == 0) return false;
  for (std::size_t i = third + 1; i < p.size(); ++i)
    if (orient3d(p[0], p[second], p[third], p[i]) != Sign::zero) return true;
  return false;
}

ConvexUnion read_union_operand(const std::string& path, const DecompositionOptions& options) {
  if (is_pieces_path(path)) return read_pieces_file(path);
  return decompose_soup(read_soup(path), path, options);
}

ConvexUnion decompose_soup(PolygonSoup soup, const std::string& path, const DecompositionOptions& options) {
  const Solid solid = solid_from_soup(std::move(soup), input_name(path));
  try {
    return convex_decomposition(solid, options);
  } catch (const Error& e) {
    try {
      rethrow_with_pieces_limit_hint(e);
    } catch (const Error& hinted) {
      throw Error(hinted.category(), input_name(path) + ": " + hinted.message());
    }
  }
}

void rethrow_explaining_non_convex(const Error& convex_error, const std::string& path, std::string_view hint) {
  const bool shape_error =
      convex_error.category() == ErrorCategory::not_convex || convex_error.category() == ErrorCategory::topology;
  const bool mesh_file = !is_std_stream(path) && check_mesh_path(path).empty() && !is_cdd_points_path(path);
  if (!shape_error || !mesh_file) throw convex_error;
  std::string what;
  if (is_pieces_path(path)) {
    what = pieces_file_of(read_pieces_file(path).size());
  } else {
    PolygonSoup soup = read_soup(path);
    if (!spans_space(soup)) throw convex_error;
    what = describe(solid_from_soup(std::move(soup), input_name(path)));
  }
  throw_not_a_convex_set(path, what, hint);
}

void throw_not_a_convex_set(const std::string& path, const std::string& what, std::string_view hint) {
  throw Error(ErrorCategory::not_convex, input_name(path) + ": " + what + ", not a convex set: " + std::string(hint));
}

std::string pieces_file_of(std::size_t count) { return "a pieces file of " + std::to_string(count) + " convex pieces"; }

void check_pieces_output(const std::string& path) {
  const bool device = path.rfind("/dev/", 0) == 0 && std::filesystem::path(path).extension().empty();
  if (!is_std_stream(path) && !device && lower_extension(path) != ".obj")
    throw UsageError("'" + printable(path) + "': pieces are written as OBJ objects: expected '-' or a file ending in .obj");
  check_output_directory(path);
}

void write_pieces_output(const std::string& path, const ConvexUnion& pieces, Coordinates coordinates) {
  if (!is_std_stream(path)) return write_pieces(std::filesystem::path(path), pieces, coordinates);
  write_stdout([&](std::ostream& out) { write_pieces(out, pieces, coordinates); });
}

void add_decomposition_limit_options(CLI::App& command, DecompositionLimits& limits) {
  command.add_option("--max-pieces", limits.max_pieces, "refuse a decomposition into more convex pieces")
      ->default_val(limits.max_pieces)
      ->check(CLI::PositiveNumber);
  command
      .add_option_function<std::string>(
          "--max-decomposition-memory",
          [&limits](const std::string& text) { limits.max_memory_bytes = parse_byte_size(text); },
          "refuse a decomposition estimated to need more working memory (bytes, or 512M, 4G, ...)")
      ->default_str(format_byte_size(limits.max_memory_bytes))
      ->check([](const std::string& text) {
        try {
          (void)parse_byte_size(text);
          return std::string();
        } catch (const std::invalid_argument& e) {
          return std::string(e.what());
        }
      });
}

void rethrow_with_pieces_limit_hint(const Error& e) {
  const std::string_view message = e.message();
  if (e.category() == ErrorCategory::limit && message.rfind("convex_decomposition:", 0) == 0) {
    if (message.find("max_pieces") != std::string_view::npos)
      throw Error(e.category(), std::string(message) + "; raise it with --max-pieces");
    throw Error(e.category(), std::string(message) + "; raise it with --max-decomposition-memory");
  }
  rethrow_with_limit_hint(e);
}

}  // namespace cvms::cli
