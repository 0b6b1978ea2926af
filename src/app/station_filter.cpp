#include "occlusion/app/station_filter.hpp"

#include <algorithm>
#include <cstdint>
#include <sstream>

#include "occlusion/app/errors.hpp"
#include "occlusion/app/json_output.hpp"

namespace occlusion {

namespace {

std::string station_names(const std::vector<Station>& stations) {
  std::string names;
  for (const auto& station : stations) names += (names.empty() ? "'" : ", '") + station.name + "'";
  return names;
}

// Keeps the stations named in `scans` and their points.
std::size_t pick_scans(PointCloud& cloud, const std::vector<std::string>& scans,
                       const std::string& path) {
  if (cloud.stations.empty()) {
    throw KeyError("scans", "picks stations by name, but " + path +
                                " records no stations (an E57 file's scans, or a PLY this "
                                "tool wrote from one, have them): leave scans out");
  }
  std::vector<bool> picked(cloud.stations.size(), false);
  for (const auto& name : scans) {
    bool found = false;
    for (std::size_t s = 0; s < cloud.stations.size(); ++s) {
      if (cloud.stations[s].name == name) picked[s] = found = true;
    }
    if (!found) {
      throw KeyError("scans", "names no station of " + path + ": '" + name +
                                  "' (its stations: " + station_names(cloud.stations) + ")");
    }
  }
  if (std::all_of(picked.begin(), picked.end(), [](bool p) { return p; })) return 0;
  if (!cloud.has_station_ids()) {
    throw KeyError("scans", "cannot pick scans of " + path + ": it records " +
                                std::to_string(cloud.stations.size()) +
                                " stations but not which one measured each point");
  }
  std::vector<std::int32_t> renumbered(cloud.stations.size(), -1);
  std::vector<Station> kept_stations;
  for (std::size_t s = 0; s < cloud.stations.size(); ++s) {
    if (!picked[s]) continue;
    renumbered[s] = static_cast<std::int32_t>(kept_stations.size());
    kept_stations.push_back(cloud.stations[s]);
  }
  std::vector<bool> keep(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    keep[i] = picked[static_cast<std::size_t>(cloud.station_ids[i])];
  }
  PointCloud kept = cloud.subset(keep);
  for (auto& id : kept.station_ids) id = renumbered[static_cast<std::size_t>(id)];
  kept.stations = std::move(kept_stations);
  const std::size_t dropped = cloud.size() - kept.size();
  cloud = std::move(kept);
  return dropped;
}

// Drops the points outside [min_range, max_range] of their own station.
void drop_out_of_range(PointCloud& cloud, const StationFilter& filter, const std::string& path,
                       StationFilterReport& report) {
  const char* key = filter.min_range > 0.0 ? "min_range" : "max_range";
  const std::vector<Station> stations = scan_stations(cloud);
  if (stations.empty()) {
    throw KeyError(key, "measures each point's range from its own station, but " + path +
                            " records no station (no scan poses, no sensor VIEWPOINT): set it "
                            "to 0");
  }
  if (stations.size() > 1 && !cloud.has_station_ids()) {
    throw KeyError(key, "measures each point's range from its own station, but " + path +
                            " records " + std::to_string(stations.size()) +
                            " stations and not which one measured each point: set it to 0");
  }
  std::vector<bool> keep(cloud.size(), true);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const std::size_t s =
        cloud.has_station_ids() ? static_cast<std::size_t>(cloud.station_ids[i]) : 0;
    const double range = (cloud.positions[i].cast<double>() - stations[s].frame.origin).norm();
    if (filter.min_range > 0.0 && range < filter.min_range) {
      keep[i] = false;
      ++report.too_near;
    } else if (filter.max_range > 0.0 && range > filter.max_range) {
      keep[i] = false;
      ++report.too_far;
    }
  }
  if (report.too_near + report.too_far > 0) cloud = cloud.subset(keep);
}

}  // namespace

void validate(const StationFilter& filter) {
  if (filter.min_range > 0.0 && filter.max_range > 0.0 && filter.min_range >= filter.max_range) {
    std::ostringstream message;
    message << "must be above min_range (" << filter.min_range << "), got " << filter.max_range;
    throw KeyError("max_range", message.str());
  }
}

StationFilterReport apply_station_filter(PointCloud& cloud, const StationFilter& filter,
                                         const std::string& path) {
  validate(filter);
  StationFilterReport report;
  report.filter = filter;
  if (!filter.scans.empty()) report.other_scans = pick_scans(cloud, filter.scans, path);
  if (filter.min_range > 0.0 || filter.max_range > 0.0) {
    drop_out_of_range(cloud, filter, path, report);
  }
  if (filter.active() && cloud.size() == 0) {
    throw KeyError(
        filter.scans.empty() ? (filter.min_range > 0.0 ? "min_range" : "max_range") : "scans",
        "leaves no point of " + path + " (" + std::to_string(report.other_scans) +
            " of other scans, " + std::to_string(report.too_near) + " too near, " +
            std::to_string(report.too_far) + " too far)");
  }
  return report;
}

Json::Value station_filter_json(const StationFilterReport& report) {
  Json::Value json(Json::objectValue);
  json["scans"] = to_json(report.filter.scans);
  json["min_range"] = report.filter.min_range;
  json["max_range"] = report.filter.max_range;
  json["dropped_other_scans"] = Json::UInt64(report.other_scans);
  json["dropped_too_near"] = Json::UInt64(report.too_near);
  json["dropped_too_far"] = Json::UInt64(report.too_far);
  return json;
}

}  // namespace occlusion
