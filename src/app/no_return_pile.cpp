#include "occlusion/app/no_return_pile.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace occlusion {

std::vector<NoReturnPile> find_no_return_piles(const PointCloud& cloud) {
  const std::vector<Station> stations = scan_stations(cloud);
  std::vector<NoReturnPile> piles;
  if (stations.empty() || (stations.size() > 1 && !cloud.has_station_ids())) return piles;
  const auto range_of = [&](std::size_t i, std::size_t s) {
    return (cloud.positions[i].cast<double>() - stations[s].frame.origin).norm();
  };
  std::vector<double> farthest(stations.size(), 0.0);
  std::vector<std::size_t> count(stations.size(), 0);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const auto s = static_cast<std::size_t>(measuring_station(cloud, stations.size(), i));
    farthest[s] = std::max(farthest[s], range_of(i, s));
    ++count[s];
  }
  std::vector<std::size_t> in_shell(stations.size(), 0);
  std::vector<std::size_t> in_gap(stations.size(), 0);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const auto s = static_cast<std::size_t>(measuring_station(cloud, stations.size(), i));
    const double below = farthest[s] - range_of(i, s);
    const double shell = kNoReturnShell * farthest[s];
    if (below <= shell) {
      ++in_shell[s];
    } else if (below <= kNoReturnGapShells * shell) {
      ++in_gap[s];
    }
  }
  for (std::size_t s = 0; s < stations.size(); ++s) {
    if (count[s] < kNoReturnMinStationPoints || farthest[s] <= 0.0) continue;
    const double share = static_cast<double>(in_shell[s]) / static_cast<double>(count[s]);
    if (share < kNoReturnMinShare || share > kNoReturnMaxShare) continue;
    if (10 * in_gap[s] >= in_shell[s]) continue;
    piles.push_back({stations[s].name, farthest[s], in_shell[s], count[s]});
  }
  return piles;
}

double max_range_below(const NoReturnPile& pile) {
  return std::floor(pile.range * (1.0 - 2.0 * kNoReturnShell) * 100.0) / 100.0;
}

void warn_no_return_piles(const PointCloud& cloud, double max_range,
                          std::vector<std::string>& warnings) {
  if (max_range > 0.0) return;
  for (const NoReturnPile& pile : find_no_return_piles(cloud)) {
    const double below = max_range_below(pile);
    std::ostringstream message;
    message << "station '" << pile.station << "': " << pile.points << " of its "
            << pile.station_points << " points (" << std::fixed << std::setprecision(1)
            << 100.0 * static_cast<double>(pile.points) / static_cast<double>(pile.station_points)
            << " %) lie at its farthest range, " << std::setprecision(2) << pile.range
            << ", and none just below it: a scanner's no-return value, not a surface, yet "
               "counted as points seen. Drop them with max_range "
            << below << " (--max-range " << below << ")";
    warnings.push_back(message.str());
  }
}

}  // namespace occlusion
