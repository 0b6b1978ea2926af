#pragma once
// The `mesh_occlusion` job (-moc): one request struct that the CLI flags, the
// JSON config and the server all fill, one report they all print.

#include <json/value.h>

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "occlusion/analysis/mesh_occlusion.hpp"
#include "occlusion/app/key.hpp"
#include "occlusion/app/viewpoint_choice.hpp"
#include "occlusion/core/progress.hpp"

namespace occlusion {

struct MeshOcclusionRequest {
  std::string path;  // OBJ or PLY mesh (io/mesh_reader.hpp)
  ViewpointChoice viewpoints = ViewpointChoice::from_pattern(7);
  double samples_per_unit_area = 100.0;
  double octree_resolution = 0.0;  // smallest octree cell edge, scene units; 0 = no limit
  bool enable_acceleration = true;
  std::uint64_t seed = 0;
  unsigned threads = 0;  // 0 = all cores
  std::string out;       // directory for output files; empty = none
  // Refuse, before the work, a request estimated to need more (memory_budget.hpp); 0 = the machine.
  std::uint64_t max_memory_mb = 0;
  // Refuse, before the work, a request estimated to trace more (work_budget.hpp),
  // in G ray steps; 0 = no budget.
  double max_work = 0;
};

struct MeshOcclusionReport {
  MeshOcclusionRequest request;
  MeshOcclusionResult result;
  std::vector<std::string> viewpoint_names;  // "centre", ... or "viewpoint_1", ...
  std::vector<std::string> outputs;          // files written
  std::vector<std::string> warnings;
  // Triangles of no area the reader left out (mesh_read_report.hpp).
  std::size_t degenerate_faces_skipped = 0;
  double load_seconds = 0.0;
  double total_seconds = 0.0;
};

// Checks the request's values; throws UsageError naming the offending option.
void validate(const MeshOcclusionRequest& request);

// Every key of the job (config section occlusion.mesh), declared once.
const Keys<MeshOcclusionRequest>& mesh_occlusion_keys();

// The analysis's options as a request's keys set them, at a sampling density
// (the request's, or -rgoc's raised to min_samples): the mesh job, the
// server's live station and -rgoc on the mesh it estimates trace the same way.
template <class Request>
MeshOcclusionOptions mesh_occlusion_options(const Request& request, double samples_per_unit_area) {
  MeshOcclusionOptions options;
  options.samples_per_unit_area = samples_per_unit_area;
  options.octree.min_cell_size = static_cast<float>(request.octree_resolution);
  options.octree.enable_acceleration = request.enable_acceleration;
  options.seed = request.seed;
  options.threads = request.threads;
  return options;
}
inline MeshOcclusionOptions mesh_occlusion_options(const MeshOcclusionRequest& request) {
  return mesh_occlusion_options(request, request.samples_per_unit_area);
}

// Loads the mesh, computes, writes outputs. Throws UsageError, InputError,
// OutputError, Cancelled.
MeshOcclusionReport run_mesh_occlusion(const MeshOcclusionRequest& request,
                                       const Progress& progress = {});

// What run_mesh_occlusion computes once the mesh is loaded, for a mesh
// already in memory; request.path names it in messages. Nothing is read or
// written (request.out is not looked at).
MeshOcclusionReport run_mesh_occlusion_on(const TriangleMesh& mesh,
                                          const MeshOcclusionRequest& request,
                                          const Progress& progress = {});

// The report as one JSON object with the headline figure `occlusion_level`.
Json::Value to_json(const MeshOcclusionReport& report);

}  // namespace occlusion
