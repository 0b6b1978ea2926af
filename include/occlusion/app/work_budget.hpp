#pragma once
// Work too long for the budget is refused before it starts, as work too large
// for memory is (memory_budget.hpp): a server's workers are shared, and one
// request of 10,000 viewpoints x 1e8 rays would hold one for days. Work is
// counted in ray steps: rays traced x the cost of one ray, which is the
// octree's depth (log2 of its primitives) or, with enable_acceleration false,
// every primitive. Each tracing job's estimate is here, once.

#include <cstddef>
#include <cstdint>
#include <string>

#include "occlusion/app/errors.hpp"
#include "occlusion/core/mesh.hpp"

namespace occlusion {

// `max_work` counts ray steps in units of a billion (G).
constexpr double kWorkUnit = 1e9;

struct WorkEstimate {
  std::uint64_t steps = 0;
  std::string made_of;  // for people: "9,000,000 rays x 17 octree levels over 80,000 points"
  std::string keys;     // the job's keys that size it: "num_rays_per_vp, num_vp or viewpoints"
};

// The refusal: a usage error (invalid_request on the server) that says how
// much work was asked for, so a caller can tell an estimate from other errors.
struct WorkBudgetError : UsageError {
  WorkBudgetError(const std::string& message, std::uint64_t work_steps)
      : UsageError(message), steps(work_steps) {}
  std::uint64_t steps;
};

// WorkBudgetError, naming the estimate, its keys and `max_work`, when the
// estimate exceeds max_work G ray steps (0: no budget).
void check_work_budget(const WorkEstimate& estimate, double max_work);

// -poc: num_rays_per_vp from each viewpoint, twice with the exterior variant.
WorkEstimate cloud_occlusion_work(std::size_t points, std::size_t viewpoints,
                                  std::uint64_t rays_per_viewpoint, bool exterior,
                                  bool accelerated);
// -moc (and -rgoc's estimated mesh): a shadow ray from every sample to every viewpoint.
WorkEstimate mesh_occlusion_work(const TriangleMesh& mesh, double samples_per_unit_area,
                                 std::size_t viewpoints, bool accelerated);
// -fscan: a shadow ray from every point to every viewpoint.
WorkEstimate scan_work(std::size_t points, std::size_t viewpoints, bool accelerated);
// plan's free-space filter (analysis/station_candidates.hpp) of `positions`:
// each one's probe rays (outside, and inside solids for a mesh) through the
// octree over `primitives`, two rays to and past each of a cloud's
// `stations` (the space they saw empty), and its clearance, a look-up among
// a cloud's points or a test of every face of a mesh. Known before the filter.
WorkEstimate plan_filter_work(std::size_t positions, std::uint64_t primitives, bool mesh,
                              std::size_t stations);
// The work of `first`, then `then`'s: named by then's keys.
WorkEstimate one_after_the_other(const WorkEstimate& first, const WorkEstimate& then);
// plan: a shadow ray from every target (-moc's samples of a mesh, a cloud's
// points) to every candidate, with `intervisible` one between every two
// candidates, and to each of the `refine_positions` a refinement may try
// (analysis/station_refinement.hpp; their free-space test is the caller's
// plan_filter_work). Known before any sample is drawn or point model made.
WorkEstimate plan_mesh_work(const TriangleMesh& mesh, double samples_per_unit_area,
                            std::size_t candidates, bool intervisible,
                            std::size_t refine_positions);
WorkEstimate plan_cloud_work(std::size_t points, std::size_t candidates, bool intervisible,
                             std::size_t refine_positions);

}  // namespace occlusion
