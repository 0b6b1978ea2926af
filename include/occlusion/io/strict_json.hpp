#pragma once
// The one way the tool parses JSON it is given (a config, a class mapping, a
// frame descriptor, a server message, a study's parameters): JSON as RFC 8259
// writes it and nothing more, so that what a file says is all it says.
// JsonCpp's defaults would accept a second value after the first (ignored),
// comments and trailing commas, and keep a NUL (\u0000) inside a string,
// which cuts a file name short where the system reads it.

#include <json/value.h>

#include <string>
#include <string_view>

namespace occlusion {

struct StrictJson {
  // Nesting deeper than this is refused rather than recursed into.
  int max_depth = 64;
  // NaN, Infinity and -Infinity as numbers (a frame descriptor names a lost
  // pose's -Infinity as such rather than as a syntax error).
  bool special_floats = false;
};

// Parses `text` into `value`: one value with only whitespace around it, no
// comments, no trailing commas, no duplicate keys, no string or key holding
// NUL. False with the reason (JsonCpp's, "Line L, Column C: ...") in
// `errors` otherwise.
bool parse_strict_json(std::string_view text, const StrictJson& rules, Json::Value& value,
                       std::string& errors);

}  // namespace occlusion
