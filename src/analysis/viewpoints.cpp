#include "occlusion/analysis/viewpoints.hpp"

#include <stdexcept>

namespace occlusion {

namespace {

// Bit 0: centre, bit 1: max midpoint, bit 2: min midpoint; indexed by pattern.
constexpr int kPatternMembers[kMaxPattern + 1] = {0,     0b001, 0b010, 0b100,
                                                  0b011, 0b101, 0b110, 0b111};

void check_pattern(int pattern) {
  if (pattern < kMinPattern || pattern > kMaxPattern) {
    throw std::invalid_argument("viewpoint pattern must be 1..7, got " + std::to_string(pattern));
  }
}

}  // namespace

std::vector<Eigen::Vector3d> pattern_viewpoints(int pattern, const Eigen::Vector3d& lo,
                                                const Eigen::Vector3d& hi) {
  check_pattern(pattern);
  if (!lo.allFinite() || !hi.allFinite() || (lo.array() > hi.array()).any()) {
    throw std::invalid_argument("viewpoint pattern needs a non-empty, finite bounding box");
  }
  const Eigen::Vector3d centre = 0.5 * (lo + hi);
  const Eigen::Vector3d candidates[3] = {centre, 0.5 * (centre + hi), 0.5 * (centre + lo)};
  std::vector<Eigen::Vector3d> out;
  for (int k = 0; k < 3; ++k) {
    if (kPatternMembers[pattern] & (1 << k)) out.push_back(candidates[k]);
  }
  return out;
}

std::vector<std::string> pattern_viewpoint_names(int pattern) {
  check_pattern(pattern);
  static const char* const kNames[3] = {"centre", "max_mid", "min_mid"};
  std::vector<std::string> out;
  for (int k = 0; k < 3; ++k) {
    if (kPatternMembers[pattern] & (1 << k)) out.emplace_back(kNames[k]);
  }
  return out;
}

}  // namespace occlusion
