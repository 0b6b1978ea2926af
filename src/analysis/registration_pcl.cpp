#include <pcl/features/normal_3d.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/registration/gicp.h>
#include <pcl/registration/icp.h>
#include <pcl/registration/ndt.h>
#include <pcl/registration/transformation_estimation_point_to_plane_lls.h>

#include "pcl_quiet.hpp"
#include "registration_align.hpp"

namespace occlusion::registration_detail {

namespace {

// Iterations done: PCL keeps the count protected (NDT alone exposes it).
template <class Base>
struct Counted : Base {
  unsigned iterations() const { return static_cast<unsigned>(this->nr_iterations_); }
};

// Translation steps below this share of the voxel (and rotation steps below
// its angle at 10 voxels) end a level: finer than the grid can tell apart.
constexpr double kStepPerVoxel = 1e-3;

template <class Point>
typename pcl::PointCloud<Point>::Ptr to_pcl(const std::vector<Eigen::Vector3f>& points) {
  auto cloud = pcl::make_shared<pcl::PointCloud<Point>>();
  cloud->resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    (*cloud)[i].x = points[i].x();
    (*cloud)[i].y = points[i].y();
    (*cloud)[i].z = points[i].z();
  }
  return cloud;
}

// Normals from each voxel centroid's 10 nearest (a 3 x 3 patch of a surface's
// voxels and a ring beyond); PCL turns them towards the origin of the local
// frame, which point-to-plane does not care about.
pcl::PointCloud<pcl::PointNormal>::Ptr with_normals(const std::vector<Eigen::Vector3f>& points) {
  auto cloud = to_pcl<pcl::PointNormal>(points);
  pcl::NormalEstimation<pcl::PointNormal, pcl::PointNormal> estimation;
  estimation.setInputCloud(cloud);
  estimation.setKSearch(10);
  estimation.compute(*cloud);
  // A point whose neighbours are collinear has no plane: it cannot pull.
  pcl::Indices finite;
  for (std::size_t i = 0; i < cloud->size(); ++i) {
    if (std::isfinite((*cloud)[i].normal_x)) finite.push_back(static_cast<int>(i));
  }
  auto kept = pcl::make_shared<pcl::PointCloud<pcl::PointNormal>>(*cloud, finite);
  return kept;
}

template <class Aligner, class Cloud>
LevelAlignment run(Aligner& aligner, const Cloud& source, const Cloud& target,
                   const Eigen::Matrix4d& guess, double voxel, unsigned max_iterations) {
  aligner.setInputSource(source);
  aligner.setInputTarget(target);
  aligner.setMaximumIterations(static_cast<int>(max_iterations));
  aligner.setTransformationEpsilon(kStepPerVoxel * voxel * kStepPerVoxel * voxel);
  typename std::remove_reference_t<decltype(*source)> aligned;
  aligner.align(aligned, guess.cast<float>());
  LevelAlignment level;
  level.pose = aligner.getFinalTransformation().template cast<double>();
  level.iterations = aligner.iterations();
  level.converged = aligner.hasConverged() && level.iterations < max_iterations;
  return level;
}

}  // namespace

LevelAlignment align_level(RegistrationMethod method, const std::vector<Eigen::Vector3f>& source,
                           const std::vector<Eigen::Vector3f>& target, const Eigen::Matrix4d& guess,
                           double voxel, double search_distance, unsigned max_iterations) {
  const analysis_support::QuietPcl quiet;
  switch (method) {
    case RegistrationMethod::kGicp: {
      using Points = pcl::PointCloud<pcl::PointXYZ>;
      Counted<pcl::GeneralizedIterativeClosestPoint<pcl::PointXYZ, pcl::PointXYZ>> gicp;
      gicp.setMaxCorrespondenceDistance(search_distance);
      gicp.setRotationEpsilon(kStepPerVoxel / 10.0);
      const Points::Ptr s = to_pcl<pcl::PointXYZ>(source), t = to_pcl<pcl::PointXYZ>(target);
      return run(gicp, s, t, guess, voxel, max_iterations);
    }
    case RegistrationMethod::kIcpPlane: {
      using Point = pcl::PointNormal;
      Counted<pcl::IterativeClosestPoint<Point, Point>> icp;
      icp.setTransformationEstimation(
          pcl::make_shared<
              pcl::registration::TransformationEstimationPointToPlaneLLS<Point, Point>>());
      icp.setMaxCorrespondenceDistance(search_distance);
      // Steps this small in a point-to-plane fit are the plane's own sliding.
      icp.setEuclideanFitnessEpsilon(0.0);
      return run(icp, with_normals(source), with_normals(target), guess, voxel, max_iterations);
    }
    case RegistrationMethod::kNdt: {
      using Points = pcl::PointCloud<pcl::PointXYZ>;
      Counted<pcl::NormalDistributionsTransform<pcl::PointXYZ, pcl::PointXYZ>> ndt;
      // As PCL's tutorial (its 1 m cells and 0.1 m step for a room), scaled
      // to the level: cells span the search distance, steps a third of it.
      ndt.setResolution(static_cast<float>(search_distance));
      ndt.setStepSize(search_distance / 3.0);
      const Points::Ptr s = to_pcl<pcl::PointXYZ>(source), t = to_pcl<pcl::PointXYZ>(target);
      return run(ndt, s, t, guess, voxel, max_iterations);
    }
  }
  return {};
}

}  // namespace occlusion::registration_detail
