// SPDX-License-Identifier: MIT
// See solid_sum.hpp.
#include "solid_sum.hpp"

#include <chrono>
#include <ostream>
#include <utility>

#include "cvms/solid_sum.hpp"
#include "files.hpp"
#include "keep_until_exit.hpp"
#include "pieces_files.hpp"
#include "reports.hpp"
#include "usage_error.hpp"

namespace cvms::cli {
namespace {

std::string solid_counts(const Solid& s) {
  return std::string(s.is_convex() ? "convex" : "not convex") + ", V " + std::to_string(s.vertices().size()) +
         ", facets " + std::to_string(s.num_facets()) + ", shells " + std::to_string(s.num_shells());
}

const char* road(const Solid& a, const Solid& b) {
  if (a.is_convex() && b.is_convex()) return "convex sum";
  if (a.is_convex() || b.is_convex()) return "faces of the solid + the convex operand, united";
  return "pairwise sums of convex pieces, united";
}

}  // namespace

std::optional<Solid> read_non_convex_solid(const Error& convex_error, const std::string& path,
                                           const Placement& placement, const std::string& operand) {
  const bool shape_error = convex_error.category() == ErrorCategory::not_convex ||
                           convex_error.category() == ErrorCategory::topology;
  if (!shape_error || is_std_stream(path) || !check_mesh_path(path).empty() || is_cdd_points_path(path) ||
      is_pieces_path(path))
    return std::nullopt;
  PolygonSoup soup = read_soup(path);
  if (!spans_space(soup)) return std::nullopt;
  return solid_from_soup(placed(std::move(soup), placement, operand), input_name(path));
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
