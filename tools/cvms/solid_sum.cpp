// SPDX-License-Identifier: MIT
// See solid_sum.hpp.
#include "solid_sum.hpp"

#include <chrono>
#include <ostream>
#include <utility>

#include "cvms/solid_sum.hpp"
#include "files.hpp"
#include "keep_until_exit.hpp"
#include "mesh_input.hpp"
#include "pieces_files.hpp"
#include "reports.hpp"
#include "set_files.hpp"
#include "usage_error.hpp"

namespace cvms::cli {
namespace {

std::string solid_counts(const Solid& s) {
  return std::string(s.is_convex() ? "convex" : "not convex") + ", V " + std::to_string(s.vertices().size()) +
         ", facets " + std::to_string(s.num_facets()) + ", shells " + std::to_string(s.num_shells());
}

// The road as the library took it (solid_sum_road).
const char* road(const Solid& a, const Solid& b) {
  switch (solid_sum_road(a, b)) {
    case SolidSumRoad::convex:
      return "convex sum";
    case SolidSumRoad::faces_with_convex:
      return "faces of the solid + the convex operand, united";
    case SolidSumRoad::pieces:
      break;
  }
  return "pairwise sums of convex pieces, united";
}

}  // namespace

SetOrSolid read_set_or_solid(const std::string& path, const Placement& placement, const std::string& operand) {
  SetOrSolid read;
  const bool mesh = is_std_stream(path) || (check_mesh_path(path).empty() && !is_cdd_points_path(path));
  if (!mesh) {
    try {
      read.set = read_set(path);
    } catch (const Error& e) {
      read.convex_error = e;
    }
    return read;
  }
  MeshInput input;
  try {
    input = read_mesh_input(path);
    read.set = set_from_soup(parse_soup(input), is_std_stream(path) ? input_name(path) : path);
    return read;
  } catch (const Error& e) {
    read.convex_error = e;
  }
  const ErrorCategory category = read.convex_error->category();
  if (category != ErrorCategory::not_convex && category != ErrorCategory::topology) return read;
  if (holds_pieces(input)) {
    read.pieces = read_pieces_text(input).size();
    return read;
  }
  PolygonSoup soup = parse_soup(input);
  if (!spans_space(soup)) return read;
  read.convex_error.reset();
  read.solid = solid_from_soup(placed(std::move(soup), placement, operand), input_name(path));
  return read;
}

void check_solid_sum(const SolidSum& sum) {
  if (sum.float_output == "outer")
    throw UsageError(
        "--float outer writes convex sets only: the sum of a solid that is not convex is written "
        "exactly or with --float nearest");
}

void run_solid_sum(const Solid& a, const Solid& b, const SolidSum& sum, std::ostream& report) {
  const auto start = std::chrono::steady_clock::now();
  Solid result;
  try {
    result = minkowski_sum(a, b, sum.options, sum.decomposition);
  } catch (const Error& e) {
    rethrow_with_pieces_limit_hint(e);
  }
  const auto time = std::chrono::steady_clock::now() - start;
  write_soup(sum.output, result.to_soup(), coordinates_of(sum.float_output), sum.format);
  if (sum.stats)
    report << "A: solid, " << solid_counts(a) << "\nB: solid, " << solid_counts(b) << "\nA+B: solid, "
           << solid_counts(result) << "\nroad: " << road(a, b) << "\ntime: " << milliseconds(time) << "\n";
  keep_until_exit(std::move(result));
}

}  // namespace cvms::cli
