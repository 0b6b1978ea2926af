#pragma once
// Pairwise registration: a source scan's pose onto a target scan refined
// from an initial pose, coarse to fine, on PCL's registration classes.
//
// The pyramid. Every level registers voxel-grid copies of both clouds (one
// centroid per occupied voxel), starting from the level before's pose. The
// finest voxel is kFinestVoxelPerSpacing x the clouds' point spacing (the
// larger of the two medians, analysis/point_spacing.hpp), each coarser level
// kVoxelRatio x the one below, and a level's search distance (the farthest a
// correspondence may be) kSearchPerVoxel x its voxel. So the defaults scale
// with the scans: a Kinect frame (spacing ~2 mm) starts at 3.6 cm voxels and
// an 11 cm search, PCL's tutorial laser room (spacing 2.7 cm) at 49 cm voxels
// and a 1.5 m search, which is about how far off the initial pose may be.
//
// The methods. gicp (the default): PCL's Generalized ICP, plane to plane on
// each point's local covariance. On the PCL tutorial pair, from the
// tutorial's guess and from starts 0.05 rad and 0.2 m off it, and on
// simulated scans of a furnished room, every level converged and the pose
// came back to within a millimetre of the others (or of the truth)
// (tests/analysis/registration_test.cpp). icp_plane: PCL's ICP with the
// point-to-plane linear least squares step; it reached the same pose on the
// tutorial pair (7 mm away) but ran its coarsest level to max_iterations.
// ndt: PCL's NormalDistributionsTransform as in its tutorial, cells the
// level's search distance; the same pose within 4 mm and 0.15 degrees.
//
// Nothing is random: voxel grids, normals and the registrations are
// deterministic, so the same inputs give the same pose.
//
// What is judged, at full resolution after the last level: the share of
// source points with a target point within `evaluation distance` (the finest
// level's search distance) (overlap), and the RMS of those points' distances
// to the plane of their nearest target points. The pair is refused (RegistrationRefused) when the
// overlap at the initial pose's coarsest search distance is below min_overlap / 4 (the scans do not
// meet at all), when the final overlap is below min_overlap, when the last level did not converge,
// or when the pose moved farther than the pyramid's reach (more than the coarsest search distance,
// or max_rotation): such a pose is a different local minimum, not a refinement.

#include <Eigen/Geometry>
#include <stdexcept>
#include <string>
#include <vector>

#include "occlusion/core/point_cloud.hpp"
#include "occlusion/core/progress.hpp"

namespace occlusion {

inline constexpr double kFinestVoxelPerSpacing = 2.0;
inline constexpr double kVoxelRatio = 3.0;
inline constexpr double kSearchPerVoxel = 3.0;

enum class RegistrationMethod { kGicp, kIcpPlane, kNdt };
// "gicp", "icp_plane", "ndt"; the parser throws std::invalid_argument.
const char* registration_method_name(RegistrationMethod method);
RegistrationMethod parse_registration_method(const std::string& name);

struct RegistrationOptions {
  RegistrationMethod method = RegistrationMethod::kGicp;
  unsigned levels = 3;
  // The finest voxel; 0: kFinestVoxelPerSpacing x the point spacing.
  double finest_voxel = 0.0;
  // The coarsest level's search distance; 0: kSearchPerVoxel x its voxel.
  // Finer levels' shrink with their voxels.
  double max_distance = 0.0;
  unsigned max_iterations = 50;  // per level
  double min_overlap = 0.5;      // share of source points, at the end
  double max_rotation_deg = 30.0;
  unsigned threads = 0;
};

struct RegistrationLevel {
  double voxel = 0.0;
  double search_distance = 0.0;
  std::size_t source_points = 0, target_points = 0;  // after the voxel grid
  unsigned iterations = 0;
  bool converged = false;  // PCL's criteria met before max_iterations
};

struct RegistrationFit {
  double overlap = 0.0;  // share of source points with a target point within the distance
  double rms = 0.0;      // over those points, to their nearest target points' plane
  std::size_t matched = 0;
};

struct RegistrationResult {
  // Both map source coordinates to target coordinates (the clouds' original
  // frames, shifts included).
  Eigen::Isometry3d initial = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d refined = Eigen::Isometry3d::Identity();
  double source_spacing = 0.0, target_spacing = 0.0;
  double evaluation_distance = 0.0;
  RegistrationFit before, after;          // at evaluation_distance, full resolution
  double moved_translation = 0.0;         // |refined origin of the source - initial's|, metres
  double moved_rotation_deg = 0.0;        // angle of initial^-1 * refined's rotation
  std::vector<RegistrationLevel> levels;  // coarsest first
  bool converged = false;
  double seconds = 0.0;
};

// A pair that cannot be registered as asked: what() says why and what to do.
// `result` holds what was measured (the pose reached, overlap, levels).
struct RegistrationRefused : std::runtime_error {
  RegistrationRefused(const std::string& reason, RegistrationResult measured)
      : std::runtime_error(reason), result(std::move(measured)) {}
  RegistrationResult result;
};

// Throws std::invalid_argument for bad options or clouds with too few
// distinct points, RegistrationRefused as above.
RegistrationResult register_pair(const PointCloud& source, const PointCloud& target,
                                 const Eigen::Isometry3d& initial,
                                 const RegistrationOptions& options = {},
                                 const Progress& progress = {});

// The angle of `pose`'s rotation, in degrees (0 to 180), as the report and
// the faces state a pose and how far it moved.
inline double rotation_degrees(const Eigen::Isometry3d& pose) {
  return Eigen::AngleAxisd(pose.linear()).angle() * 180.0 / 3.14159265358979323846;
}

// The overlap and RMS of `source` placed by `pose` onto `target`, within
// `distance`, at full resolution.
RegistrationFit measure_fit(const PointCloud& source, const PointCloud& target,
                            const Eigen::Isometry3d& pose, double distance, unsigned threads = 0);

}  // namespace occlusion
