#include "occlusion/analysis/scene_frame.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace occlusion {

SceneFrame measure_scene_frame(const std::vector<Eigen::Vector3f>& points) {
  if (points.empty()) throw std::invalid_argument("scene frame: no points");
  SceneFrame frame;
  std::vector<float> values(points.size());
  const double last = static_cast<double>(points.size() - 1);
  const auto low = static_cast<std::ptrdiff_t>(std::floor(kRobustQuantile * last));
  const auto high = static_cast<std::ptrdiff_t>(std::ceil((1.0 - kRobustQuantile) * last));
  for (int axis = 0; axis < 3; ++axis) {
    for (std::size_t i = 0; i < points.size(); ++i) values[i] = points[i][axis];
    const auto [min, max] = std::minmax_element(values.begin(), values.end());
    frame.bbox.lo[axis] = *min;
    frame.bbox.hi[axis] = *max;
    std::nth_element(values.begin(), values.begin() + low, values.end());
    frame.robust.lo[axis] = values[static_cast<std::size_t>(low)];
    std::nth_element(values.begin(), values.begin() + high, values.end());
    frame.robust.hi[axis] = values[static_cast<std::size_t>(high)];
  }
  return frame;
}

FrameKind parse_frame_kind(const std::string& name) {
  if (name == "robust") return FrameKind::kRobust;
  if (name == "bbox") return FrameKind::kBbox;
  throw std::invalid_argument("frame must be robust or bbox, got '" + name + "'");
}

}  // namespace occlusion
