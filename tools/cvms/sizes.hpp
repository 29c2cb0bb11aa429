// SPDX-License-Identifier: MIT
// Sizes on the command line: "4096", "512K", "512M", "4G", "1T" (binary
// multiples, an optional trailing "B" or "iB": "4GiB", "512MB").
#pragma once

#include <cstdint>
#include <string>

#include "cvms/error.hpp"

namespace cvms::cli {

/// The number of bytes `text` spells.
/// \throw std::invalid_argument with a one-line reason for text that is not
///   a size or does not fit 64 bits.
std::uint64_t parse_byte_size(const std::string& text);

/// `bytes` in the shortest spelling parse_byte_size reads back exactly
/// ("4G" for 4 GiB, "1000" for 1000).
std::string format_byte_size(std::uint64_t bytes);

/// Rethrows `e`; an Error(limit) naming SumLimits::max_output_facets or
/// max_memory_bytes (as the library's sums do) gets the option that raises
/// it appended ("; raise it with --max-facets"). For every `cvms sum` path
/// and `cvms gen zonotope`.
[[noreturn]] void rethrow_with_limit_hint(const Error& e);

}  // namespace cvms::cli
