// SPDX-License-Identifier: MIT
// One JSON object on one line, for the --json output of the commands that
// report (distance, penetration, check). Exact numbers are strings (as the
// writers print coordinates: cvms::to_string), each beside a member
// "<name>_double" holding its nearest double, so that a script gets the
// exact value and a float without parsing p/q. A double beyond the range of
// doubles is null (JSON has no infinity).
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>

#include "cvms/rational.hpp"
#include "cvms/vec.hpp"

namespace cvms::cli {

/// `text` as a JSON string literal: quotes, backslashes, control bytes and
/// bytes beyond ASCII escaped (\u00XX), so the output is valid JSON and
/// ASCII whatever a file name holds.
std::string json_string(std::string_view text);

/// The shortest decimal that reads back to `d`, or null when it is not finite.
std::string json_number(double d);

/// Writes `{"a": ..., "b": ...}` member by member; end() closes it and ends the line.
class JsonObject {
 public:
  explicit JsonObject(std::ostream& out);
  JsonObject& text(std::string_view name, std::string_view value);
  JsonObject& number(std::string_view name, double value);
  JsonObject& integer(std::string_view name, std::int64_t value);
  JsonObject& boolean(std::string_view name, bool value);
  /// "<name>": "<exact>", "<name>_double": <nearest double>.
  JsonObject& exact(std::string_view name, const Rational& value);
  /// "<name>": ["x", "y", "z"], "<name>_double": [x, y, z].
  JsonObject& point(std::string_view name, const Vec3& p);
  /// "<name>": <raw>, for a value made elsewhere (a nested object).
  JsonObject& raw(std::string_view name, std::string_view json);
  void end();

 private:
  void key(std::string_view name);
  std::ostream& out_;
  bool first_ = true;
};

}  // namespace cvms::cli
