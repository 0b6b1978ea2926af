#pragma once
// The JSON configuration file, in the seed's shape (thesis listing 4.14):
//   { "occlusion": { "mesh": { "path": ..., "pattern": 4, ... },
//                    "point_cloud": { ... }, "reconstruct": { ... }, "study": { ... } } }
// The whole file is checked on load: an unknown key or a wrong type is a
// UsageError that names the key. Relative paths are resolved against the
// config file's folder. Each job reads its own section (ConfigSection).

#include <json/value.h>

#include <cstdint>
#include <string>
#include <vector>

#include "occlusion/app/viewpoint_choice.hpp"

namespace occlusion {

struct Config {
  Json::Value root;
  std::string directory;  // folder of the config file, for relative paths
  std::string path;
};

// Reads and checks the whole file (all sections). Throws UsageError.
Config load_config(const std::string& path);

// Checks a config given as JSON (e.g. a server request's parameters), as
// load_config does a file. `name` prefixes error messages; relative paths
// resolve against `directory`. Throws UsageError.
Config config_from_json(const Json::Value& root, const std::string& directory,
                        const std::string& name);

// One section, e.g. "mesh". Each read leaves `out` unchanged when the key is
// absent; types were checked by load_config.
class ConfigSection {
 public:
  ConfigSection(const Config& config, const std::string& name);

  bool has(const std::string& key) const;
  void read(const std::string& key, std::string& out) const;
  // Resolved against the config's folder; "" stays "" (none).
  void read_path(const std::string& key, std::string& out) const;
  void read(const std::string& key, double& out) const;
  void read(const std::string& key, bool& out) const;
  void read(const std::string& key, std::uint64_t& out) const;
  void read(const std::string& key, unsigned& out) const;
  void read(const std::string& key, std::vector<std::string>& out) const;
  // A list of paths, each resolved as read_path does.
  void read_paths(const std::string& key, std::vector<std::string>& out) const;
  // A list of named viewpoint choices (the study's configurations).
  void read(const std::string& key, std::vector<NamedViewpointChoice>& out) const;
  // "viewpoints", "pattern" or "num_vp": at most one may be present.
  void read_viewpoints(ViewpointChoice& out) const;

 private:
  const Config& config_;
  std::string name_;
  const Json::Value& body_;
};

}  // namespace occlusion
