#pragma once
// The stages of estimate_mesh (internal to analysis/): segmentation with PCL's
// normals and region growing, then one polygon per cluster. PCL types stop here.

#include <pcl/PointIndices.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/search/kdtree.h>

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "occlusion/analysis/mesh_estimation.hpp"

namespace occlusion::mesh_estimation {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using Normals = pcl::PointCloud<pcl::Normal>;
using Tree = pcl::search::KdTree<pcl::PointXYZ>;

// Normals of every point, in blocks so that progress and cancel are checked.
Normals::Ptr estimate_normals(const Cloud::ConstPtr& cloud, const Tree::Ptr& tree,
                              const RegionGrowingOptions& options, const Progress& progress);

struct Segmentation {
  std::vector<pcl::PointIndices> clusters;  // within the size limits, PCL's order
  RegionSizes regions;
};

// Region growing over the tree the normals used (not built again).
Segmentation grow_regions(const Cloud::ConstPtr& cloud, const Normals::Ptr& normals,
                          const Tree::Ptr& tree, const RegionGrowingOptions& options,
                          const Progress& progress);

// A cluster's plane and its projected inliers, in the plane's own coordinates.
struct ClusterPlane {
  Eigen::Vector3d normal, axis_u, axis_v;  // orthonormal, right-handed
  Eigen::Vector3d origin;                  // mean of the projected inliers
  double offset = 0.0;                     // normal . p + offset = 0
  std::vector<Eigen::Vector2f> inliers_2d;
};

// The polygon a cluster became, in 3-D, counter-clockwise around the normal.
struct ClusterPolygon {
  std::vector<Eigen::Vector3d> vertices;
  Eigen::Vector3d centroid;
  double area = 0.0;
};

// Either a plane or why there is none.
struct PlaneOutcome {
  std::optional<ClusterPlane> plane;
  std::size_t inliers = 0;
  std::size_t edge_points = 0;
  SkipReason reason = SkipReason::kNoPlane;
  std::string detail;
};
PlaneOutcome fit_plane(const Cloud::ConstPtr& cloud, const pcl::PointIndices& cluster,
                       const RegionGrowingOptions& options);

// Points in no cluster (label < 0) that planes took, and which planes (up to
// three: a corner's), -1 for none. Adds them to the planes' inliers_2d.
struct EdgePoints {
  std::vector<pcl::index_t> points;
  std::vector<std::array<std::int32_t, 3>> planes;
};
EdgePoints recover_edge_points(const Cloud::ConstPtr& cloud, const Tree& tree,
                               const std::vector<std::int32_t>& label,
                               std::vector<PlaneOutcome>& planes,
                               const RegionGrowingOptions& options);

struct PolygonOutcome {
  std::optional<ClusterPolygon> polygon;
  SkipReason reason = SkipReason::kHullFailed;
  std::string detail;
};
PolygonOutcome build_polygon(const ClusterPlane& plane);

// Ratio of the second-largest to the largest standard deviation below which
// points count as a line: far above float rounding (1e-7), far below a strip
// worth a polygon (1 mm across 10 m).
constexpr double kMinSpreadRatio = 1e-4;

}  // namespace occlusion::mesh_estimation
