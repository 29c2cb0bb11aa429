// SPDX-License-Identifier: MIT
// The memory budget of the tool's inputs (see input_memory.hpp).
#include "input_memory.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <limits>
#include <string_view>

#include "cvms/error.hpp"
#include "files.hpp"
#include "machine_memory.hpp"

namespace cvms::cli {
namespace {

// What the inputs read so far took from memory_budget().
std::uint64_t& taken() {
  static std::uint64_t bytes = 0;
  return bytes;
}

std::uint64_t left_of_budget() { return memory_budget() - std::min(taken(), memory_budget()); }

std::string beyond_budget(std::uint64_t left) {
  std::string text = "beyond ";
  if (left != memory_budget()) text += std::to_string(left) + " bytes left of ";
  return text + "the memory limit of " + std::to_string(memory_budget()) +
         " bytes; raise it with --max-memory";
}

}  // namespace

std::uint64_t memory_per_input_byte(InputCost cost) { return cost == InputCost::mesh ? 144 : 256; }

std::uint64_t estimated_input_memory(std::uint64_t input_bytes, InputCost cost) {
  constexpr std::uint64_t max = std::numeric_limits<std::uint64_t>::max();
  const std::uint64_t per_byte = memory_per_input_byte(cost);
  return input_bytes > max / per_byte ? max : input_bytes * per_byte;
}

std::uint64_t& memory_budget() {
  static std::uint64_t bytes = sum_limits_for_memory(usable_memory_bytes()).max_memory_bytes;
  return bytes;
}

ReadLimits input_read_limits(const std::string& path, InputCost cost) {
  ReadLimits limits = read_limits();
  const std::uint64_t left = left_of_budget();
  struct stat info {};
  const bool regular = !is_std_stream(path) && ::stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode);
  const auto size = regular ? static_cast<std::uint64_t>(info.st_size) : 0;
  // A file beyond --max-bytes gets the reader's own message, which names that option.
  if (regular && size > limits.max_bytes) return limits;
  limits.max_bytes = std::min(limits.max_bytes, left / memory_per_input_byte(cost));
  if (!regular) return limits;
  const std::uint64_t estimate = estimated_input_memory(size, cost);
  if (estimate > left)
    throw Error(ErrorCategory::limit, path + ": an input of " + std::to_string(size) +
                                          " bytes is estimated to need up to " + std::to_string(estimate) +
                                          " bytes of memory (" + std::to_string(memory_per_input_byte(cost)) +
                                          " per byte), " + beyond_budget(left));
  taken() += estimate;
  return limits;
}

void rethrow_with_memory_hint(const Error& e, const ReadLimits& limits, InputCost cost) {
  const std::string_view message = e.message();
  if (e.category() != ErrorCategory::limit || limits.max_bytes >= read_limits().max_bytes ||
      message.find("input is larger than the limit of " + std::to_string(limits.max_bytes) + " bytes") ==
          std::string_view::npos)
    throw e;
  throw Error(e.category(), std::string(message) + " (" + std::to_string(memory_per_input_byte(cost)) +
                                " bytes of memory per byte of input, " + beyond_budget(left_of_budget()) +
                                ")");
}

}  // namespace cvms::cli
