// SPDX-License-Identifier: MIT
// Sizes on the command line: "4096", "512K", "512M", "4G", "1T" (binary
// multiples, an optional trailing "B" or "iB": "4GiB", "512MB").
#pragma once

#include <cstdint>
#include <string>

namespace cvms::cli {

/// The number of bytes `text` spells.
/// \throw std::invalid_argument with a one-line reason for text that is not
///   a size or does not fit 64 bits.
std::uint64_t parse_byte_size(const std::string& text);

/// `bytes` in the shortest spelling parse_byte_size reads back exactly
/// ("4G" for 4 GiB, "1000" for 1000).
std::string format_byte_size(std::uint64_t bytes);

}  // namespace cvms::cli
