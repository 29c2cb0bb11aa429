// SPDX-License-Identifier: MIT
// The memory budget of the tool's inputs: what reading a file will cost is
// estimated from its size and taken from the budget (--max-memory) before a
// single number is made, so that an input too big for the machine ends in a
// `limit` error naming the file and the option, never in a failed allocation
// inside GMP (which aborts the process: its allocation functions must not
// return on failure, and throwing from them is undefined).
//
// Why a bound per byte exists: every reader keeps what it parses, and a
// number costs at most a fixed size however short its text. The shortest
// number is one digit and a separator ("0 "); as a GMP rational it is a
// 32-byte mpq_t plus one limb block each for the numerator and the
// denominator (32 bytes each with malloc's header): 96 bytes for 2 of text.
// Longer numbers cost less per byte (their digits take under half a byte
// each; an exponent such as "1e300" is bounded by
// ReadLimits::max_number_bits_per_byte). A command holds the parsed input and
// at most one working copy of it (rows are normalised, points are hulled),
// and vectors growing by doubling hold up to half again: 48 * 2 * 1.5 = 144
// bytes per input byte. The worst inputs measured (duplicate one-digit rows
// through `hull --from-halfspaces`, the costliest path) peak near 110.
#pragma once

#include <cstdint>
#include <string>

#include "cvms/error.hpp"
#include "cvms/io.hpp"

namespace cvms::cli {

/// Bytes of memory a command may take per byte of input it reads (see the
/// file comment).
inline constexpr std::uint64_t memory_per_input_byte = 144;

/// input_bytes * memory_per_input_byte, saturated at 2^64 - 1.
std::uint64_t estimated_input_memory(std::uint64_t input_bytes);

/// The memory budget of the command that runs (--max-memory); by default
/// the tool's machine-fitted budget (machine_memory.hpp). The inputs of a
/// command share it.
std::uint64_t& memory_budget();

/// The limits to read `path` with ("-": stdin): read_limits(), with
/// max_bytes lowered to what is left of memory_budget() divided by
/// memory_per_input_byte. A regular file's size is checked against it and
/// its estimate taken from the budget first.
/// \throw Error(limit) "<file>: an input of N bytes is estimated to need
///   up to M bytes of memory ..., beyond ...; raise it with --max-memory"
///   when the file is too big for what is left of the budget.
ReadLimits input_read_limits(const std::string& path);

/// Rethrows `e`; the Error(limit) of a stream longer than the max_bytes that
/// input_read_limits lowered for the budget gets the budget named, and the
/// option that raises it.
[[noreturn]] void rethrow_with_memory_hint(const Error& e, const ReadLimits& limits);

}  // namespace cvms::cli
