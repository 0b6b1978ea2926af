#pragma once
// Laser-scan hygiene at load: the scans a job keeps
// (`scans`, by station name) and the ranges it trusts (`min_range`,
// `max_range`, measured from each point's own station): a scanner records its
// own tripod and operator a few decimetres away, and some write a fixed
// no-return range (e.g. 32.76 m) as if a surface stood there.

#include <json/value.h>

#include <cstddef>
#include <string>
#include <vector>

#include "occlusion/core/point_cloud.hpp"

namespace occlusion {

struct StationFilter {
  std::vector<std::string> scans;  // empty: every station
  double min_range = 0.0;          // 0: off
  double max_range = 0.0;          // 0: off

  bool active() const { return !scans.empty() || min_range > 0.0 || max_range > 0.0; }
};

// What the filter dropped, for the report.
struct StationFilterReport {
  StationFilter filter;
  std::size_t other_scans = 0;  // points of stations not picked
  std::size_t too_near = 0;     // nearer than min_range to their station
  std::size_t too_far = 0;      // farther than max_range from their station
};

// A request's filter (-poc's and -fscan's hold the same keys).
template <class Request>
StationFilter station_filter(const Request& request) {
  return {request.scans, request.min_range, request.max_range};
}

// Throws KeyError when min_range is not below max_range (both set).
void validate(const StationFilter& filter);

// Drops from `cloud` the points the filter refuses; the stations not picked
// leave its station list (station ids renumbered). KeyError naming the key,
// `path` and why: a scan name the cloud has no station of (listing those it
// has), `scans` on a cloud without stations, a range on a cloud without a
// station (scan_stations) or with several but no station ids, or a filter
// that leaves no point.
StationFilterReport apply_station_filter(PointCloud& cloud, const StationFilter& filter,
                                         const std::string& path);

// {"scans": [...], "min_range": ..., "max_range": ..., "dropped_other_scans",
//  "dropped_too_near", "dropped_too_far"}
Json::Value station_filter_json(const StationFilterReport& report);

}  // namespace occlusion
