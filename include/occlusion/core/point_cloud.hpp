#pragma once
// One point cloud type for every job: positions plus optional per-point
// colour, semantic label and instance id. An optional attribute is either
// empty or has exactly one entry per point.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace occlusion {

// Where a single-view frame was captured: the sensor's pose (PCD `VIEWPOINT`:
// origin, then the rotation from the sensor frame, +z forward, +y down, to the
// cloud's frame) and, for an organised frame, its pixel grid (PCD WIDTH x
// HEIGHT with HEIGHT > 1). The grid says how the file was laid out; positions
// hold only the valid pixels, so it is no index into them.
struct SensorFrame {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  std::size_t width = 0, height = 0;

  bool organised() const { return height > 1; }
  // A VIEWPOINT other than PCL's default (origin, no rotation) was written on purpose.
  bool has_pose() const {
    return origin != Eigen::Vector3d::Zero() ||
           orientation.coeffs() != Eigen::Quaterniond::Identity().coeffs();
  }
  // A frame seen from one sensor: organised, or a pose given on purpose.
  bool single_view() const { return organised() || has_pose(); }
};

struct PointCloud {
  std::vector<Eigen::Vector3f> positions;
  std::vector<std::array<std::uint8_t, 3>> colours;  // RGB
  std::vector<std::int32_t> labels;                  // semantic class id, -1 = unlabelled
  std::vector<std::int32_t> instances;               // instance id, -1 = none
  // class_names[label] when known (S3DIS: the 13 classes), else empty.
  std::vector<std::string> class_names;
  SensorFrame sensor;  // PCD only; the default says "not a single-view frame"

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
