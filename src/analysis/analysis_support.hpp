#pragma once
// Pieces every analysis shares (internal to analysis/): timing and the
// argument checks each one makes at its API edge.

#include <Eigen/Core>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace occlusion::analysis_support {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Throws std::invalid_argument("<analysis>: ...") for no viewpoints or a non-finite one.
inline void check_viewpoints(const std::vector<Eigen::Vector3d>& viewpoints,
                             const std::string& analysis) {
  if (viewpoints.empty()) throw std::invalid_argument(analysis + ": no viewpoints given");
  for (const auto& viewpoint : viewpoints) {
    if (!viewpoint.allFinite()) {
      throw std::invalid_argument(analysis + ": a viewpoint is not finite");
    }
  }
}

// Throws unless value is finite and > 0.
inline void check_positive(double value, const std::string& name, const std::string& analysis) {
  if (!std::isfinite(value) || value <= 0.0) {
    throw std::invalid_argument(analysis + ": " + name + " must be a finite number > 0");
  }
}

}  // namespace occlusion::analysis_support
