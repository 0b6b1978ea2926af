#pragma once
// The plan request the app-level plan tests start from: a mesh, 20 samples
// per unit area, seed 3.

#include "occlusion/app/plan_job.hpp"

namespace occlusion::testing {

inline PlanRequest plan_mesh_request() {
  PlanRequest request;
  request.path = "<scene>";
  request.samples_per_unit_area = 20.0;
  request.seed = 3;
  return request;
}

}  // namespace occlusion::testing
