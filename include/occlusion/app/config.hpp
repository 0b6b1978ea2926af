#pragma once
// The JSON configuration file, in the seed's shape (thesis listing 4.14):
//   { "occlusion": { "mesh": { "path": ..., "pattern": 4, ... },
//                    "point_cloud": { ... }, "scan": { ... }, "study": { ... } } }
// One section per job (job_registry.hpp names them). The whole file is checked
// on load against the jobs' key declarations: an unknown section or key, a
// wrong type or an out-of-range value is a UsageError that names it. Relative
// paths resolve against the config file's folder.

#include <json/value.h>

#include <string>

#include "occlusion/app/key_sources.hpp"

namespace occlusion {

struct JobInfo;

struct Config {
  Json::Value root;
  std::string directory;  // folder of the config file, for relative paths
  std::string path;
};

// Reads and checks the whole file (all sections). Throws UsageError.
Config load_config(const std::string& path);

// Checks a config given as JSON, as load_config does a file. `name` prefixes
// error messages; relative paths resolve against `directory`. Throws UsageError.
Config config_from_json(const Json::Value& root, const std::string& directory,
                        const std::string& name);

// The job's section as a source of key values (empty when the file has none).
KeySource config_source(const Config& config, const JobInfo& job);

// Fills `request` from the config's section for its job, e.g.
// apply_config(load_config(path), "study", study_keys(), request).
template <class R>
void apply_config(const Config& config, const std::string& job_name, const Keys<R>& keys,
                  R& request);

}  // namespace occlusion

#include "occlusion/app/job_registry.hpp"

namespace occlusion {

template <class R>
void apply_config(const Config& config, const std::string& job_name, const Keys<R>& keys,
                  R& request) {
  const JobInfo* job = find_job(job_name);
  if (job == nullptr) throw std::logic_error("no job " + job_name);
  apply_sources(keys, {config_source(config, *job)}, request);
}

}  // namespace occlusion
