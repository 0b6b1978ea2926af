#pragma once
// A job's params are exactly the keys of its config-file section, so the
// browser, the config file and the command line cannot drift apart: the
// params are checked by the app layer's own config loader (unknown key, wrong
// type: UsageError naming the key) and copied into the request by the job's
// own apply_config().

#include <json/value.h>

#include <string>
#include <vector>

#include "occlusion/app/config.hpp"
#include "occlusion/server/data_root.hpp"

namespace occlusion::server {

// Keys that name files: "path", "out" and any key ending in "_path".
bool is_path_key(const std::string& key);

// What the server needs to know of a job's section beyond the config's own checks.
struct JobParams {
  std::string section;                      // e.g. "mesh"
  bool default_out = true;                  // a missing "out" is DATA/out
  std::vector<std::string> path_list_keys;  // lists of input paths, e.g. "ground_truth"
};

// The params as a Config holding the one section `spec.section`. Path keys
// (is_path_key and spec.path_list_keys) are resolved inside the data
// directory first (ProtocolError path_outside_data, or not_found for a
// missing input). Throws UsageError for what a config file would be refused for.
Config job_config(const Json::Value& params, const JobParams& spec, const DataRoot& root);

}  // namespace occlusion::server
