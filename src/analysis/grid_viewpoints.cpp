#include <cmath>
#include <stdexcept>

#include "occlusion/analysis/viewpoints.hpp"

namespace occlusion {

std::vector<Eigen::Vector3d> grid_viewpoints(std::size_t count, const Eigen::Vector3d& lo,
                                             const Eigen::Vector3d& hi, int up_axis) {
  if (count == 0) throw std::invalid_argument("grid viewpoints: count must be > 0");
  if (!lo.allFinite() || !hi.allFinite() || (lo.array() > hi.array()).any()) {
    throw std::invalid_argument("grid viewpoints need a non-empty, finite bounding box");
  }
  if (up_axis < 0 || up_axis > 2) throw std::invalid_argument("grid viewpoints: up axis not 0..2");
  const int a = (up_axis + 1) % 3;
  const int b = (up_axis + 2) % 3;
  auto nx = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(count))));
  // sqrt rounding must not leave the grid one column short.
  while (nx * nx < count) ++nx;
  while (nx > 1 && (nx - 1) * (nx - 1) >= count) --nx;
  const std::size_t ny = (count + nx - 1) / nx;

  // Cell centres over the middle 80%: keeps viewpoints off the walls, and a
  // single viewpoint lands in the middle of the room.
  const Eigen::Vector3d size = hi - lo;
  const double height = 0.5 * (lo[up_axis] + hi[up_axis]);
  std::vector<Eigen::Vector3d> out;
  out.reserve(count);
  for (std::size_t k = 0; k < count; ++k) {
    const double fx = (static_cast<double>(k % nx) + 0.5) / static_cast<double>(nx);
    const double fy = (static_cast<double>(k / nx) + 0.5) / static_cast<double>(ny);
    Eigen::Vector3d p;
    p[a] = lo[a] + size[a] * (0.1 + 0.8 * fx);
    p[b] = lo[b] + size[b] * (0.1 + 0.8 * fy);
    p[up_axis] = height;
    out.push_back(p);
  }
  return out;
}

}  // namespace occlusion
