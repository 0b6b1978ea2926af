#include "occlusion/io/strict_json.hpp"

#include <json/reader.h>

#include <algorithm>
#include <memory>

namespace occlusion {
namespace {

// "Line L, Column C" of byte `offset`, as JsonCpp names places.
std::string position_at(std::string_view text, std::size_t offset) {
  const std::string_view before = text.substr(0, std::min(offset, text.size()));
  const std::size_t line_start = before.rfind('\n');
  const std::size_t column =
      before.size() - (line_start == std::string_view::npos ? 0 : line_start + 1) + 1;
  return "Line " + std::to_string(1 + std::count(before.begin(), before.end(), '\n')) +
         ", Column " + std::to_string(column);
}

std::string position_of(std::string_view text, const Json::Value& value) {
  return position_at(text,
                     static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, value.getOffsetStart())));
}

// The first string or key below `value` holding NUL; its depth is bounded by
// the parse's max_depth.
bool holds_nul(std::string_view text, const Json::Value& value, std::string& errors) {
  const auto nul = [](const std::string& s) { return s.find('\0') != std::string::npos; };
  if (value.isString()) {
    if (!nul(value.asString())) return false;
    errors = position_of(text, value) + ": a string holds NUL (\\u0000), which no name or path can";
    return true;
  }
  if (value.isObject()) {
    for (auto member = value.begin(); member != value.end(); ++member) {
      if (nul(member.name())) {
        errors = position_of(text, *member) + ": a key holds NUL (\\u0000)";
        return true;
      }
      if (holds_nul(text, *member, errors)) return true;
    }
  }
  if (value.isArray()) {
    for (const Json::Value& item : value) {
      if (holds_nul(text, item, errors)) return true;
    }
  }
  return false;
}

// JSON has no comments, so no / outside a string. JsonCpp's allowComments
// = false refuses one only where a value starts: inside an object or an
// array it skips them whatever the setting (1.9.5), hence this scan.
bool holds_comment(std::string_view text, std::string& errors) {
  bool in_string = false;
  for (std::size_t at = 0; at < text.size(); ++at) {
    const char c = text[at];
    if (in_string) {
      if (c == '\\') {
        ++at;  // the escaped character, " included
      } else if (c == '"') {
        in_string = false;
      }
    } else if (c == '"') {
      in_string = true;
    } else if (c == '/') {
      errors = position_at(text, at) + ": a comment (JSON has none)";
      return true;
    }
  }
  return false;
}

}  // namespace

bool parse_strict_json(std::string_view text, const StrictJson& rules, Json::Value& value,
                       std::string& errors) {
  Json::CharReaderBuilder builder;
  builder["collectComments"] = false;
  builder["allowComments"] = false;
  builder["allowTrailingCommas"] = false;
  builder["allowDroppedNullPlaceholders"] = false;
  builder["allowNumericKeys"] = false;
  builder["allowSingleQuotes"] = false;
  builder["failIfExtra"] = true;
  builder["rejectDupKeys"] = true;
  builder["allowSpecialFloats"] = rules.special_floats;
  builder["stackLimit"] = rules.max_depth;
  const std::unique_ptr<Json::CharReader> reader(builder.newCharReader());
  errors.clear();
  if (holds_comment(text, errors)) return false;
  bool parsed = false;
  try {
    parsed = reader->parse(text.data(), text.data() + text.size(), &value, &errors);
  } catch (const Json::Exception& e) {  // JsonCpp throws on the stack limit
    errors = e.what();
  }
  if (parsed && holds_nul(text, value, errors)) parsed = false;
  while (!errors.empty() && (errors.back() == '\n' || errors.back() == ' ')) errors.pop_back();
  return parsed;
}

}  // namespace occlusion
