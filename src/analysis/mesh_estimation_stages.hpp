#pragma once
// The stages of estimate_mesh (internal to analysis/): segmentation from one
// neighbour search (PCL's normals, PCL's region growing), then one polygon per cluster. PCL types
// stop here.

#include <pcl/PointIndices.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "neighbour_lists.hpp"
#include "occlusion/analysis/mesh_estimation.hpp"

namespace occlusion::mesh_estimation {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;
// What one nearest-neighbour search per point found (the kd-tree is gone):
// PCL's normal and curvature from the normal_k nearest, and the `neighbours`
// nearest, nearest first, that region growing and edge recovery compare.
struct Neighbourhoods {
  NeighbourLists lists;                  // min(neighbours, points) per point
  std::vector<Eigen::Vector3f> normals;  // NaN where PCL finds no normal
  std::vector<float> curvatures;
};

// In blocks, so that progress ("normals") and cancel are checked.
Neighbourhoods find_neighbourhoods(const Cloud::ConstPtr& cloud,
                                   const RegionGrowingOptions& options, const Progress& progress);

struct Segmentation {
  std::vector<pcl::PointIndices> clusters;  // within the size limits, PCL's order
  RegionSizes regions;
};

// PCL's region growing (smooth mode) over the neighbourhoods' lists and normals.
Segmentation grow_regions(const Neighbourhoods& hoods, const RegionGrowingOptions& options,
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

// The points in no cluster (label < 0), each with the clusters of its
// neighbours, nearest first, each cluster once: all that edge recovery needs
// of the neighbourhoods (a cluster whose plane is too far from the point is
// too far however often it appears). Taken before the planes are fitted so
// that every point's neighbour lists, most of -rgoc's memory, go first.
struct EdgeCandidates {
  std::vector<pcl::index_t> points;
  std::vector<std::uint32_t> first;  // points[e]'s clusters: [first[e], first[e + 1])
  std::vector<std::int32_t> clusters;
};
EdgeCandidates edge_candidates(const Neighbourhoods& hoods, const std::vector<std::int32_t>& label);

// Candidates that planes took, and which planes (up to three: a corner's), -1
// for none. Adds them to the planes' inliers_2d.
struct EdgePoints {
  std::vector<pcl::index_t> points;
  std::vector<std::array<std::int32_t, 3>> planes;
};
EdgePoints recover_edge_points(const Cloud::ConstPtr& cloud, EdgeCandidates candidates,
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
