#pragma once
// Labels carried from one cloud onto another's points by nearest neighbour.
// A network's output is often a voxelised or subsampled copy of the scan;
// before it can be compared point by point with the ground truth, every
// ground-truth point takes the label of the closest predicted point, if that
// point is near enough to stand for it.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "occlusion/core/point_cloud.hpp"
#include "occlusion/core/progress.hpp"

namespace occlusion {

struct LabelTransferOptions {
  // A target point whose nearest source point is farther than this (scene
  // units, Euclidean) gets no label. +infinity: no limit.
  double max_distance = 0.05;
  unsigned threads = 0;  // 0 = all cores
};

struct LabelTransfer {
  // One per target point: the nearest source point's label, or -1 when it is
  // beyond max_distance (or the source is empty). Equidistant source points
  // are a tie the kd-tree breaks arbitrarily.
  std::vector<std::int32_t> labels;
  std::size_t beyond_distance = 0;  // target points left at -1 for distance
  double max_matched_distance = 0;  // largest distance of a transferred label
  double seconds = 0;
};

// Exact nearest neighbours (a kd-tree, PCL's FLANN wrapper). Distances are
// compared in single precision, as the positions are stored: a point at
// max_distance to within float rounding may fall on either side.
// std::invalid_argument when source_labels and source differ in size or
// max_distance is not > 0. Cancelled between blocks of target points.
LabelTransfer transfer_labels(const std::vector<Eigen::Vector3f>& source,
                              const std::vector<std::int32_t>& source_labels,
                              const std::vector<Eigen::Vector3f>& target,
                              const LabelTransferOptions& options = {},
                              const Progress& progress = {});

// Each point of `target` takes the colour of the nearest point of `source`
// (compared in the file's frame, each cloud's shift applied), as a scanner's
// camera colours its returns: a virtual scan of a mesh, coloured from the
// room's coloured points. std::invalid_argument when source has no colours
// (or no points) and target has points.
void colour_from_nearest(PointCloud& target, const PointCloud& source, unsigned threads = 0,
                         const Progress& progress = {});

}  // namespace occlusion
