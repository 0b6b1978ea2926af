#include "occlusion/core/polygon_fan.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace occlusion {

namespace {

void check_polygon(const std::vector<Eigen::Vector2d>& polygon) {
  if (polygon.size() < 3) {
    throw std::invalid_argument("polygon centroid: needs at least 3 vertices, got " +
                                std::to_string(polygon.size()));
  }
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    if (!polygon[i].allFinite()) {
      throw std::invalid_argument("polygon centroid: vertex " + std::to_string(i) +
                                  " is not finite");
    }
  }
}

}  // namespace

double polygon_signed_area(const std::vector<Eigen::Vector2d>& polygon) {
  if (polygon.size() < 3) return 0.0;
  const Eigen::Vector2d& base = polygon.front();
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d a = polygon[i] - base;
    const Eigen::Vector2d b = polygon[(i + 1) % polygon.size()] - base;
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * twice;
}

Eigen::Vector2d polygon_centroid_2d(const std::vector<Eigen::Vector2d>& polygon) {
  check_polygon(polygon);
  const Eigen::Vector2d& base = polygon.front();
  double twice_area = 0.0;
  Eigen::Vector2d moment = Eigen::Vector2d::Zero();
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d a = polygon[i] - base;
    const Eigen::Vector2d b = polygon[(i + 1) % polygon.size()] - base;
    const double cross = a.x() * b.y() - b.x() * a.y();
    twice_area += cross;
    moment += (a + b) * cross;
  }
  if (!(std::abs(twice_area) > 0.0)) {
    throw std::invalid_argument("polygon centroid: the polygon has zero area");
  }
  // 1/(6A) with A = twice_area / 2.
  return base + moment / (3.0 * twice_area);
}

std::vector<std::array<std::uint32_t, 3>> fan_triangles(std::uint32_t centre, std::uint32_t first,
                                                        std::size_t count) {
  if (count < 3) {
    throw std::invalid_argument("fan triangles: needs at least 3 polygon vertices, got " +
                                std::to_string(count));
  }
  std::vector<std::array<std::uint32_t, 3>> triangles;
  triangles.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    triangles.push_back({centre, first + static_cast<std::uint32_t>(i),
                         first + static_cast<std::uint32_t>((i + 1) % count)});
  }
  return triangles;
}

}  // namespace occlusion
