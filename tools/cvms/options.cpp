// SPDX-License-Identifier: MIT
// Options shared by several commands (see options.hpp).
#include "options.hpp"

#include <stdexcept>
#include <string_view>
#include <vector>

#include "files.hpp"
#include "input_memory.hpp"
#include "set_files.hpp"
#include "sizes.hpp"

namespace cvms::cli {
namespace {

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

constexpr Algorithm algorithms[] = {Algorithm::cvms, Algorithm::essdms, Algorithm::chms};

}  // namespace

const CLI::Validator& mesh_path() {
  static const CLI::Validator validator{check_mesh_path, "FILE(.off|.obj|.stl|.ply|.ext|-)", "mesh path"};
  return validator;
}

const CLI::Validator& unsigned_64() {
  static const CLI::Validator validator{check_unsigned_64, "UINT64", "unsigned 64-bit integer"};
  return validator;
}

void add_read_limit_options(CLI::App& app) {
  ReadLimits& limits = read_limits();
  app.add_option("--max-bytes", limits.max_bytes, "largest input read, in bytes")
      ->check(unsigned_64())
      ->default_str(std::to_string(limits.max_bytes));
  app.add_option("--max-line-bytes", limits.max_line_bytes, "longest line of a text input, in bytes")
      ->check(unsigned_64())
      ->default_str(std::to_string(limits.max_line_bytes));
}

void add_operands(CLI::App& command, std::string& a, std::string& b) {
  command.add_option("A", a, "first operand")->required()->check(set_path());
  command.add_option("B", b, "second operand")->required()->check(set_path());
}

void add_float_option(CLI::App& command, std::string& float_output) {
  // A flag, not an option with an optional value: `--float A.off` must not
  // take A.off for the mode. The mode goes after '=': --float=outer.
  command
      .add_flag("--float{nearest}", float_output,
                "write doubles: --float or --float=nearest, a valid convex set near the exact one; "
                "--float=outer, one that contains it")
      ->check(CLI::IsMember({"nearest", "outer"}))
      ->option_text("[=nearest|outer]");
}

void add_output_options(CLI::App& command, std::string& output, std::string& format, std::string& float_output) {
  command.add_option("-o,--output", output, "result file (default -, OFF on stdout)")->default_str("-");
  command
      .add_option("--format", format,
                  "off, obj, stl or ply (default: the output's extension; OFF for - and /dev/null, /dev/stdout, ...)")
      ->check(CLI::IsMember({"off", "obj", "stl", "ply"}, CLI::ignore_case));
  add_float_option(command, float_output);
}

void add_max_memory_option(CLI::App& command, std::uint64_t& bytes, const std::string& what) {
  command
      .add_option_function<std::string>(
          "--max-memory",
          [&bytes](const std::string& text) {
            bytes = parse_byte_size(text);
            memory_budget() = bytes;
          },
          "refuse " + what +
              " is estimated to need more memory (bytes, or 512M, 4G, ...; by default half of "
              "this machine's memory or of the address-space limit, ulimit -v, at most 4G)")
      ->check([](const std::string& text) {
        try {
          parse_byte_size(text);
          return std::string();
        } catch (const std::invalid_argument& e) {
          return std::string(e.what());
        }
      })
      ->default_str(format_byte_size(bytes));
}

void add_input_memory_option(CLI::App& command) {
  add_max_memory_option(command, memory_budget(), "an input that");
}

void add_algorithm_option(CLI::App& command, Algorithm& algorithm) {
  std::vector<std::string> names;
  for (Algorithm a : algorithms) names.emplace_back(to_string(a));
  command
      .add_option_function<std::string>(
          "--algorithm",
          [&algorithm](const std::string& name) {
            for (Algorithm a : algorithms)
              if (name == to_string(a)) algorithm = a;
          },
          "cvms, essdms or chms")
      ->transform(CLI::IsMember(names, CLI::ignore_case))
      ->default_str(to_string(Options{}.algorithm));
}

}  // namespace cvms::cli
