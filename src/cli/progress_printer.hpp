#pragma once
#include "occlusion/core/progress.hpp"

namespace occlusion::cli {

// Progress lines on stderr: one when a stage starts and then at most one per
// tenth of the stage, so logs stay short. Silent when quiet.
Progress make_progress_printer(const std::string& job, bool quiet);

}  // namespace occlusion::cli
