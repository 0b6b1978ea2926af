#include "occlusion/app/viewpoint_choice.hpp"

#include "occlusion/analysis/viewpoints.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/json_output.hpp"

namespace occlusion {

ViewpointChoice ViewpointChoice::from_points(std::vector<Eigen::Vector3d> points) {
  ViewpointChoice choice;
  choice.kind = Kind::kPoints;
  choice.points = std::move(points);
  return choice;
}

ViewpointChoice ViewpointChoice::from_pattern(int pattern) {
  ViewpointChoice choice;
  choice.kind = Kind::kPattern;
  choice.pattern = pattern;
  return choice;
}

ViewpointChoice ViewpointChoice::from_grid(std::size_t count) {
  ViewpointChoice choice;
  choice.kind = Kind::kGrid;
  choice.grid_count = count;
  return choice;
}

ViewpointChoice ViewpointChoice::stations_else(ViewpointChoice fallback) {
  fallback.stations_first = true;
  return fallback;
}

void ViewpointChoice::validate() const {
  switch (kind) {
    case Kind::kPoints:
      if (points.empty()) throw KeyError("viewpoints", "must name at least one viewpoint");
      if (points.size() > kMaxViewpoints) {
        throw KeyError("viewpoints",
                       "must hold at most " + std::to_string(kMaxViewpoints) + " viewpoints");
      }
      for (const auto& point : points) {
        if (!point.allFinite()) throw KeyError("viewpoints", "must be finite");
      }
      break;
    case Kind::kPattern:
      if (pattern < kMinPattern || pattern > kMaxPattern) {
        throw KeyError("pattern", "must be an integer 1..7, got " + std::to_string(pattern));
      }
      break;
    case Kind::kGrid:
      if (grid_count == 0 || grid_count > kMaxViewpoints) {
        throw KeyError("num_vp", "must be an integer 1.." + std::to_string(kMaxViewpoints) +
                                     ", got " + std::to_string(grid_count));
      }
      break;
  }
}

ViewpointChoice::Resolved ViewpointChoice::resolve(const Eigen::Vector3d& lo,
                                                   const Eigen::Vector3d& hi, int up_axis) const {
  validate();
  Resolved resolved;
  switch (kind) {
    case Kind::kPoints:
      resolved.positions = points;
      resolved.source = "viewpoints";
      break;
    case Kind::kPattern:
      resolved.positions = pattern_viewpoints(pattern, lo, hi);
      resolved.names = pattern_viewpoint_names(pattern);
      resolved.source = "pattern " + std::to_string(pattern);
      return resolved;
    case Kind::kGrid:
      resolved.positions = grid_viewpoints(grid_count, lo, hi, up_axis);
      resolved.source = "num_vp " + std::to_string(grid_count);
      break;
  }
  for (std::size_t v = 0; v < resolved.positions.size(); ++v) {
    resolved.names.push_back("viewpoint_" + std::to_string(v + 1));
  }
  return resolved;
}

Json::Value ViewpointChoice::to_json() const {
  Json::Value json(Json::objectValue);
  switch (kind) {
    case Kind::kPoints: {
      Json::Value list(Json::arrayValue);
      for (const auto& point : points) list.append(occlusion::to_json(point));
      json["viewpoints"] = list;
      break;
    }
    case Kind::kPattern:
      json["pattern"] = pattern;
      break;
    case Kind::kGrid:
      json["num_vp"] = Json::UInt64(grid_count);
      break;
  }
  return json;
}

}  // namespace occlusion
