// SPDX-License-Identifier: MIT
// Byte sizes with binary suffixes (see sizes.hpp).
#include "sizes.hpp"

#include <cctype>
#include <limits>
#include <stdexcept>
#include <string_view>

namespace cvms::cli {

std::uint64_t parse_byte_size(const std::string& text) {
  const std::string bad = "'" + text + "' is not a size (an integer, optionally followed by K, M, G or T)";
  std::size_t i = 0;
  std::uint64_t value = 0;
  constexpr std::uint64_t max = std::numeric_limits<std::uint64_t>::max();
  for (; i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])); ++i) {
    const auto digit = static_cast<std::uint64_t>(text[i] - '0');
    if (value > (max - digit) / 10) throw std::invalid_argument("'" + text + "' does not fit 64 bits");
    value = value * 10 + digit;
  }
  if (i == 0) throw std::invalid_argument(bad);
  std::string suffix = text.substr(i);
  for (char& c : suffix) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (suffix.empty() || suffix == "B") return value;
  int shift = 0;
  switch (suffix[0]) {
    case 'K':
      shift = 10;
      break;
    case 'M':
      shift = 20;
      break;
    case 'G':
      shift = 30;
      break;
    case 'T':
      shift = 40;
      break;
    default:
      throw std::invalid_argument(bad);
  }
  const std::string unit = suffix.substr(1);
  if (!unit.empty() && unit != "B" && unit != "IB") throw std::invalid_argument(bad);
  if (value > (max >> shift)) throw std::invalid_argument("'" + text + "' does not fit 64 bits");
  return value << shift;
}

std::string format_byte_size(std::uint64_t bytes) {
  const char* suffix = "";
  for (const char* next : {"K", "M", "G", "T"}) {
    if (bytes == 0 || bytes % 1024 != 0) break;
    bytes /= 1024;
    suffix = next;
  }
  return std::to_string(bytes) + suffix;
}

// The library names the SumLimits field that stopped a sum; the tool adds
// the option that raises it.
void rethrow_with_limit_hint(const Error& e) {
  const std::string_view message = e.message();
  if (e.category() == ErrorCategory::limit) {
    if (message.find("max_output_facets") != std::string_view::npos)
      throw Error(e.category(), std::string(message) + "; raise it with --max-facets");
    if (message.find("max_memory_bytes") != std::string_view::npos)
      throw Error(e.category(), std::string(message) + "; raise it with --max-memory");
  }
  throw e;
}

}  // namespace cvms::cli
