// SPDX-License-Identifier: MIT
// Entry point of the `cvms` command-line tool: parses the command line with
// CLI11 and maps outcomes to exit codes: 0 success, 1 bad input (one line on
// stderr, from the library's Error), 2 usage.
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <new>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "commands.hpp"
#include "machine_memory.hpp"
#include "cvms/error.hpp"
#include "files.hpp"
#include "heap_pages.hpp"
#include "sizes.hpp"
#include "halfspace_commands.hpp"
#include "proximity_commands.hpp"

namespace {

constexpr int exit_bad_input = 1;
constexpr int exit_usage = 2;

// One line, whatever the message holds, and no control bytes: a file name
// with terminal escape codes is shown as \x1b[..., never run.
std::string one_line(const std::string& text) { return cvms::cli::printable(text); }

const CLI::Validator mesh_path{cvms::cli::check_mesh_path, "FILE(.off|.obj|.stl|-)", "mesh path"};

// A decimal integer from 0 to 2^64-1, digits only (no sign, no exponent):
// CLI11 alone would wrap "-1" and saturate 2^64 silently.
std::string check_unsigned_64(const std::string& text) {
  constexpr std::string_view max = "18446744073709551615";
  const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
  std::string_view value = text;
  while (value.size() > 1 && value.front() == '0') value.remove_prefix(1);
  if (!digits || value.size() > max.size() || (value.size() == max.size() && value > max))
    return "'" + text + "' is not an integer from 0 to 18446744073709551615";
  return {};
}
const CLI::Validator unsigned_64{check_unsigned_64, "UINT64", "unsigned 64-bit integer"};

// -o, --format and --float of a command that writes a polyhedron. The
// output is checked when the command runs (its format may come from
// --format), before any work.
void add_output_options(CLI::App& command, std::string& output, std::string& format, bool& float_output) {
  command.add_option("-o,--output", output, "result file (default -, OFF on stdout)")->default_str("-");
  command
      .add_option("--format", format,
                  "off, obj or stl (default: the output's extension; OFF for - and /dev/null, /dev/stdout, ...)")
      ->check(CLI::IsMember({"off", "obj", "stl"}, CLI::ignore_case));
  command.add_flag("--float", float_output, "round output coordinates to the nearest double");
}

// Options of every command that reads (before or after the command name).
void add_read_limit_options(CLI::App& app) {
  cvms::ReadLimits& limits = cvms::cli::read_limits();
  app.add_option("--max-bytes", limits.max_bytes, "largest input read, in bytes")
      ->check(unsigned_64)
      ->default_str(std::to_string(limits.max_bytes));
  app.add_option("--max-line-bytes", limits.max_line_bytes, "longest line of a text input, in bytes")
      ->check(unsigned_64)
      ->default_str(std::to_string(limits.max_line_bytes));
}

constexpr cvms::Algorithm algorithms[] = {cvms::Algorithm::cvms, cvms::Algorithm::essdms,
                                          cvms::Algorithm::chms};

CLI::Option* add_algorithm_option(CLI::App& command, cvms::Algorithm& algorithm, const char* default_text) {
  std::vector<std::string> names;
  for (cvms::Algorithm a : algorithms) names.emplace_back(cvms::to_string(a));
  return command
      .add_option_function<std::string>(
          "--algorithm",
          [&algorithm](const std::string& name) {
            for (cvms::Algorithm a : algorithms)
              if (name == cvms::to_string(a)) algorithm = a;
          },
          "cvms, essdms or chms")
      ->transform(CLI::IsMember(names, CLI::ignore_case))
      ->default_str(default_text);
}

// --max-facets and --max-memory of sum; `limits` holds the defaults (machine_memory.hpp).
void add_sum_limit_options(CLI::App& command, cvms::SumLimits& limits) {
  command.add_option("--max-facets", limits.max_output_facets, "refuse a sum with more output facets")
      ->default_val(limits.max_output_facets)
      ->check(CLI::PositiveNumber);
  command
      .add_option_function<std::string>(
          "--max-memory",
          [&limits](const std::string& text) { limits.max_memory_bytes = cvms::cli::parse_byte_size(text); },
          "refuse a sum whose output is estimated to need more memory (bytes, or 512M, 4G, ...; "
          "at most half of this machine's memory by default)")
      ->check([](const std::string& text) {
        try {
          cvms::cli::parse_byte_size(text);
          return std::string();
        } catch (const std::invalid_argument& e) {
          return std::string(e.what());
        }
      })
      ->default_str(cvms::cli::format_byte_size(limits.max_memory_bytes));
}

}  // namespace

int main(int argc, char** argv) {
  using namespace cvms::cli;
  prefer_huge_heap_pages();
  CLI::App app{"cvms: exact Minkowski sums of convex polyhedra (OFF/OBJ/STL; '-' is OFF on stdin/stdout)"};
  app.require_subcommand(1);
  app.fallthrough();  // the read limits may follow the command name too
  add_read_limit_options(app);
  const char* default_algorithm = cvms::to_string(cvms::Options{}.algorithm);

  SumArgs sum;
  sum.limits = sum_limits_for_memory(usable_memory_bytes());
  CLI::App* sum_cmd = app.add_subcommand("sum", "Minkowski sum A + B [+ C ...] of convex sets of any dimension");
  sum_cmd->add_option("A", sum.a, "first operand")->required()->check(mesh_path);
  sum_cmd->add_option("B", sum.b, "second operand")->required()->check(mesh_path);
  sum_cmd->add_option("C", sum.more, "further operands")->check(mesh_path);
  add_output_options(*sum_cmd, sum.output, sum.format, sum.float_output);
  add_algorithm_option(*sum_cmd, sum.algorithm, default_algorithm);
  sum_cmd
      ->add_option(
          "--threads", sum.threads,
          "threads for each sum of two polyhedra by cvms, used where they pay (the output is identical)")
      ->check(CLI::Range(1u, 1024u))
      ->default_val(1u);
  sum_cmd->add_flag("--stats", sum.stats, "print counts, time and algorithm statistics");
  add_sum_limit_options(*sum_cmd, sum.limits);

  HullArgs hull;
  CLI::App* hull_cmd = app.add_subcommand("hull", "exact convex hull of points");
  CLI::Option* hull_points =
      hull_cmd->add_option("POINTS", hull.input, "OFF/OBJ/STL vertices or one 'x y z' per line")->required();
  add_output_options(*hull_cmd, hull.output, hull.format, hull.float_output);

  GenArgs gen;
  std::string shape_list;
  for (const char* s : gen_shapes) shape_list += std::string(shape_list.empty() ? "" : " ") + s;
  CLI::App* gen_cmd = app.add_subcommand("gen", "write a built-in shape");
  gen_cmd->add_option("SHAPE", gen.shape, shape_list + " (box is [0,1]x[0,2]x[0,3], prism has height 2)")
      ->required()
      ->check(CLI::IsMember(std::vector<std::string>(std::begin(gen_shapes), std::end(gen_shapes))));
  CLI::Option* subdivisions_opt =
      gen_cmd->add_option("--subdivisions", gen.subdivisions, "K for Sphere_K (1..9)")
          ->check(CLI::Range(1, 9));
  CLI::Option* seed_opt =
      gen_cmd->add_option("--seed", gen.seed, "seed of random and zonotope (0 to 2^64-1)")->check(unsigned_64);
  gen_cmd
      ->add_option("--points", gen.points,
                   "points of random (4.." + std::to_string(max_random_points) + ", default 100), sides of prism (3.." +
                       std::to_string(max_prism_sides) + ", default 6)")
      ->check(CLI::Range(1, max_random_points));
  gen_cmd->add_option("--generators", gen.generators, "generators of zonotope (default 10)")
      ->check(CLI::Range(1, 100'000));
  add_output_options(*gen_cmd, gen.output, gen.format, gen.float_output);

  std::string check_input;
  CLI::App* check_cmd =
      app.add_subcommand("check", "validate a convex set, print its dimension, V E F and facet degrees");
  check_cmd->add_option("F", check_input, "the file")->required()->check(mesh_path);

  DemoArgs demo;
  CLI::App* demo_cmd = app.add_subcommand("demo", "Cube + Sphere4 with counts and time");
  add_algorithm_option(*demo_cmd, demo.algorithm, default_algorithm);

  ProximityArgs proximity;
  add_proximity_commands(app, proximity, mesh_path);

  HalfspaceArgs halfspace;
  add_halfspace_commands(app, *hull_cmd, *hull_points, hull, halfspace, mesh_path);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e);  // prints help, or the error with a hint
    return code == 0 ? 0 : exit_usage;
  }

  try {
    if (run_proximity_command(proximity, std::cout)) return 0;
    if (run_halfspace_command(halfspace, std::cout)) return 0;
    if (*sum_cmd)
      run_sum(sum, sum.output == "-" ? std::cerr : std::cout);
    else if (*hull_cmd)
      run_hull(hull);
    else if (*gen_cmd) {
      gen.subdivisions_given = subdivisions_opt->count() > 0;
      gen.seed_given = seed_opt->count() > 0;
      run_gen(gen);
    } else if (*check_cmd)
      run_check(check_input, std::cout);
    else if (*demo_cmd)
      run_demo(demo, std::cout);
  } catch (const UsageError& e) {
    std::cerr << "cvms: " << one_line(e.what()) << "\nRun with --help for more information.\n";
    return exit_usage;
  } catch (const cvms::Error& e) {
    std::cerr << "cvms: " << one_line(e.what()) << "\n";
    return exit_bad_input;
  } catch (const std::bad_alloc&) {
    std::cerr << "cvms: out of memory\n";
    return exit_bad_input;
  } catch (const std::exception& e) {
    std::cerr << "cvms: internal error: " << one_line(e.what()) << "\n";
    return exit_bad_input;
  }
  return 0;
}
