#pragma once
// The viewer's live station over a scene already in memory: what a scanner
// placed at a position sees, by -fscan's rule for a cloud and -moc's for a
// mesh, from the keys those jobs take (scan_keys, mesh_occlusion_keys), so
// the live answer is what `scan` or `mesh_occlusion` would give for that one
// viewpoint. The model (discs, spheres or the mesh's samples) and its octree
// are built once per scene and settings (analysis/station_view.hpp); each
// position then traces one ray per point or sample. A scanner's limits (the
// keys `plan` declares for them: plan_limit_keys) apply as the plan's
// coverage applies them, so the live answer is also what a plan with those
// limits counts for a station there.

#include <json/value.h>

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "occlusion/analysis/station_view.hpp"
#include "occlusion/app/mesh_occlusion_job.hpp"
#include "occlusion/app/scan_job.hpp"
#include "occlusion/core/mesh.hpp"
#include "occlusion/core/point_cloud.hpp"
#include "occlusion/core/progress.hpp"

namespace occlusion {

struct LiveStationSight {
  Json::Value json;                 // position, counts, fraction, trace time
  std::vector<std::uint16_t> seen;  // clouds: per point 1 (seen) or 0, as -fscan's visible_count
  std::vector<float> face_seen_fraction;  // meshes: per face
};

class LiveStation {
 public:
  // The model from the request's point keys (primitive, point_radius,
  // disc_coverage, normal_neighbours, self_tolerance, octree keys, threads);
  // its viewpoints, outputs and station filter are not used. UsageError when
  // the model or one trace would exceed max_memory_mb / max_work (the
  // request's, as the job checks them).
  // The station keeps `cloud` (its tracer refers to it).
  static std::shared_ptr<const LiveStation> for_cloud(std::shared_ptr<const PointCloud> cloud,
                                                      const ScanRequest& request,
                                                      const Progress& progress = {});
  // The samples and octree from samples_per_unit_area, seed and the octree keys.
  static std::shared_ptr<const LiveStation> for_mesh(const TriangleMesh& mesh,
                                                     const MeshOcclusionRequest& request,
                                                     const Progress& progress = {});

  // `position` in the file's frame (a cloud's global shift added back, as
  // jobs take viewpoints); `limits` as station_limits(PlanRequest) gives
  // them. UsageError for a position that is not finite or too far to trace
  // in float, or limits out of range.
  LiveStationSight see(const Eigen::Vector3d& position, const StationLimits& limits = {}) const;

  // What the settings name: equal keys, the same model (the server keeps one per scene).
  static std::string settings_key(const ScanRequest& request);
  static std::string settings_key(const MeshOcclusionRequest& request);

  // The model as traced: {"targets": "points"|"samples", "point_model", "build_seconds", ...}.
  const Json::Value& model() const { return model_; }
  const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  LiveStation() = default;

  Eigen::Vector3d shift_ = Eigen::Vector3d::Zero();
  std::shared_ptr<const PointCloud> points_;
  std::unique_ptr<CloudStationView> cloud_;
  std::unique_ptr<MeshStationView> mesh_;
  Json::Value model_;
  std::vector<std::string> warnings_;
};

}  // namespace occlusion
