#include "occlusion/core/morton_order.hpp"

#include <algorithm>
#include <limits>
#include <utility>

#include "occlusion/core/morton.hpp"

namespace occlusion {

std::vector<std::uint32_t> morton_order(const std::vector<Eigen::Vector3f>& positions) {
  if (positions.empty()) return {};
  Eigen::Vector3f lo = positions[0], hi = positions[0];
  for (const Eigen::Vector3f& p : positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const float extent = std::max((hi - lo).maxCoeff(), std::numeric_limits<float>::min());
  const double scale = static_cast<double>(kMortonLastCell) / static_cast<double>(extent);
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Eigen::Vector3d cell = (positions[i] - lo).cast<double>() * scale;
    const auto coordinate = [&](int axis) {
      return static_cast<std::uint32_t>(
          std::clamp(cell[axis], 0.0, static_cast<double>(kMortonLastCell)));
    };
    keyed[i] = {spread_by_three(coordinate(0)) | spread_by_three(coordinate(1)) << 1 |
                    spread_by_three(coordinate(2)) << 2,
                static_cast<std::uint32_t>(i)};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::uint32_t> order(positions.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = keyed[i].second;
  return order;
}

}  // namespace occlusion
