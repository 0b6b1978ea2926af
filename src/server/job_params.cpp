#include "job_params.hpp"

#include <algorithm>
#include <filesystem>

#include "messages.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/io/input_error.hpp"

namespace occlusion::server {

namespace fs = std::filesystem;

namespace {

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

bool is_path_key(const std::string& key) {
  return key == "path" || key == "out" || ends_with(key, "_path");
}

Config job_config(const Json::Value& params, const JobParams& spec, const DataRoot& root) {
  Json::Value body = params;
  // A wrong type is left for the config check to name; "" means "none".
  const auto resolve = [&root](Json::Value& value, bool must_exist) {
    if (value.isString() && !value.asString().empty()) {
      value = root.resolve(value.asString(), must_exist).string();
    }
  };
  for (const auto& key : body.getMemberNames()) {
    Json::Value& value = body[key];
    if (is_path_key(key)) resolve(value, key != "out");
    const auto& lists = spec.path_list_keys;
    if (value.isArray() && std::find(lists.begin(), lists.end(), key) != lists.end()) {
      for (auto& item : value) resolve(item, true);
    }
  }
  // "out": "" stays as it is: the config reads it as "no output files".
  if (spec.default_out && !body.isMember("out")) {
    body["out"] = root.resolve("out", false).string();
  }

  Json::Value file(Json::objectValue);
  file["occlusion"][spec.section] = body;
  // Relative paths (none are left, but the rule stays right) are data-relative.
  return config_from_json(file, root.path().string(), "params");
}

}  // namespace occlusion::server
