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
KeySource job_source(const Json::Value& params, const JobInfo& job, const DataRoot& root);

}  // namespace occlusion::server
