#pragma once
// JSON documents the user gives as files (the config, the class mapping).

#include <json/value.h>

#include <string>

namespace occlusion {

// The file's one JSON value, as io/strict_json.hpp reads it (nothing after
// it, no comments, no trailing commas, no duplicate keys, no NUL in a
// string), nesting deeper than 64 refused rather than recursed into. UsageError
// "<path>: cannot read <what>: ..." or "<path>: not valid JSON: ...", as a
// file given on the command line is part of the usage (exit 2).
Json::Value read_json_file(const std::string& path, const std::string& what);
// The same rules for JSON text given elsewhere (a command-line value);
// `source` names it in the UsageError.
Json::Value parse_json_text(const std::string& text, const std::string& source);

}  // namespace occlusion
