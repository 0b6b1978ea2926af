#pragma once
// Small helpers shared by every job's report.

#include <json/value.h>

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "occlusion/core/octree.hpp"

namespace occlusion {

Json::Value to_json(const Eigen::Vector3d& point);
Json::Value to_json(const std::vector<std::string>& strings);
// {"inner_nodes", "leaves", "depth", "largest_leaf", "memory_bytes"}
Json::Value to_json(const OctreeStats& stats);
// null when absent: an undefined figure (an mIoU without classes) is not 0.
Json::Value to_json(const std::optional<double>& value);
// Indented, 15 significant digits, UTF-8 kept as is.
std::string format_json(const Json::Value& value);

}  // namespace occlusion
