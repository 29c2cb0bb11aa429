// SPDX-License-Identifier: MIT
// `cvms sum A B [C ...]`: the Minkowski sum of convex sets of any dimension.
// Two polyhedra go through minkowski_sum; flat operands, or more than two,
// through the sum of convex sets. A solid that is not convex, one of two
// operands, goes through solid_sum.hpp (the boundary of A + B as one solid);
// with --pieces, operands that need not be convex go through pieces_sum.hpp
// (the pieces of A + B).
#include <algorithm>
#include <array>
#include <chrono>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "cvms/error.hpp"
#include "cvms/set_sum.hpp"
#include "files.hpp"
#include "keep_until_exit.hpp"
#include "machine_memory.hpp"
#include "options.hpp"
#include "pieces_files.hpp"
#include "pieces_sum.hpp"
#include "placement.hpp"
#include "progress_line.hpp"
#include "reports.hpp"
#include "set_files.hpp"
#include "sizes.hpp"
#include "solid_sum.hpp"
#include "timed_sum.hpp"
#include "usage_error.hpp"

namespace cvms::cli {
namespace {

struct SumArgs {
  std::string a, b, output = "-";
  std::vector<std::string> more;  ///< operands after B
  std::string format;  ///< --format, empty: from the output path
  Algorithm algorithm = Options{}.algorithm;
  unsigned threads = 1;  ///< --threads: Options::threads
  std::string float_output;  ///< --float: empty, "nearest" or "outer"
  bool stats = false;
  bool progress = false;  ///< --progress
  SumLimits limits;  ///< --max-facets, --max-memory
  Placement place_a, place_b;  ///< --rotate-a, --translate-b, --negate-b, ...
  PiecesOptions pieces;  ///< --pieces (pieces_sum.hpp)

  [[nodiscard]] Options options() const {
    Options options;
    options.algorithm = algorithm;
    options.threads = threads;
    options.limits = limits;
    options.progress = progress_callback(progress);
    return options;
  }
};

// --max-facets and --max-memory; `limits` holds the defaults (machine_memory.hpp).
void add_sum_limit_options(CLI::App& command, SumLimits& limits) {
  command.add_option("--max-facets", limits.max_output_facets, "refuse a sum with more output facets")
      ->default_val(limits.max_output_facets)
      ->check(CLI::PositiveNumber);
  add_max_memory_option(command, limits.max_memory_bytes, "an input or a sum whose output");
}

// A limit error names the option that raises it (sizes.hpp).
template <class Sum>
auto with_limit_hint(Sum&& sum) {
  try {
    return sum();
  } catch (const Error& e) {
    rethrow_with_limit_hint(e);
  }
}

// `read_time`: of reading and validating both operands, shown with --stats
// beside the sum's and the write's, so that a whole run's wall time can be
// told apart from the work inside it. The operands' facet planes, made
// before the sum's clock starts, count as reading, and the write shows its
// wait for the disk: the atomic replace's fsync can outweigh the text.
void sum_polyhedra(const ConvexPolyhedron& a, const ConvexPolyhedron& b, const SumArgs& args,
                   std::chrono::steady_clock::duration read_time, std::ostream& report) {
  Timed sum = with_limit_hint([&] { return timed_sum(a, b, args.options()); });
  // Written in an order of the set alone, so that A + B and B + A give the
  // same bytes.
  WriteTimes written;
  write_polyhedron(args.output, sum.result.polyhedron, coordinates_of(args.float_output), args.format,
                   VertexOrder::canonical, &written);
  if (args.stats) {
    report << "A: " << counts(a) << "\nB: " << counts(b) << "\nA+B: " << counts(sum.result.polyhedron)
           << "\nalgorithm: " << to_string(args.algorithm) << "\ntime: " << milliseconds(sum.time)
           << "\nread time: " << milliseconds(read_time + sum.planes_time)
           << " (of it, facet planes time: " << milliseconds(sum.planes_time)
           << ")\nwrite time: " << milliseconds(written.total)
           << " (of it, disk sync time: " << milliseconds(written.sync) << ")\n";
    print_stats(report, sum.result.stats, sum.diagnostics);
  }
  keep_until_exit(std::move(sum.result.polyhedron));
}

void sum_sets(const std::vector<ConvexSet>& operands, const SumArgs& args, std::ostream& report) {
  const auto start = std::chrono::steady_clock::now();
  const ConvexSet sum = with_limit_hint([&] { return minkowski_sum(operands, args.options()); });
  const auto time = std::chrono::steady_clock::now() - start;
  // The order of the operands decides which partial sums are made, and so
  // the numbering of a polyhedron: written in an order of the set alone.
  write_canonical_set(args.output, sum, coordinates_of(args.float_output), args.format);
  if (!args.stats) return;
  for (std::size_t i = 0; i < operands.size(); ++i)
    report << "operand " << i + 1 << ": " << kind(operands[i]) << ", " << size_text(operands[i]) << "\n";
  report << "sum: " << kind(sum) << ", " << size_text(sum) << "\nalgorithm: " << to_string(args.algorithm)
         << "\ntime: " << milliseconds(time) << "\n";
}

// The operands as read: convex sets, and for a sum of two, a solid that is
// not convex in place of its operand (the set there is then empty).
struct Operands {
  std::vector<ConvexSet> sets;
  std::array<std::optional<Solid>, 2> solids;
};

// Moved in one by one: a braced list would copy every operand (its elements
// are const), as costly as a sum on large operands.
Operands read_operands(const SumArgs& args) {
  Operands operands;
  operands.sets.reserve(2 + args.more.size());
  auto read = [&](const std::string& path) {
    if (!args.more.empty()) {
      try {
        return read_set(path);
      } catch (const Error& e) {
        rethrow_explaining_non_convex(e, path, "a sum of more than two operands takes convex sets only");
      }
    }
    const std::size_t index = operands.sets.size();
    SetOrSolid read = read_set_or_solid(path, index == 0 ? args.place_a : args.place_b, index == 0 ? "a" : "b");
    if (read.pieces)
      throw_not_a_convex_set(path, pieces_file_of(*read.pieces), "pass --pieces to sum it as a union of convex pieces");
    if (read.convex_error) throw *read.convex_error;
    operands.solids[index] = std::move(read.solid);
    return std::move(read.set);
  };
  operands.sets.push_back(read(args.a));
  operands.sets.push_back(read(args.b));
  for (const std::string& path : args.more) operands.sets.push_back(read(path));
  return operands;
}

// A + B when an operand is a solid that is not convex: the other one, a
// convex set, must be a polyhedron.
void sum_solids(Operands operands, const SumArgs& args, std::ostream& report) {
  SolidSum sum{args.output,       args.format, args.options(), args.pieces.decomposition,
               args.float_output, args.stats};
  check_solid_sum(sum);
  for (std::size_t i = 0; i < 2; ++i) {
    if (operands.solids[i]) continue;
    const ConvexSet set =
        placed(std::move(operands.sets[i]), i == 0 ? args.place_a : args.place_b, i == 0 ? "a" : "b");
    if (set.dimension() != 3)
      throw Error(ErrorCategory::invalid_argument,
                  input_name(i == 0 ? args.a : args.b) + ": a " + kind(set) +
                      ": a solid that is not convex is summed with polyhedra and solids only");
    operands.solids[i] = Solid::from_polyhedron(set.polyhedron());
  }
  run_solid_sum(*operands.solids[0], *operands.solids[1], sum, report);
  keep_until_exit(std::move(operands));
}

// With stats, the counts, the time and the algorithm's statistics go to report.
void run_sum(const SumArgs& args, std::ostream& report) {
  if (args.pieces.enabled)
    return run_pieces_sum({args.a, args.b, args.output, args.format, !args.more.empty(), args.options(),
                           args.pieces.decomposition, args.place_a, args.place_b, args.float_output, args.stats},
                          report);
  if (args.a == "-" && args.b == "-") throw UsageError("only one input can be read from stdin");
  check_output(args.output, args.format);
  if (std::count(args.more.begin(), args.more.end(), "-") + (args.a == "-") + (args.b == "-") > 1)
    throw UsageError("only one input can be read from stdin");
  check_placement(args.place_a, "a");
  check_placement(args.place_b, "b");
  const auto read_start = std::chrono::steady_clock::now();
  Operands operands = read_operands(args);
  const auto read_time = std::chrono::steady_clock::now() - read_start;
  if (operands.solids[0] || operands.solids[1]) return sum_solids(std::move(operands), args, report);
  std::vector<ConvexSet>& sets = operands.sets;
  sets[0] = placed(std::move(sets[0]), args.place_a, "a");
  sets[1] = placed(std::move(sets[1]), args.place_b, "b");
  if (sets.size() > 2 || sets[0].dimension() != 3 || sets[1].dimension() != 3)
    sum_sets(sets, args, report);
  else
    sum_polyhedra(sets[0].polyhedron(), sets[1].polyhedron(), args, read_time, report);
  keep_until_exit(std::move(sets));
}

}  // namespace

void register_sum(CLI::App& app, Commands& commands) {
  auto args = std::make_shared<SumArgs>();
  args->limits = sum_limits_for_memory(usable_memory_bytes());
  CLI::App* command = app.add_subcommand(
      "sum", "Minkowski sum A + B [+ C ...] of convex sets of any dimension, or A + B of solids");
  add_operands(*command, args->a, args->b);
  command->add_option("C", args->more, "further operands")->check(set_path());
  add_output_options(*command, args->output, args->format, args->float_output);
  add_algorithm_option(*command, args->algorithm);
  command
      ->add_option("--threads", args->threads,
                   "threads for each sum of two polyhedra by cvms and for sums of solids, used where they "
                   "pay (the output is identical)")
      ->check(CLI::Range(1u, 1024u))
      ->default_val(1u);
  command->add_flag("--stats", args->stats, "print counts, time and algorithm statistics");
  add_progress_option(*command, args->progress);
  add_sum_limit_options(*command, args->limits);
  add_placement_options(*command, args->place_a, "a");
  add_placement_options(*command, args->place_b, "b");
  add_pieces_options(*command, args->pieces);
  commands.push_back({command, [args] { run_sum(*args, args->output == "-" ? std::cerr : std::cout); }});
}

}  // namespace cvms::cli
