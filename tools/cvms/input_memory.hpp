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
// denominator (32 bytes each with malloc's header): 96 bytes for 2 bytes of
// text, 48 per byte. Longer numbers cost less per byte (their digits take
// under half a byte each; an exponent such as "1e300" is bounded by
// ReadLimits::max_number_bits_per_byte). A command holds the parsed input
// and at most one working copy of it (points are hulled, rows normalised),
// in vectors that grow by doubling (up to half again): 48 * 2 * 1.5 = 144
// bytes per byte of a mesh, whose numbers are all coordinates; the worst
// mesh measured (a point-only OFF of one-digit coordinates, hulled) peaks
// near 72 (with the mesh's bytes held while they are parsed, one more per
// byte: mesh_input.hpp). Rows and point lists may be files of the plane, whose rows and
// points get a zero coordinate each (3 numbers for 2 of text), and the set
// of rows of the plane is built through more copies: the worst measured (one-digit rows of
// the plane, duplicated, through `diff`) peaks near 233, so they count 256.
#pragma once

#include <cstdint>
#include <string>

#include "cvms/error.hpp"
#include "cvms/io.hpp"

namespace cvms::cli {

/// What an input holds, for the memory it costs per byte.
enum class InputCost {
  mesh,           ///< OFF, OBJ, STL (3-D coordinates, faces)
  rows_or_points  ///< cdd .ine/.ext, plain rows, point lists (3-D or of the plane)
};

/// Bytes of memory a command may take per byte of an input (see the file
/// comment): 144 for a mesh, 256 for rows or points.
std::uint64_t memory_per_input_byte(InputCost cost);

/// input_bytes * memory_per_input_byte(cost), saturated at 2^64 - 1.
std::uint64_t estimated_input_memory(std::uint64_t input_bytes, InputCost cost);

/// The memory budget of the command that runs (--max-memory); by default
/// the tool's machine-fitted budget (machine_memory.hpp). The inputs of a
/// command share it; they are read one after the other.
std::uint64_t& memory_budget();

/// The limits to read `path` with ("-": stdin): read_limits(), with
/// max_bytes lowered to what is left of memory_budget() divided by
/// memory_per_input_byte(cost). A regular file's size is checked against it
/// and its estimate taken from the budget first.
/// \throw Error(limit) "<file>: an input of N bytes is estimated to need
///   up to M bytes of memory ..., beyond ...; raise it with --max-memory"
///   when the file is too big for what is left of the budget.
ReadLimits input_read_limits(const std::string& path, InputCost cost);

/// Rethrows `e`; the Error(limit) of a stream longer than the max_bytes that
/// input_read_limits lowered for the budget gets the budget named, and the
/// option that raises it.
[[noreturn]] void rethrow_with_memory_hint(const Error& e, const ReadLimits& limits, InputCost cost);

}  // namespace cvms::cli
