#pragma once
// A job's params are its declared keys (app/job_registry), checked by the same
// code as a config section or the command line: the browser, the config file
// and the command line cannot drift apart.

#include <json/value.h>

#include "occlusion/app/job_registry.hpp"
#include "occlusion/server/data_root.hpp"

namespace occlusion::server {

// The params as a source of key values. Path keys are resolved inside the
// data directory first (ProtocolError path_outside_data, or not_found for a
// missing input); a job that writes files and was given no "out" writes to
// DATA/out. Throws UsageError for what a config file would be refused for.
struct JobBudget {
  std::uint64_t max_memory_mb = 0;  // 0: none
  double max_work = 0;              // G ray steps; 0: none
};

// A job with a memory or work budget gets the server's (`max_memory_mb`,
// `max_work`) unless the request asks for less.
KeySource job_source(const Json::Value& params, const JobInfo& job, const DataRoot& root,
                     const JobBudget& budget);

}  // namespace occlusion::server
