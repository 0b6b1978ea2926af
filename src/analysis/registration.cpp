#include "occlusion/analysis/registration.hpp"

#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unordered_map>

#include "analysis_support.hpp"
#include "occlusion/analysis/point_spacing.hpp"
#include "occlusion/core/parallel.hpp"
#include "pcl_frame.hpp"
#include "registration_align.hpp"

namespace occlusion {

namespace {

constexpr const char* kName = "register";

std::string metres(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

std::string percent(double share) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f %%", 100.0 * share);
  return text;
}

// A cloud in PCL's local frame: its points minus `centre` (the original
// frame's coordinates of its bounds' centre), as pcl_frame.hpp asks.
struct LocalCloud {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // original frame
  std::vector<Eigen::Vector3f> points;
};

LocalCloud local_cloud(const PointCloud& cloud) {
  LocalCloud local;
  const Eigen::Vector3d centre = pcl_frame::centre_of(cloud.positions);
  local.centre = cloud.to_original(centre);
  local.points.reserve(cloud.size());
  for (const auto& p : cloud.positions)
    local.points.push_back(pcl_frame::to_local(p, centre, kName));
  return local;
}

// One centroid per occupied voxel, in the order of the voxels' keys, so the
// answer does not depend on the points' order.
std::vector<Eigen::Vector3f> voxel_centroids(const std::vector<Eigen::Vector3f>& points,
                                             double voxel) {
  struct Sum {
    Eigen::Vector3d total = Eigen::Vector3d::Zero();
    std::size_t count = 0;
  };
  // 21 bits per axis: 2 million voxels across; a cloud wider than that at
  // this voxel is refused by the caller's checks first.
  const auto key = [voxel](const Eigen::Vector3f& p) {
    std::uint64_t k = 0;
    for (int a = 0; a < 3; ++a) {
      const auto cell = static_cast<std::int64_t>(std::floor(p[a] / voxel)) + (1 << 20);
      k = (k << 21) | static_cast<std::uint64_t>(cell & ((1 << 21) - 1));
    }
    return k;
  };
  std::unordered_map<std::uint64_t, Sum> sums;
  sums.reserve(points.size() / 4 + 16);
  for (const auto& p : points) {
    Sum& sum = sums[key(p)];
    sum.total += p.cast<double>();
    ++sum.count;
  }
  std::vector<std::pair<std::uint64_t, Eigen::Vector3f>> cells;
  cells.reserve(sums.size());
  for (const auto& [k, sum] : sums) {
    cells.emplace_back(k, (sum.total / static_cast<double>(sum.count)).cast<float>());
  }
  std::sort(cells.begin(), cells.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Eigen::Vector3f> centroids;
  centroids.reserve(cells.size());
  for (const auto& cell : cells) centroids.push_back(cell.second);
  return centroids;
}

Eigen::Isometry3d translation(const Eigen::Vector3d& t) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = t;
  return pose;
}

// original-frame pose <-> the same map between the PCL local frames.
Eigen::Matrix4d to_local_pose(const Eigen::Isometry3d& pose, const LocalCloud& source,
                              const LocalCloud& target) {
  return (translation(-target.centre) * pose * translation(source.centre)).matrix();
}
Eigen::Isometry3d to_original_pose(const Eigen::Matrix4d& local, const LocalCloud& source,
                                   const LocalCloud& target) {
  Eigen::Isometry3d pose;
  pose.matrix() = local;
  Eigen::Isometry3d original = translation(target.centre) * pose * translation(-source.centre);
  // Re-orthonormalise: PCL composes in float.
  const Eigen::Matrix3d r = original.linear();
  original.linear() = Eigen::Quaterniond(r).normalized().toRotationMatrix();
  return original;
}

// Neighbours of a target point that give its plane: a 3 x 3 patch of a
// scan's grid and a few beyond.
constexpr int kPlaneNeighbours = 8;

// The fit within `distance` of the source's points under the local pose. A
// matched point's residual is its distance to the plane of its nearest
// target points (their centroid and least-variance axis), not to the
// nearest point: two scans sample a surface at different spots, and the
// distance between samples would count the scans' spacing (centimetres, far
// from a laser) as misfit.
RegistrationFit fit_of(const std::vector<Eigen::Vector3f>& source,
                       const pcl::KdTreeFLANN<pcl::PointXYZ>& tree, const Eigen::Matrix4d& pose,
                       double distance, unsigned threads, bool planes = true) {
  const Eigen::Matrix3d r = pose.topLeftCorner<3, 3>();
  const Eigen::Vector3d t = pose.topRightCorner<3, 1>();
  const double max_squared = distance * distance;
  const auto& target = *tree.getInputCloud();
  std::vector<double> squared(source.size(), -1.0);
  parallel_for(source.size(), 4096, threads, [&](std::size_t begin, std::size_t end) {
    pcl::Indices nearest(kPlaneNeighbours);
    std::vector<float> distances(kPlaneNeighbours);
    for (std::size_t i = begin; i < end; ++i) {
      const Eigen::Vector3d q = r * source[i].cast<double>() + t;
      // Beyond PCL's reach is beyond any search distance: unmatched.
      if (!(q.cwiseAbs().maxCoeff() <= pcl_frame::kMaxLocalCoordinate)) continue;
      const pcl::PointXYZ query(static_cast<float>(q.x()), static_cast<float>(q.y()),
                                static_cast<float>(q.z()));
      const int found =
          tree.nearestKSearch(query, planes ? kPlaneNeighbours : 1, nearest, distances);
      if (found < 1 || distances[0] > max_squared) continue;
      squared[i] = distances[0];
      if (found < 3) continue;
      Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
      for (int k = 0; k < found; ++k)
        centroid += target[nearest[k]].getVector3fMap().cast<double>();
      centroid /= found;
      Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
      for (int k = 0; k < found; ++k) {
        const Eigen::Vector3d d = target[nearest[k]].getVector3fMap().cast<double>() - centroid;
        covariance += d * d.transpose();
      }
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
      // A plane only where the neighbours spread in two directions; along a
      // line (a scan line's edge) the point distance stands.
      if (solver.eigenvalues()(1) > 10.0 * solver.eigenvalues()(0)) {
        const double along_normal = solver.eigenvectors().col(0).dot(q - centroid);
        squared[i] = along_normal * along_normal;
      }
    }
  });
  RegistrationFit fit;
  double sum = 0.0;
  for (const double d : squared) {
    if (d < 0.0) continue;
    sum += d;
    ++fit.matched;
  }
  fit.overlap = source.empty() ? 0.0 : static_cast<double>(fit.matched) / source.size();
  fit.rms = fit.matched == 0 ? 0.0 : std::sqrt(sum / static_cast<double>(fit.matched));
  return fit;
}

pcl::PointCloud<pcl::PointXYZ>::Ptr pcl_points(const std::vector<Eigen::Vector3f>& points) {
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  cloud->reserve(points.size());
  for (const auto& p : points) cloud->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
  return cloud;
}

void check(const RegistrationOptions& options) {
  const auto fail = [](const std::string& what) {
    throw std::invalid_argument(std::string(kName) + ": " + what);
  };
  if (options.levels < 1 || options.levels > 8) fail("levels must be 1 to 8");
  if (!(options.finest_voxel >= 0.0) || !std::isfinite(options.finest_voxel)) {
    fail("finest_voxel must be >= 0 (0: from the point spacing)");
  }
  if (!(options.max_distance >= 0.0) || !std::isfinite(options.max_distance)) {
    fail("max_distance must be >= 0 (0: from the voxels)");
  }
  if (options.max_iterations < 1) fail("max_iterations must be >= 1");
  if (!(options.min_overlap > 0.0 && options.min_overlap <= 1.0)) {
    fail("min_overlap must be in (0, 1]");
  }
  if (!(options.max_rotation_deg > 0.0 && options.max_rotation_deg <= 180.0)) {
    fail("max_rotation must be in (0, 180] degrees");
  }
}

double spacing_of(const PointCloud& cloud, const char* which, unsigned threads) {
  try {
    return measure_point_spacing(cloud, threads).spacing;
  } catch (const std::invalid_argument&) {
    throw std::invalid_argument(std::string(kName) + ": the " + which +
                                " cloud has fewer than two distinct points");
  }
}

}  // namespace

const char* registration_method_name(RegistrationMethod method) {
  switch (method) {
    case RegistrationMethod::kGicp:
      return "gicp";
    case RegistrationMethod::kIcpPlane:
      return "icp_plane";
    case RegistrationMethod::kNdt:
      return "ndt";
  }
  return "gicp";
}

RegistrationMethod parse_registration_method(const std::string& name) {
  for (const auto method :
       {RegistrationMethod::kGicp, RegistrationMethod::kIcpPlane, RegistrationMethod::kNdt}) {
    if (name == registration_method_name(method)) return method;
  }
  throw std::invalid_argument("registration method must be gicp, icp_plane or ndt, not '" + name +
                              "'");
}

RegistrationFit measure_fit(const PointCloud& source, const PointCloud& target,
                            const Eigen::Isometry3d& pose, double distance, unsigned threads) {
  const LocalCloud s = local_cloud(source), t = local_cloud(target);
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud(pcl_points(t.points));
  return fit_of(s.points, tree, to_local_pose(pose, s, t), distance, threads);
}

RegistrationResult register_pair(const PointCloud& source, const PointCloud& target,
                                 const Eigen::Isometry3d& initial,
                                 const RegistrationOptions& options, const Progress& progress) {
  const auto start = analysis_support::Clock::now();
  check(options);
  if (!initial.matrix().allFinite()) {
    throw std::invalid_argument(std::string(kName) + ": the initial pose is not finite");
  }
  RegistrationResult result;
  result.initial = initial;
  result.refined = initial;
  progress("measuring point spacing", 0.0);
  result.source_spacing = spacing_of(source, "source", options.threads);
  result.target_spacing = spacing_of(target, "target", options.threads);
  const double finest =
      options.finest_voxel > 0.0
          ? options.finest_voxel
          : kFinestVoxelPerSpacing * std::max(result.source_spacing, result.target_spacing);
  // Levels, coarsest first.
  for (unsigned l = 0; l < options.levels; ++l) {
    RegistrationLevel level;
    const double steps_down = static_cast<double>(options.levels - 1 - l);
    level.voxel = finest * std::pow(kVoxelRatio, steps_down);
    level.search_distance =
        options.max_distance > 0.0
            ? options.max_distance / std::pow(kVoxelRatio, static_cast<double>(l))
            : kSearchPerVoxel * level.voxel;
    result.levels.push_back(level);
  }
  result.evaluation_distance = result.levels.back().search_distance;
  const double reach = result.levels.front().search_distance;

  const LocalCloud s = local_cloud(source), t = local_cloud(target);
  for (const LocalCloud* cloud : {&s, &t}) {
    for (const auto& p : cloud->points) {
      if (p.cast<double>().cwiseAbs().maxCoeff() / result.levels.back().voxel >= (1 << 20)) {
        throw std::invalid_argument(
            std::string(kName) + ": the clouds span more than a million voxels of " +
            metres(result.levels.back().voxel) +
            " (the finest level); give a larger finest_voxel or crop the clouds");
      }
    }
  }
  pcl::KdTreeFLANN<pcl::PointXYZ> full_target;
  full_target.setInputCloud(pcl_points(t.points));
  Eigen::Matrix4d pose = to_local_pose(initial, s, t);
  result.before = fit_of(s.points, full_target, pose, result.evaluation_distance, options.threads);
  const double min_meeting = options.min_overlap / 4.0;
  const RegistrationFit meeting =
      fit_of(s.points, full_target, pose, reach, options.threads, false);
  progress.check_cancel();
  if (meeting.overlap < min_meeting) {
    throw RegistrationRefused(
        std::string(kName) + ": the scans do not overlap at the initial pose: " +
            percent(meeting.overlap) + " of the source's points have a target point within " +
            metres(reach) + " (the coarsest search distance), below " + percent(min_meeting) +
            " (min_overlap / 4). Give an initial pose that puts the source onto the target "
            "(within about " +
            metres(reach) + "), or a larger max_distance",
        result);
  }

  for (std::size_t l = 0; l < result.levels.size(); ++l) {
    RegistrationLevel& level = result.levels[l];
    progress("registering, level " + std::to_string(l + 1) + " of " +
                 std::to_string(result.levels.size()),
             static_cast<double>(l) / static_cast<double>(result.levels.size()));
    const std::vector<Eigen::Vector3f> sv = voxel_centroids(s.points, level.voxel);
    const std::vector<Eigen::Vector3f> tv = voxel_centroids(t.points, level.voxel);
    level.source_points = sv.size();
    level.target_points = tv.size();
    if (sv.size() < 20 || tv.size() < 20) {
      // Too coarse a grid for this cloud: the finer levels do the work.
      continue;
    }
    const registration_detail::LevelAlignment aligned = registration_detail::align_level(
        options.method, sv, tv, pose, level.voxel, level.search_distance, options.max_iterations);
    level.iterations = aligned.iterations;
    level.converged = aligned.converged;
    if (aligned.pose.allFinite()) pose = aligned.pose;
    progress.check_cancel();
  }
  progress("registering", 1.0);

  result.refined = to_original_pose(pose, s, t);
  const Eigen::Isometry3d change = initial.inverse() * result.refined;
  result.moved_translation = (result.refined.translation() - initial.translation()).norm();
  result.moved_rotation_deg = rotation_degrees(change);
  result.after = fit_of(s.points, full_target, to_local_pose(result.refined, s, t),
                        result.evaluation_distance, options.threads);
  result.converged = result.levels.back().converged;
  result.seconds = analysis_support::seconds_since(start);

  const std::string fit_text = percent(result.after.overlap) + " overlap (source points with a " +
                               "target point within " + metres(result.evaluation_distance) +
                               "), RMS " + metres(result.after.rms);
  if (!result.converged) {
    throw RegistrationRefused(std::string(kName) + ": the finest level did not converge within " +
                                  std::to_string(options.max_iterations) + " iterations (" +
                                  fit_text +
                                  "). Give a better initial pose, or more max_iterations",
                              result);
  }
  if (result.moved_translation > reach || result.moved_rotation_deg > options.max_rotation_deg) {
    throw RegistrationRefused(
        std::string(kName) + ": the pose moved " + metres(result.moved_translation) + " and " +
            metres(result.moved_rotation_deg) +
            " degrees from the initial one, beyond what it "
            "can correct (" +
            metres(reach) + ", the coarsest search distance; max_rotation " +
            metres(options.max_rotation_deg) +
            " degrees): it found another fit, not a "
            "refinement. Give an initial pose within about " +
            metres(reach) + " and " + metres(options.max_rotation_deg) + " degrees of the truth",
        result);
  }
  if (result.after.overlap < options.min_overlap) {
    throw RegistrationRefused(
        std::string(kName) + ": the refined pose leaves the scans overlapping too little: " +
            fit_text + ", below min_overlap " + percent(options.min_overlap) +
            ". Give a better initial pose; if the scans truly share less, lower min_overlap",
        result);
  }
  return result;
}

}  // namespace occlusion
