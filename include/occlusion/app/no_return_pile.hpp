#pragma once
// A scanner that writes a fixed range for a beam that met nothing (3DTK's SICK
// scans: 32.77 m) leaves a shell of points at its station's farthest range, as
// if a sphere stood there. They are no surface, yet count in every figure as
// points seen, and their discs can stand in other stations' way. `max_range`
// (app/station_filter) drops them; this finds them when it is off, so the job
// can say so.

#include <cstddef>
#include <string>
#include <vector>

#include "occlusion/core/point_cloud.hpp"

namespace occlusion {

// The shell: within this share of the farthest range (1 cm at 33 m).
inline constexpr double kNoReturnShell = 3e-4;
// A pile is at least this share of its station's points (3DTK: 1.6-2 %)...
inline constexpr double kNoReturnMinShare = 0.005;
// ...at most this share (a scanner at the centre of a spherical tank sees one
// range everywhere: that is a surface)...
inline constexpr double kNoReturnMaxShare = 0.2;
// ...and the band this many shells deep below it holds under a tenth of the
// pile's count: a far wall's points fall off continuously below their farthest.
inline constexpr double kNoReturnGapShells = 30.0;
// Stations with fewer points are not judged.
inline constexpr std::size_t kNoReturnMinStationPoints = 1000;

struct NoReturnPile {
  std::string station;
  double range = 0.0;  // the farthest range, scene units
  std::size_t points = 0;
  std::size_t station_points = 0;
};

// The piles of a cloud's stations (scan_stations): each point's range from its
// own station (measuring_station); none when the cloud does not say which
// station measured each point.
std::vector<NoReturnPile> find_no_return_piles(const PointCloud& cloud);

// The max_range that drops the pile and nothing nearer: below its shell,
// rounded down to a hundredth of a unit (a centimetre in metres).
double max_range_below(const NoReturnPile& pile);

// One warning a pile, naming max_range_below; nothing when `max_range` is on
// (the user decided already).
void warn_no_return_piles(const PointCloud& cloud, double max_range,
                          std::vector<std::string>& warnings);

}  // namespace occlusion
