#include "occlusion/app/key.hpp"

#include <charconv>
#include <cmath>
#include <sstream>

#include "occlusion/app/errors.hpp"

namespace occlusion {

namespace {

std::string format_number(double value) {
  std::ostringstream text;
  text.precision(15);
  text << value;
  return text.str();
}

bool is_number(const Json::Value& v) {
  return v.isNumeric() && !v.isBool();
}

bool is_non_negative_integer(const Json::Value& v) {
  return !v.isBool() && v.isIntegral() && (v.isUInt64() || (v.isInt64() && v.asInt64() >= 0));
}

bool is_point(const Json::Value& p) {
  if (!p.isArray() || p.size() != 3) return false;
  for (const auto& c : p) {
    if (!is_number(c) || !std::isfinite(c.asDouble())) return false;
  }
  return true;
}

const char* type_name(ValueType type) {
  switch (type) {
    case ValueType::kString:
      return "string";
    case ValueType::kPath:
      return "path";
    case ValueType::kNumber:
      return "number";
    case ValueType::kInteger:
      return "integer";
    case ValueType::kBool:
      return "bool";
    case ValueType::kStringList:
      return "string_list";
    case ValueType::kPathList:
      return "path_list";
    case ValueType::kIntegerList:
      return "integer_list";
    case ValueType::kNumberList:
      return "number_list";
    case ValueType::kPointList:
      return "point_list";
    case ValueType::kViewpointSets:
      return "viewpoint_sets";
    case ValueType::kPathEntries:
      return "path_entries";
  }
  return "?";
}

std::string kebab(const std::string& name) {
  std::string text = "--" + name;
  for (char& c : text) {
    if (c == '_') c = '-';
  }
  return text;
}

std::string describe_range(const KeyInfo& info, const char* noun) {
  const bool integer = info.type == ValueType::kInteger || info.type == ValueType::kIntegerList;
  // (a number list's bounds are each item's)
  const bool has_max = info.max && *info.max < 1.8e19;
  std::string text = noun;
  if (info.min && has_max) {
    if (integer) return text + " " + format_number(*info.min) + ".." + format_number(*info.max);
    return text + " in " + (info.min_exclusive ? "(" : "[") + format_number(*info.min) + ", " +
           format_number(*info.max) + "]";
  }
  if (info.min && (*info.min != 0.0 || info.min_exclusive || !integer)) {
    text += std::string(info.min_exclusive ? " > " : " >= ") + format_number(*info.min);
  }
  if (has_max) text += " <= " + format_number(*info.max);
  return text;
}

// Why a value is wrong, or "" when it is right.
std::string problem(const KeyInfo& info, const Json::Value& v);

std::string in_range(const KeyInfo& info, double x) {
  const bool below = info.min && (info.min_exclusive ? x <= *info.min : x < *info.min);
  const bool above = info.max && x > *info.max;
  if (below || above) return "must be " + describe_values(info) + ", got " + format_number(x);
  return "";
}

std::string check_viewpoint_set(const std::string& name, const Json::Value& set,
                                Json::ArrayIndex index) {
  const std::string item = name + "[" + std::to_string(index) + "]";
  if (!set.isObject()) return item + " must be an object";
  int kinds = 0;
  for (const auto& member : set.getMemberNames()) {
    const Json::Value& v = set[member];
    if (member == "name") {
      if (!v.isString() || v.asString().empty()) return item + ".name must be a non-empty string";
    } else if (member == "pattern") {
      ++kinds;
      if (!is_non_negative_integer(v) || v.asUInt64() < 1 || v.asUInt64() > 7) {
        return item + ".pattern must be an integer 1..7";
      }
    } else if (member == "num_vp") {
      ++kinds;
      if (!is_non_negative_integer(v) || v.asUInt64() < 1 ||
          v.asUInt64() > ViewpointChoice::kMaxViewpoints) {
        return item + ".num_vp must be an integer 1.." +
               std::to_string(ViewpointChoice::kMaxViewpoints);
      }
    } else if (member == "viewpoints") {
      ++kinds;
      if (!v.isArray() || v.empty() || v.size() > ViewpointChoice::kMaxViewpoints) {
        return item + ".viewpoints must be a list of 1.." +
               std::to_string(ViewpointChoice::kMaxViewpoints) + " [x, y, z] points";
      }
      for (const auto& p : v) {
        if (!is_point(p)) return item + ".viewpoints must be a list of [x, y, z] points";
      }
    } else {
      return item + " has an unknown key '" + member + "'";
    }
  }
  if (!set.isMember("name")) return item + " needs a \"name\"";
  if (kinds != 1) return item + " needs exactly one of \"pattern\", \"num_vp\" or \"viewpoints\"";
  return "";
}

std::string entry_key_names(const KeyInfo& info) {
  std::string text;
  for (const auto& entry : info.entry_keys) text += (text.empty() ? "" : ", ") + entry.name;
  return text;
}

// An entry names its path, so that a bad value is found in a long list.
std::string check_path_entry(const KeyInfo& info, const Json::Value& item, Json::ArrayIndex index) {
  const std::string at = info.name + "[" + std::to_string(index) + "]";
  if (item.isString()) return item.asString().empty() ? at + " is an empty path" : "";
  if (!item.isObject()) return at + " must be a path or an object with a \"path\"";
  if (!item["path"].isString() || item["path"].asString().empty()) {
    return at + " needs a \"path\" (a non-empty string)";
  }
  const std::string entry = at + " (" + item["path"].asString() + ")";
  for (const auto& member : item.getMemberNames()) {
    if (member == "path") continue;
    const KeyInfo* known = nullptr;
    for (const auto& candidate : info.entry_keys) {
      if (candidate.name == member) known = &candidate;
    }
    if (known == nullptr) {
      return entry + " has an unknown key '" + member + "' (an entry may set " +
             entry_key_names(info) + ")";
    }
    const std::string why = problem(*known, item[member]);
    if (!why.empty()) return entry + ": '" + member + "' " + why;
  }
  return "";
}

std::string problem(const KeyInfo& info, const Json::Value& v) {
  const std::string wrong = "must be " + describe_values(info);
  if (info.allows_auto && v.isString() && v.asString() == "auto") return "";
  switch (info.type) {
    case ValueType::kString:
    case ValueType::kPath:
      if (!v.isString()) return wrong;
      if (!info.choices.empty()) {
        for (const auto& choice : info.choices) {
          if (v.asString() == choice) return "";
        }
        return wrong + ", got '" + v.asString() + "'";
      }
      return "";
    case ValueType::kNumber:
      if (!is_number(v) || !std::isfinite(v.asDouble())) return wrong;
      return in_range(info, v.asDouble());
    case ValueType::kInteger:
      if (!is_non_negative_integer(v)) return wrong;
      return in_range(info, static_cast<double>(v.asUInt64()));
    case ValueType::kBool:
      return v.isBool() ? "" : wrong;
    case ValueType::kStringList:
    case ValueType::kPathList:
      if (!v.isArray()) return wrong;
      for (const auto& item : v) {
        if (!item.isString()) return wrong;
      }
      break;
    case ValueType::kIntegerList:
      if (!v.isArray()) return wrong;
      for (const auto& item : v) {
        if (!is_non_negative_integer(item)) return wrong;
        const std::string range = in_range(info, static_cast<double>(item.asUInt64()));
        if (!range.empty()) return range;
      }
      break;
    case ValueType::kNumberList:
      if (!v.isArray()) return wrong;
      for (const auto& item : v) {
        if (!is_number(item) || !std::isfinite(item.asDouble())) return wrong;
        const std::string range = in_range(info, item.asDouble());
        if (!range.empty()) return range;
      }
      break;
    case ValueType::kPointList:
      if (!v.isArray() || v.empty()) return wrong;
      for (const auto& item : v) {
        if (!is_point(item)) return wrong;
      }
      break;
    case ValueType::kViewpointSets:
      if (!v.isArray()) return wrong;
      for (Json::ArrayIndex i = 0; i < v.size(); ++i) {
        const std::string why = check_viewpoint_set(info.name, v[i], i);
        if (!why.empty()) return "is wrong: " + why;
      }
      break;
    case ValueType::kPathEntries:
      if (!v.isArray()) return wrong;
      for (Json::ArrayIndex i = 0; i < v.size(); ++i) {
        const std::string why = check_path_entry(info, v[i], i);
        if (!why.empty()) return "is wrong: " + why;
      }
      break;
  }
  if (info.max_items > 0 && v.size() > info.max_items) {
    return "must hold at most " + std::to_string(info.max_items) + " items, got " +
           std::to_string(v.size());
  }
  return "";
}

}  // namespace

std::string default_text(const KeyInfo& info) {
  const Json::Value& d = info.default_value;
  if (d.isNull()) return "";
  if (d.isString()) return d.asString().empty() ? "" : d.asString();
  if (d.isArray()) {
    if (d.empty()) return "";
    std::string text;
    for (const auto& item : d) {
      text +=
          (text.empty() ? "" : ",") + (item.isString() ? item.asString() : item.toStyledString());
    }
    return text;
  }
  // A fraction as the shortest text that reads back as the same double (JSON's
  // 17 digits print 0.99 as 0.98999999999999999); whole numbers keep JSON's
  // "100.0", which says the key takes a number, not only integers.
  if (d.isDouble() && std::isfinite(d.asDouble()) && d.asDouble() != std::floor(d.asDouble())) {
    char digits[32];
    return std::string(digits, std::to_chars(digits, digits + sizeof digits, d.asDouble()).ptr);
  }
  std::string text = d.toStyledString();
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text;
}

std::string cli_spelling(const KeyInfo& info) {
  return info.cli_name.empty() ? kebab(info.name) : info.cli_name;
}

std::string describe_values(const KeyInfo& info) {
  std::string text;
  switch (info.type) {
    case ValueType::kString:
    case ValueType::kPath:
      if (info.choices.empty()) {
        text = info.type == ValueType::kPath ? "a path" : "a string";
      } else {
        text = "one of ";
        for (std::size_t i = 0; i < info.choices.size(); ++i) {
          text += (i == 0 ? "" : ", ") + info.choices[i];
        }
      }
      break;
    case ValueType::kNumber:
      text = describe_range(info, "a number");
      break;
    case ValueType::kInteger:
      text = describe_range(info, "an integer");
      break;
    case ValueType::kBool:
      text = "true or false";
      break;
    case ValueType::kStringList:
      text = "a list of strings";
      break;
    case ValueType::kPathList:
      text = "a list of paths";
      break;
    case ValueType::kIntegerList:
      text = "a list of " + describe_range(info, "integers");
      break;
    case ValueType::kNumberList:
      text = "a list of " + describe_range(info, "numbers");
      break;
    case ValueType::kPointList:
      text = "a list of [x, y, z] points";
      break;
    case ValueType::kViewpointSets:
      text = "a list of {\"name\", and \"pattern\", \"num_vp\" or \"viewpoints\"} objects";
      break;
    case ValueType::kPathEntries:
      text =
          "a list of paths, each a path or {\"path\": PATH} with any of " + entry_key_names(info);
      break;
  }
  if (info.allows_auto) text += " or \"auto\"";
  return text;
}

std::string entry_path(const Json::Value& item) {
  return item.isObject() ? item["path"].asString() : item.asString();
}

void check_value(const KeyInfo& info, const Json::Value& value, const std::string& spelling) {
  const std::string why = problem(info, value);
  if (!why.empty()) throw KeyError(info.name, why, spelling);
}

Json::Value to_json(const KeyInfo& info) {
  Json::Value json(Json::objectValue);
  json["name"] = info.name;
  json["type"] = type_name(info.type);
  json["default"] = info.default_value;
  json["doc"] = info.doc;
  json["values"] = describe_values(info);
  if (!info.unit.empty()) json["unit"] = info.unit;
  if (info.min) json["min"] = *info.min;
  if (info.max && *info.max < 1.8e19) json["max"] = *info.max;
  if (info.min_exclusive) json["min_exclusive"] = true;
  if (info.allows_auto) json["auto"] = true;
  if (!info.choices.empty()) {
    Json::Value choices(Json::arrayValue);
    for (const auto& c : info.choices) choices.append(c);
    json["choices"] = choices;
  }
  if (info.max_items > 0) json["max_items"] = Json::UInt64(info.max_items);
  if (!info.exclusive_group.empty()) json["exclusive_group"] = info.exclusive_group;
  if (!info.entry_keys.empty()) {
    Json::Value entry_keys(Json::arrayValue);
    for (const auto& entry : info.entry_keys) entry_keys.append(entry.name);
    json["entry_keys"] = entry_keys;
  }
  json["cli"] = cli_spelling(info);
  return json;
}

}  // namespace occlusion
