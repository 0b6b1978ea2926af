#pragma once
// The study's built-in segmentation: a BASELINE, not a network. It needs no
// GPU and no training, and its quality still depends on how complete a scan
// is, which is what the study measures. It labels the room's structure from
// the region-growing planes (mesh_estimation.hpp) and calls everything else
// clutter. Per plane of the estimate, measured by its polygon:
//   floor    normal within max_tilt_degrees of vertical, and the polygon's
//            centroid within the lowest height_band of the cloud's z range
//   ceiling  the same, within the highest height_band
//   wall     normal within max_tilt_degrees of horizontal, the polygon spanning
//            at least min_wall_height of the z range vertically and at least
//            min_wall_width of the box's shorter horizontal side along the wall
//   clutter  every other plane (table tops, shelves, the sides of furniture)
// Points keep their cluster's class. Region growing leaves the points along
// every edge out of the clusters, so a point in no plane's cluster takes the
// class of the nearest floor, ceiling or wall plane within snap_distance of
// it, inside that polygon's box grown by snap_distance; any other point is clutter.
// Fractions are of the cloud's bounding box, so the rules hold at any scale.
// "Vertical", "height" and "horizontal side" are along options.up (default
// +z; camera-frame data such as Kinect frames has up -y), and the data are
// checked against it (check_up_axis): a disagreement is returned as a warning.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "occlusion/analysis/mesh_estimation.hpp"
#include "occlusion/analysis/up_axis.hpp"
#include "occlusion/core/point_cloud.hpp"

namespace occlusion {

// How the study names it wherever it is reported, so that no figure of it is
// taken for a network's.
inline constexpr const char* kBaselineSegmenterName = "baseline (geometric, region-growing planes)";

enum class BaselineClass { kFloor = 0, kCeiling = 1, kWall = 2, kClutter = 3 };

struct BaselineOptions {
  double max_tilt_degrees = 15.0;
  double height_band = 0.1;
  double min_wall_height = 0.5;
  double min_wall_width = 0.2;
  double snap_distance = 0.02;  // scene units; region growing's ransac_distance by default
  // The labels written per class: by default the evaluation ids of the seed's
  // table 3.1 (docs/metrics.md), so -eval scores the output as it is.
  std::int32_t floor_id = 1, ceiling_id = 1, wall_id = 0, clutter_id = 25;
  UpAxis up;
};

struct BaselineSegmentation {
  std::vector<std::int32_t> labels;          // per point of the cloud
  std::vector<BaselineClass> plane_classes;  // per entry of estimate.planes
  std::array<std::size_t, 4> points{};       // per class, indexed by BaselineClass
  std::vector<std::string> warnings;         // e.g. the data disagree with options.up
};

// An estimate without planes (and an empty point_cluster) labels every point
// clutter. std::invalid_argument when point_cluster is neither empty nor one
// per point, or for options out of range (negative values, a tilt over 45°).
BaselineSegmentation segment_baseline(const PointCloud& cloud, const MeshEstimate& estimate,
                                      const BaselineOptions& options = {});

}  // namespace occlusion
