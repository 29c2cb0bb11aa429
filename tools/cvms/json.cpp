// SPDX-License-Identifier: MIT
// See json.hpp.
#include "json.hpp"

#include <charconv>
#include <cmath>

namespace cvms::cli {

std::string json_string(std::string_view text) {
  std::string out = "\"";
  for (char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (byte >= 0x20 && byte < 0x7f) {
      out += c;
    } else {
      constexpr const char* hex = "0123456789abcdef";
      out += "\\u00";
      out += hex[byte >> 4];
      out += hex[byte & 15];
    }
  }
  return out + "\"";
}

std::string json_number(double d) {
  if (!std::isfinite(d)) return "null";
  char digits[64];
  const auto result = std::to_chars(digits, digits + sizeof digits, d);
  return std::string(digits, result.ptr);
}

JsonObject::JsonObject(std::ostream& out) : out_(out) { out_ << '{'; }

void JsonObject::key(std::string_view name) {
  out_ << (first_ ? "" : ", ") << json_string(name) << ": ";
  first_ = false;
}

JsonObject& JsonObject::text(std::string_view name, std::string_view value) {
  key(name);
  out_ << json_string(value);
  return *this;
}

JsonObject& JsonObject::number(std::string_view name, double value) {
  key(name);
  out_ << json_number(value);
  return *this;
}

JsonObject& JsonObject::integer(std::string_view name, std::int64_t value) {
  key(name);
  out_ << value;
  return *this;
}

JsonObject& JsonObject::boolean(std::string_view name, bool value) {
  key(name);
  out_ << (value ? "true" : "false");
  return *this;
}

JsonObject& JsonObject::exact(std::string_view name, const Rational& value) {
  text(name, to_string(value));
  return number(std::string(name) + "_double", to_double_nearest(value));
}

JsonObject& JsonObject::point(std::string_view name, const Vec3& p) {
  key(name);
  out_ << '[' << json_string(to_string(p.x)) << ", " << json_string(to_string(p.y)) << ", "
       << json_string(to_string(p.z)) << ']';
  key(std::string(name) + "_double");
  out_ << '[' << json_number(to_double_nearest(p.x)) << ", " << json_number(to_double_nearest(p.y)) << ", "
       << json_number(to_double_nearest(p.z)) << ']';
  return *this;
}

JsonObject& JsonObject::raw(std::string_view name, std::string_view json) {
  key(name);
  out_ << json;
  return *this;
}

void JsonObject::end() { out_ << "}\n"; }

}  // namespace cvms::cli
