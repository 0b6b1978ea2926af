#include "occlusion/app/class_mapping_file.hpp"

#include <json/value.h>

#include <charconv>
#include <limits>
#include <set>
#include <stdexcept>

#include "occlusion/app/errors.hpp"
#include "occlusion/app/json_file.hpp"

namespace occlusion {

namespace {

[[noreturn]] void fail(const std::string& where, const std::string& message) {
  throw UsageError(where + ": " + message);
}

bool is_int32(const Json::Value& value) {
  return value.isIntegral() && !value.isBool() && value.isInt();
}

std::int32_t id_from_key(const std::string& key, const std::string& where) {
  std::int32_t id = 0;
  const auto [end, error] = std::from_chars(key.data(), key.data() + key.size(), id);
  if (error != std::errc() || end != key.data() + key.size()) {
    fail(where, "'names' keys are evaluation ids, got '" + key + "'");
  }
  return id;
}

}  // namespace

ClassMapping parse_class_mapping(const Json::Value& root, const std::string& where,
                                 const ClassMapping& base) {
  if (!root.isObject()) fail(where, "a class mapping is a JSON object");
  for (const auto& key : root.getMemberNames()) {
    if (key != "classes" && key != "names" && key != "ignore" && key != "ignored_classes") {
      fail(where, "unknown key '" + key + "' (classes, names, ignore, ignored_classes)");
    }
  }
  std::map<std::string, std::int32_t> ids = base.ids();
  std::map<std::int32_t, std::string> names;
  std::set<std::string> ignored;
  if (root.isMember("classes")) {
    const Json::Value& classes = root["classes"];
    if (!classes.isObject()) fail(where, "'classes' must be an object {\"name\": id, ...}");
    ids.clear();
    for (const auto& name : classes.getMemberNames()) {
      if (!is_int32(classes[name])) fail(where, "'classes." + name + "' must be an integer");
      ids[name] = classes[name].asInt();
    }
  } else {
    for (const auto& c : base.evaluation_classes()) names[c.id] = c.name;
    ignored = base.ignored();
  }
  if (root.isMember("names")) {
    const Json::Value& given = root["names"];
    if (!given.isObject()) fail(where, "'names' must be an object {\"id\": \"name\", ...}");
    for (const auto& key : given.getMemberNames()) {
      if (!given[key].isString()) fail(where, "'names." + key + "' must be a string");
      names[id_from_key(key, where)] = given[key].asString();
    }
  }
  std::int32_t ignore = base.ignore_id();
  if (root.isMember("ignore")) {
    if (!is_int32(root["ignore"])) fail(where, "'ignore' must be an integer");
    ignore = root["ignore"].asInt();
  }
  if (root.isMember("ignored_classes")) {
    const Json::Value& list = root["ignored_classes"];
    if (!list.isArray()) fail(where, "'ignored_classes' must be a list of class names");
    for (const auto& item : list) {
      if (!item.isString()) fail(where, "'ignored_classes' must be a list of class names");
      ignored.insert(item.asString());
    }
  }
  try {
    return ClassMapping(ids, names, ignored, ignore);
  } catch (const std::invalid_argument& e) {
    fail(where, e.what());
  }
}

ClassMapping load_class_mapping(const std::string& path, const ClassMapping& base) {
  const Json::Value root = read_json_file(path, "class mapping file");
  return parse_class_mapping(root, path, base);
}

bool mapping_file_has_classes(const std::string& path) {
  return read_json_file(path, "class mapping file").isMember("classes");
}

}  // namespace occlusion
