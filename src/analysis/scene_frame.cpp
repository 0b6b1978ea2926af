#include "occlusion/analysis/scene_frame.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "occlusion/core/large_buffer.hpp"
#include "quantiles.hpp"

namespace occlusion {

SceneFrame measure_scene_frame(const std::vector<Eigen::Vector3f>& points) {
  if (points.empty()) throw std::invalid_argument("scene frame: no points");
  SceneFrame frame;
  LargeVector<float> values(points.size());  // huge pages: see core/large_buffer.hpp
  const double last = static_cast<double>(points.size() - 1);
  const auto low = static_cast<std::size_t>(std::floor(kRobustQuantile * last));
  const auto high = static_cast<std::size_t>(std::ceil((1.0 - kRobustQuantile) * last));
  for (int axis = 0; axis < 3; ++axis) {
    for (std::size_t i = 0; i < points.size(); ++i) values[i] = points[i][axis];
    const auto [min, max] = std::minmax_element(values.begin(), values.end());
    frame.bbox.lo[axis] = *min;
    frame.bbox.hi[axis] = *max;
    const std::vector<float> robust = quantiles::at_ranks(values, {low, high});
    frame.robust.lo[axis] = robust[0];
    frame.robust.hi[axis] = robust[1];
  }
  return frame;
}

FrameKind parse_frame_kind(const std::string& name) {
  if (name == "robust") return FrameKind::kRobust;
  if (name == "bbox") return FrameKind::kBbox;
  throw std::invalid_argument("frame must be robust or bbox, got '" + name + "'");
}

}  // namespace occlusion
