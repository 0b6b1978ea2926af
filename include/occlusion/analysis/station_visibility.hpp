#pragma once
// What each candidate scanner station sees (scan planning, issue 28): the
// coverage matrix of candidates over a cloud's points or a mesh's samples,
// with the same visibility as -fscan (clouds: scan.hpp, discs or spheres) or
// -moc (meshes: mesh_occlusion.hpp's shadow rays), one octree shared by all
// candidates, and a scanner's limits on top. A candidate is a new station:
// it turns all the way round (no laser station's window applies).

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "occlusion/analysis/coverage_matrix.hpp"
#include "occlusion/analysis/mesh_occlusion.hpp"
#include "occlusion/analysis/mesh_sampling.hpp"
#include "occlusion/analysis/scan.hpp"
#include "occlusion/analysis/scan_tracer.hpp"
#include "occlusion/core/mesh.hpp"
#include "occlusion/core/point_cloud.hpp"
#include "occlusion/core/progress.hpp"
#include "occlusion/core/triangle_octree.hpp"

namespace occlusion {

// A scanner's limits. A target outside them is not seen, whatever lies
// between; no ray is traced to it.
struct StationLimits {
  // > 0: a target farther than this from the station is not seen.
  double max_range = 0.0;
  // > 0: nor one whose surface the ray meets more than this far from its
  // normal, in degrees (oriented targets only: discs and mesh samples; a
  // sphere has no normal and is never excluded by it). Surfaces are
  // two-sided: 0 is head-on from either side, 90 grazing.
  double max_incidence_deg = 0.0;
  // The vertical field of view: elevation of the target above the plane
  // normal to `up` through the station, in degrees.
  double min_elevation_deg = -90.0, max_elevation_deg = 90.0;
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
};

// The limits made ready to test many (station, target) pairs.
class StationLimitTest {
 public:
  // Throws std::invalid_argument for limits out of range: a negative or
  // non-finite max_range, max_incidence_deg outside [0, 90], elevations
  // outside [-90, 90] or min > max, an `up` that is zero or not finite.
  explicit StationLimitTest(const StationLimits& limits);
  // Whether a station sees past its limits a target at offset `to_target`
  // from it, whose surface has unit normal `normal` (zero: unoriented).
  bool admits(const Eigen::Vector3d& to_target, const Eigen::Vector3f& normal) const;
  // The same for a cloud's point as the -fscan rule traces it
  // (ScanTracer::target: its disc, or for a sphere its centre, unoriented).
  bool admits_point(const Eigen::Vector3d& station, const ScanTracer::Target& target) const {
    return admits(target.surfel.center.cast<double>() - station, target.surfel.normal);
  }
  // True when no limit is set (every target admitted).
  bool unlimited() const { return unlimited_; }

 private:
  double max_range_squared_ = 0.0;  // 0: none
  double min_cos_incidence_ = 0.0;  // > 0 when an incidence limit is set
  bool incidence_ = false;
  double sin_min_elevation_ = -1.0, sin_max_elevation_ = 1.0;
  bool elevation_ = false;
  Eigen::Vector3d up_ = Eigen::Vector3d::UnitZ();
  bool unlimited_ = true;
};

// Cloud targets: every point, seen by the -fscan rule (scan.hpp) against the
// disc model (options.surfels) or spheres; one octree shared by all
// candidates; options.field_of_view must be unset (candidates turn all the
// way round). Targets of weight 0 are not traced (their bits stay 0).
// Throws std::invalid_argument for an empty cloud, no candidates, a
// non-finite candidate, weights not one per point (or negative), limits out
// of range, or the point model's errors (scan_cloud's); Cancelled on cancel.
CoverageMatrix cloud_station_coverage(const PointCloud& cloud,
                                      const std::vector<Eigen::Vector3d>& candidates,
                                      std::vector<double> target_weight, const ScanOptions& options,
                                      const StationLimits& limits, const Progress& progress = {});

// Mesh targets: the samples of -moc (mesh_sampling.hpp), seen by -moc's
// shadow-ray rule (mesh_shadow_ray, the sample's own face ignored); the
// incidence limit uses the sample's face normal. Same errors, with weights
// one per sample.
CoverageMatrix mesh_station_coverage(const TriangleMesh& mesh, const MeshSamples& samples,
                                     const std::vector<Eigen::Vector3d>& candidates,
                                     std::vector<double> target_weight,
                                     const MeshOcclusionOptions& options,
                                     const StationLimits& limits, const Progress& progress = {});

// What cloud_station_coverage builds once, kept for many questions: the
// octree, the points worth tracing in the order they are traced, and the
// limits; then the rows of any candidates when asked (a selection that needs
// only some rows, a viewer asking what a station dragged to a new place
// sees). cloud_station_coverage is one of these asked once. `cloud`,
// `options` and the surfels must outlive it. Same errors: the cloud's and the
// weights' when built, the candidates' when asked.
class CloudStationVisibility {
 public:
  CloudStationVisibility(const PointCloud& cloud, std::vector<double> target_weight,
                         const ScanOptions& options, const StationLimits& limits,
                         const Progress& progress = {});
  // Row c: what candidates[c] sees. Any thread count (options.threads): one
  // candidate's blocks go to all threads, many candidates spread over them.
  CoverageMatrix coverage(const std::vector<Eigen::Vector3d>& candidates,
                          const Progress& progress = {}) const;
  // As cloud_candidate_intervisibility, on this octree.
  std::vector<std::uint8_t> intervisibility(const std::vector<Eigen::Vector3d>& candidates,
                                            const Progress& progress = {}) const;

 private:
  const PointCloud& cloud_;
  const ScanOptions& options_;
  std::vector<double> weight_;
  StationLimitTest limits_;
  ScanTracer tracer_;
  std::vector<std::uint32_t> order_;         // the points with weight, in tracing order
  std::vector<ScanTracer::Target> targets_;  // targets_[k]: point order_[k]
};

// The same for a mesh's samples. `mesh`, `samples` and `options` must outlive it.
class MeshStationVisibility {
 public:
  MeshStationVisibility(const TriangleMesh& mesh, const MeshSamples& samples,
                        std::vector<double> target_weight, const MeshOcclusionOptions& options,
                        const StationLimits& limits, const Progress& progress = {});
  CoverageMatrix coverage(const std::vector<Eigen::Vector3d>& candidates,
                          const Progress& progress = {}) const;
  std::vector<std::uint8_t> intervisibility(const std::vector<Eigen::Vector3d>& candidates,
                                            const Progress& progress = {}) const;

 private:
  // A sample as its ray is made: relative to origin_, with its face.
  struct Sample {
    Eigen::Vector3d local;
    std::uint32_t face = 0;
  };
  const TriangleMesh& mesh_;
  const MeshSamples& samples_;
  const MeshOcclusionOptions& options_;
  std::vector<double> weight_;
  StationLimitTest limits_;
  // -moc's frame (compute_mesh_occlusion): rays are traced around the centre
  // of the mesh's bounds, and those longer than reach_ cut from the sample's end.
  Eigen::Vector3d origin_;
  double reach_ = 0.0, epsilon_ = 0.0;
  TriangleOctree tree_;
  std::vector<Eigen::Vector3f> normals_;  // per face; zero for a degenerate one
  std::vector<std::uint32_t> order_;
  std::vector<Sample> ordered_;
};

// Per face: its unit normal, zero for a degenerate face (what the incidence
// limit reads for a mesh sample).
std::vector<Eigen::Vector3f> face_unit_normals(const TriangleMesh& mesh);

// Which candidates see each other (registration needs overlap): n x n,
// row-major, symmetric, 1 on the diagonal. Two candidates see each other when
// the segment between them meets no point (the -fscan rule's model, with what
// it ignores near a viewpoint spared at both ends) or no face (-moc's
// tolerance at both ends). Limits do not apply. Same input errors.
std::vector<std::uint8_t> cloud_candidate_intervisibility(
    const PointCloud& cloud, const std::vector<Eigen::Vector3d>& candidates,
    const ScanOptions& options, const Progress& progress = {});
std::vector<std::uint8_t> mesh_candidate_intervisibility(
    const TriangleMesh& mesh, const std::vector<Eigen::Vector3d>& candidates,
    const MeshOcclusionOptions& options, const Progress& progress = {});

}  // namespace occlusion
