#pragma once
// What one scanner station sees, for a station that moves: the point model
// (discs or spheres) or the mesh and its octree are built once, and each new
// position traces one ray per point (or per surface sample). The rules are
// -fscan's for clouds (scan.hpp, through its ScanTracer) and -moc's
// for meshes (mesh_occlusion.hpp: mesh_shadow_ray, the sample's own face
// ignored), so a position answers what `scan` or `mesh_occlusion` with that
// one viewpoint would, without their build. The viewer's live station (a
// marker dragged across a scan) asks it many times a second. A scanner's
// limits apply as scan planning applies them (station_visibility.hpp:
// StationLimitTest), so a position answers what a plan's coverage counts for
// a station there.
//
// Both are immutable once built: one view may answer several threads at once.

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "occlusion/analysis/mesh_occlusion.hpp"
#include "occlusion/analysis/mesh_sampling.hpp"
#include "occlusion/analysis/scan.hpp"
#include "occlusion/analysis/scan_tracer.hpp"
#include "occlusion/analysis/station_visibility.hpp"
#include "occlusion/analysis/surfel_estimation.hpp"
#include "occlusion/core/mesh.hpp"
#include "occlusion/core/octree.hpp"
#include "occlusion/core/point_cloud.hpp"
#include "occlusion/core/progress.hpp"
#include "occlusion/core/triangle_octree.hpp"

namespace occlusion {

struct CloudStationSight {
  std::vector<std::uint8_t> seen;  // per point: 1 when the station sees it
  std::size_t seen_points = 0;
  double trace_seconds = 0.0;
};

class CloudStationView {
 public:
  // `surfels`: the disc model of `cloud` (kept by the view), or none for
  // spheres of options.point_radius. `cloud` must outlive the view.
  // options.surfels and options.field_of_view are ignored: the station is a
  // new one that turns all the way round. Throws std::invalid_argument as
  // scan_cloud does; Cancelled on cancel.
  CloudStationView(const PointCloud& cloud, std::optional<SurfelEstimate> surfels,
                   const ScanOptions& options, const Progress& progress = {});
  CloudStationView(const CloudStationView&) = delete;  // the tracer points into it
  CloudStationView& operator=(const CloudStationView&) = delete;

  // `position` in the cloud's local frame; a point outside `limits` is not
  // seen (and not traced). std::invalid_argument for a position that is not
  // finite or too far for float (scan_cloud's checks), or limits out of range.
  CloudStationSight see(const Eigen::Vector3d& position, const StationLimits& limits = {}) const;

  std::size_t size() const { return indices_.size(); }
  const OctreeStats& octree() const { return tracer_->stats(); }
  double build_seconds() const { return build_seconds_; }

 private:
  ScanOptions options_;
  std::optional<SurfelEstimate> surfels_;
  std::vector<std::uint32_t> indices_;  // 0, 1, ..., n - 1: every point is a target
  Eigen::Vector3f lo_, hi_;             // the cloud's box, for the precision check
  double radius_ = 0.0;                 // the length rays must resolve
  std::unique_ptr<ScanTracer> tracer_;
  double build_seconds_ = 0.0;
};

struct MeshStationSight {
  std::vector<float> face_seen_fraction;  // per face: its samples the station sees / its samples
  double visible_area = 0.0;
  double total_area = 0.0;
  double trace_seconds = 0.0;
};

class MeshStationView {
 public:
  // Samples the faces as compute_mesh_occlusion does (options' density and
  // seed) and builds the octree around the mesh's centre. Throws as
  // compute_mesh_occlusion does.
  MeshStationView(const TriangleMesh& mesh, const MeshOcclusionOptions& options,
                  const Progress& progress = {});

  // A sample outside `limits` (its face's normal for the incidence) is not seen.
  MeshStationSight see(const Eigen::Vector3d& position, const StationLimits& limits = {}) const;

  std::size_t faces() const { return areas_.size(); }
  std::size_t samples() const { return samples_.size(); }
  const OctreeStats& octree() const { return tree_->stats(); }
  double build_seconds() const { return build_seconds_; }

 private:
  MeshOcclusionOptions options_;
  MeshSamples samples_;
  std::vector<double> areas_;
  std::vector<Eigen::Vector3f> normals_;  // per face, for the incidence limit
  Eigen::Vector3d origin_, lo_, hi_;
  double epsilon_ = 0.0, reach_ = 0.0;
  std::unique_ptr<TriangleOctree> tree_;
  double build_seconds_ = 0.0;
};

}  // namespace occlusion
