#include "job_params.hpp"

#include <algorithm>

namespace occlusion::server {

KeySource job_source(const Json::Value& params, const JobInfo& job, const DataRoot& root,
                     const JobBudget& budget) {
  Json::Value body = params.isNull() ? Json::Value(Json::objectValue) : params;
  const auto has_key = [&job](const char* name) {
    return std::any_of(job.keys.begin(), job.keys.end(),
                       [name](const KeyInfo& info) { return info.name == name; });
  };
  const bool writes_files = has_key("out");
  // The server's budget, unless the request asks for less.
  const auto cap = [&](const char* name, double limit, Json::Value as_json) {
    if (!has_key(name) || !body.isObject() || limit <= 0) return;
    const Json::Value& asked = body[name];
    const bool lower = asked.isNumeric() && asked.asDouble() > 0 && asked.asDouble() < limit;
    if (!lower) body[name] = std::move(as_json);
  };
  cap("max_memory_mb", static_cast<double>(budget.max_memory_mb),
      Json::UInt64(budget.max_memory_mb));
  cap("max_work", budget.max_work, budget.max_work);
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
