#include "job_params.hpp"

#include <algorithm>

namespace occlusion::server {

KeySource job_source(const Json::Value& params, const JobInfo& job, const DataRoot& root) {
  Json::Value body = params.isNull() ? Json::Value(Json::objectValue) : params;
  const bool writes_files = std::any_of(job.keys.begin(), job.keys.end(),
                                        [](const KeyInfo& info) { return info.name == "out"; });
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
