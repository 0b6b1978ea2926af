#include "occlusion/app/work_budget.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "occlusion/analysis/inside_solid.hpp"
#include "occlusion/analysis/mesh_sampling.hpp"
#include "occlusion/analysis/station_candidates.hpp"

namespace occlusion {

namespace {

constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();

// a * b, saturating: the estimate of an absurd request must not wrap to a small one.
std::uint64_t times(std::uint64_t a, std::uint64_t b) {
  return (b != 0 && a > kMax / b) ? kMax : a * b;
}

std::string count(std::uint64_t n) {
  std::string digits = std::to_string(n);
  for (int at = static_cast<int>(digits.size()) - 3; at > 0; at -= 3) {
    digits.insert(static_cast<std::size_t>(at), ",");
  }
  return digits;
}

// What one ray costs among `primitives`, and how that reads.
struct RayCost {
  std::uint64_t steps;
  std::string text;
};

RayCost ray_cost(std::uint64_t primitives, const char* what, bool accelerated) {
  if (!accelerated) {
    return {std::max<std::uint64_t>(primitives, 1),
            count(primitives) + " " + what + " each (enable_acceleration false)"};
  }
  // An octree halves the candidates at each level it descends, about.
  const auto levels = static_cast<std::uint64_t>(
      std::ceil(std::log2(static_cast<double>(std::max<std::uint64_t>(primitives, 2)))));
  return {levels, count(levels) + " octree levels over " + count(primitives) + " " + what};
}

WorkEstimate estimate(std::uint64_t rays, const std::string& rays_text, const RayCost& cost,
                      std::string keys) {
  return {times(rays, cost.steps), rays_text + " x " + cost.text, std::move(keys)};
}

std::string gigasteps(std::uint64_t steps) {
  char text[64];
  std::snprintf(text, sizeof text, "%.3g G", static_cast<double>(steps) / kWorkUnit);
  return text;
}

}  // namespace

void check_work_budget(const WorkEstimate& estimate, double max_work) {
  if (max_work <= 0 || static_cast<double>(estimate.steps) <= max_work * kWorkUnit) return;
  char budget[64];
  std::snprintf(budget, sizeof budget, "%g", max_work);
  throw WorkBudgetError("this work is about " + gigasteps(estimate.steps) + " ray steps (" +
                            estimate.made_of + "), more than max_work = " + budget +
                            " G: ask for less (" + estimate.keys +
                            "), or raise max_work (a server's --max-work caps every job's)",
                        estimate.steps);
}

WorkEstimate cloud_occlusion_work(std::size_t points, std::size_t viewpoints,
                                  std::uint64_t rays_per_viewpoint, bool exterior,
                                  bool accelerated) {
  const std::uint64_t rays = times(times(rays_per_viewpoint, viewpoints), exterior ? 2 : 1);
  return estimate(
      rays,
      count(rays) + " rays (" + count(rays_per_viewpoint) + " from each of " + count(viewpoints) +
          " viewpoints" + (exterior ? ", twice for exterior" : "") + ")",
      ray_cost(points, "points", accelerated), "num_rays_per_vp, num_vp, pattern or viewpoints");
}

WorkEstimate mesh_occlusion_work(const TriangleMesh& mesh, double samples_per_unit_area,
                                 std::size_t viewpoints, bool accelerated) {
  const std::uint64_t samples = total_samples(mesh, samples_per_unit_area);
  const std::uint64_t rays = times(samples, viewpoints);
  return estimate(rays,
                  count(rays) + " shadow rays (" + count(samples) + " samples x " +
                      count(viewpoints) + " viewpoints)",
                  ray_cost(mesh.face_count(), "faces", accelerated),
                  "samples_per_unit_area, pattern or viewpoints");
}

WorkEstimate scan_work(std::size_t points, std::size_t viewpoints, bool accelerated) {
  const std::uint64_t rays = times(points, viewpoints);
  return estimate(rays,
                  count(rays) + " shadow rays (" + count(points) + " points x " +
                      count(viewpoints) + " viewpoints)",
                  ray_cost(points, "points", accelerated), "num_vp, pattern or viewpoints");
}

namespace {

// plan's rays: every target's to every candidate, and with `intervisible`
// one between every two candidates, through the octree over `primitives`.
WorkEstimate plan_work(std::uint64_t targets, const char* what, std::uint64_t primitives,
                       const char* primitive_name, std::size_t candidates, bool intervisible,
                       std::size_t refine_positions, const std::string& keys) {
  const std::uint64_t pairs =
      intervisible ? times(candidates, candidates > 0 ? candidates - 1 : 0) / 2 : 0;
  const std::uint64_t coverage = times(targets, candidates);
  const std::uint64_t refine = times(targets, refine_positions);
  std::uint64_t rays = coverage > kMax - pairs ? kMax : coverage + pairs;
  rays = rays > kMax - refine ? kMax : rays + refine;
  std::string text =
      count(rays) + " shadow rays (" + count(targets) + " " + what + " x " + count(candidates) +
      " candidates" + (intervisible ? ", and " + count(pairs) + " between candidates" : "") +
      (refine_positions > 0
           ? ", and x " + count(refine_positions) + " positions the refinement may try"
           : "") +
      ")";
  return estimate(rays, text, ray_cost(primitives, primitive_name, true),
                  keys + "fewer candidates: a larger spacing or a shorter candidates file" +
                      (intervisible ? ", or no intervisible" : "") +
                      (refine_positions > 0 ? ", or no refine" : ""));
}

}  // namespace

WorkEstimate plan_filter_work(std::size_t positions, std::uint64_t primitives, bool mesh,
                              std::size_t stations) {
  // Each position's probes (every one of the sphere's directions at most),
  // two rays to and past each of a cloud's stations (what they saw empty),
  // and its clearance: a look-up in the points' cells, or a test of every face.
  const std::uint64_t per_position =
      kOutsideProbeRays + (mesh ? kInsideProbeRays : 0) + 2 * std::uint64_t{stations};
  const std::uint64_t probes = times(positions, per_position);
  const RayCost cost = ray_cost(primitives, mesh ? "faces" : "points", true);
  const std::uint64_t clearance = times(positions, mesh ? primitives : cost.steps);
  const std::uint64_t steps = times(probes, cost.steps);
  return {steps > kMax - clearance ? kMax : steps + clearance,
          count(positions) + " positions' free-space probes (" + count(probes) + " rays x " +
              cost.text + ") and clearance (" + count(clearance) +
              (mesh ? " face tests)" : " point-cell steps)"),
          "a larger spacing or a shorter candidates file"};
}

WorkEstimate one_after_the_other(const WorkEstimate& first, const WorkEstimate& then) {
  return {first.steps > kMax - then.steps ? kMax : first.steps + then.steps,
          first.made_of + ", then " + then.made_of, then.keys};
}

WorkEstimate plan_mesh_work(const TriangleMesh& mesh, double samples_per_unit_area,
                            std::size_t candidates, bool intervisible,
                            std::size_t refine_positions) {
  return plan_work(total_samples(mesh, samples_per_unit_area), "samples", mesh.face_count(),
                   "faces", candidates, intervisible, refine_positions,
                   "samples_per_unit_area, or ");
}

WorkEstimate plan_cloud_work(std::size_t points, std::size_t candidates, bool intervisible,
                             std::size_t refine_positions) {
  return plan_work(points, "points", points, "points", candidates, intervisible, refine_positions,
                   "");
}

}  // namespace occlusion
