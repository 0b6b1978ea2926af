#pragma once
// Options for groups of config keys that several commands take: region
// growing (-rgoc, study) and point-cloud tracing (-poc, study).

#include "occlusion/analysis/mesh_estimation.hpp"
#include "occlusion/app/cloud_occlusion_job.hpp"
#include "option_table.hpp"

namespace occlusion::cli {

// --normal-k, --min-cluster-size, --max-cluster-size, --neighbours,
// --smoothness-degrees, --curvature-threshold, --ransac-distance,
// --ransac-iterations, --recover-edges.
void add_estimation_options(OptionTable& table, RegionGrowingOptions& options);

// --num-rays-per-vp, --point-radius, --polygon-path, --octree-resolution,
// --enable-acceleration, --sampling, --light-radius, --exterior,
// --exterior-classes, --skip-bad-lines, --seed, --threads.
void add_tracing_options(OptionTable& table, CloudOcclusionRequest& request);

}  // namespace occlusion::cli
