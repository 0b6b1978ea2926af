#pragma once
// The command line and the Python call that run a job with given keys: what
// the server returns beside each result (`reproduce`), so that a figure the
// viewer shows can be had again from the CLI or Python. Flags come from the
// keys' declarations (KeyInfo::cli_name), as the CLI parses them.

#include <json/value.h>

#include <string>

#include "occlusion/app/job_registry.hpp"

namespace occlusion {

// `params`: key -> value, as a config section or a server job message holds
// them. E.g. "occlusion -poc room.pcd --num-rays-per-vp 20000 --viewpoint
// 1,2,1.5". Numbers keep every digit (%.17g); words the shell would split or
// expand are single-quoted. Keys the job does not declare are left out.
std::string cli_command(const JobInfo& job, const Json::Value& params);
// E.g. "occlusion.cloud_occlusion('room.pcd', num_rays_per_vp=20000,
// viewpoints=[[1, 2, 1.5]])".
std::string python_call(const JobInfo& job, const Json::Value& params);

}  // namespace occlusion
