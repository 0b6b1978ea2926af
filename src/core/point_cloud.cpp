#include "occlusion/core/point_cloud.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "occlusion/core/large_buffer.hpp"

namespace occlusion {

namespace {
void check_size(std::size_t size, std::size_t points, const char* what) {
  if (size != 0 && size != points) {
    throw std::invalid_argument(std::string("point cloud: ") + what + " has " +
                                std::to_string(size) + " entries for " + std::to_string(points) +
                                " points");
  }
}

template <class T>
void keep_where(const std::vector<T>& in, const std::vector<bool>& keep, std::vector<T>& out) {
  if (in.empty()) return;
  for (std::size_t i = 0; i < in.size(); ++i) {
    if (keep[i]) out.push_back(in[i]);
  }
}
// A pixel per point, each in the organised sensor's grid and none twice
// (the surfel estimate looks points up by their pixel).
void check_pixels(const PointCloud& cloud) {
  if (!cloud.has_pixels()) return;
  check_size(cloud.pixels.size(), cloud.size(), "pixels");
  if (!cloud.sensor.organised()) {
    throw std::invalid_argument(
        "point cloud: pixels are given but the cloud is not an organised frame");
  }
  const std::size_t grid = cloud.sensor.width * cloud.sensor.height;
  std::vector<bool> taken(grid, false);
  for (std::size_t i = 0; i < cloud.pixels.size(); ++i) {
    const std::uint32_t pixel = cloud.pixels[i];
    if (pixel >= grid || taken[pixel]) {
      throw std::invalid_argument("point cloud: point " + std::to_string(i) + " has pixel " +
                                  std::to_string(pixel) +
                                  (pixel >= grid ? ", outside the " : ", taken twice in the ") +
                                  std::to_string(cloud.sensor.width) + " x " +
                                  std::to_string(cloud.sensor.height) + " grid");
    }
    taken[pixel] = true;
  }
}

// The double nearest the shortest decimal that reads back as `value`.
double shortest_decimal(float value) {
  char text[32];
  const auto written = std::to_chars(text, text + sizeof text, value);
  double parsed = 0.0;
  std::from_chars(text, written.ptr, parsed);
  return parsed;
}
}  // namespace

Eigen::Vector3d choose_global_shift(const Eigen::Vector3d& first_point) {
  if (!first_point.allFinite() || first_point.cwiseAbs().maxCoeff() < kGlobalShiftThreshold) {
    return Eigen::Vector3d::Zero();
  }
  Eigen::Vector3d shift;
  for (int axis = 0; axis < 3; ++axis) {
    shift[axis] = std::round(first_point[axis] / kGlobalShiftUnit) * kGlobalShiftUnit;
  }
  return shift;
}

Eigen::Vector3d PointCloud::original_position(std::size_t i) const {
  const Eigen::Vector3f& p = positions.at(i);
  if (!shifted()) return p.cast<double>();
  return Eigen::Vector3d(shortest_decimal(p.x()), shortest_decimal(p.y()),
                         shortest_decimal(p.z())) +
         shift;
}

void PointCloud::reserve_positions(std::size_t count) {
  positions.reserve(count);
  advise_huge_pages(positions.data(), positions.capacity() * sizeof(Eigen::Vector3f));
}

void PointCloud::validate() const {
  check_size(colours.size(), size(), "colours");
  check_size(labels.size(), size(), "labels");
  check_size(instances.size(), size(), "instances");
  check_size(intensities.size(), size(), "intensities");
  check_size(station_ids.size(), size(), "station ids");
  for (std::size_t i = 0; i < size(); ++i) {
    if (!positions[i].allFinite()) {
      throw std::invalid_argument("point cloud: point " + std::to_string(i) + " is not finite");
    }
  }
  for (std::size_t i = 0; i < station_ids.size(); ++i) {
    if (station_ids[i] < 0 || station_ids[i] >= static_cast<std::int32_t>(stations.size())) {
      throw std::invalid_argument("point cloud: point " + std::to_string(i) + " has station " +
                                  std::to_string(station_ids[i]) + " but the cloud has " +
                                  std::to_string(stations.size()) + " stations");
    }
  }
  check_pixels(*this);
  if (!class_names.empty()) {
    for (std::size_t i = 0; i < labels.size(); ++i) {
      if (labels[i] >= static_cast<std::int32_t>(class_names.size())) {
        throw std::invalid_argument("point cloud: point " + std::to_string(i) + " has label " +
                                    std::to_string(labels[i]) + " but only " +
                                    std::to_string(class_names.size()) + " class names");
      }
    }
  }
}

PointCloud PointCloud::subset(const std::vector<bool>& keep) const {
  if (keep.size() != size()) {
    throw std::invalid_argument("point cloud: subset mask has the wrong size");
  }
  PointCloud out;
  out.class_names = class_names;
  out.sensor = sensor;  // the same sensor saw the kept points
  out.shift = shift;
  out.stations = stations;
  keep_where(positions, keep, out.positions);
  keep_where(colours, keep, out.colours);
  keep_where(labels, keep, out.labels);
  keep_where(instances, keep, out.instances);
  keep_where(intensities, keep, out.intensities);
  keep_where(station_ids, keep, out.station_ids);
  keep_where(pixels, keep, out.pixels);
  return out;
}

void PointCloud::bounds(Eigen::Vector3f& lo, Eigen::Vector3f& hi) const {
  lo.setConstant(std::numeric_limits<float>::infinity());
  hi.setConstant(-std::numeric_limits<float>::infinity());
  for (const auto& p : positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
}

std::vector<Station> scan_stations(const PointCloud& cloud) {
  if (!cloud.stations.empty()) return cloud.stations;
  if (cloud.sensor.single_view()) return {Station{"sensor", cloud.sensor}};
  return {};
}

}  // namespace occlusion
