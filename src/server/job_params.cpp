#include "job_params.hpp"

#include <algorithm>

namespace occlusion::server {

KeySource job_source(const Json::Value& params, const JobInfo& job, const DataRoot& root,
                     std::uint64_t max_memory_mb) {
  Json::Value body = params.isNull() ? Json::Value(Json::objectValue) : params;
  const auto has_key = [&job](const char* name) {
    return std::any_of(job.keys.begin(), job.keys.end(),
                       [name](const KeyInfo& info) { return info.name == name; });
  };
  const bool writes_files = has_key("out");
  if (has_key("max_memory_mb") && body.isObject() && max_memory_mb > 0) {
    const Json::Value& asked = body["max_memory_mb"];
    const bool lower = asked.isUInt64() && asked.asUInt64() > 0 && asked.asUInt64() < max_memory_mb;
    if (!lower) body["max_memory_mb"] = Json::UInt64(max_memory_mb);
  }
  // "out": "" stays as it is: the job reads it as "no output files".
  if (writes_files && body.isObject() && !body.isMember("out")) {
    body["out"] = "out";  // resolved below, as every path
  }
  return source_from_json(body, job.keys, Face::kServer, "params: ", job.section,
                          [&root](const std::string& path, bool output) {
                            return root.resolve(path, !output).string();
                          });
}

}  // namespace occlusion::server
