#pragma once
// The JSON configuration file, in the seed's shape (thesis listing 4.14):
//   { "occlusion": { "mesh": { "path": ..., "pattern": 4, ... },
//                    "point_cloud": { ... } } }
// Every key is checked: an unknown key or a wrong type is a UsageError that
// names the key. Relative paths are resolved against the config file's folder.

#include <json/value.h>

#include <string>

#include "occlusion/app/mesh_occlusion_job.hpp"

namespace occlusion {

struct Config {
  Json::Value root;
  std::string directory;  // folder of the config file, for relative paths
  std::string path;
};

// Reads and checks the whole file (all sections). Throws UsageError.
Config load_config(const std::string& path);

// Copies the `occlusion.mesh` section into the request (keys absent stay as they are).
void apply_mesh_config(const Config& config, MeshOcclusionRequest& request);

}  // namespace occlusion
