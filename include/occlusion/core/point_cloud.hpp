#pragma once
// One point cloud type for every job: positions plus optional per-point
// colour, semantic label and instance id. An optional attribute is either
// empty or has exactly one entry per point.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace occlusion {

struct PointCloud {
  std::vector<Eigen::Vector3f> positions;
  std::vector<std::array<std::uint8_t, 3>> colours;  // RGB
  std::vector<std::int32_t> labels;                  // semantic class id, -1 = unlabelled
  std::vector<std::int32_t> instances;               // instance id, -1 = none
  // class_names[label] when known (S3DIS: the 13 classes), else empty.
  std::vector<std::string> class_names;

  std::size_t size() const { return positions.size(); }
  bool has_colours() const { return !colours.empty(); }
  bool has_labels() const { return !labels.empty(); }
  bool has_instances() const { return !instances.empty(); }

  // Throws std::invalid_argument if an attribute's size differs from the point
  // count, a position is not finite, or a label has no name while names exist.
  void validate() const;
  // The cloud restricted to points where keep[i] is true, all attributes kept.
  PointCloud subset(const std::vector<bool>& keep) const;
  void bounds(Eigen::Vector3f& lo, Eigen::Vector3f& hi) const;
};

}  // namespace occlusion
