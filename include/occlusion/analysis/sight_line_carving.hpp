#pragma once
// Free space a scan proves. A point a station recorded was seen from it, so
// the line between them crosses nothing: no disc of the model may stand
// across it. Discs do, where they are larger than the surface they stand for:
// at a silhouette the density rule (surfel_estimation.hpp) gives the last
// point before a depth step a disc that overhangs the step by about a point
// spacing, which on a scanner's grid is the next beam's line of sight, so the
// model hid the points just behind every edge from the very station that
// recorded them (1.2 % of a noise-free laser scan of a furnished room, 5 %
// beyond 4 m). Each such disc (or sphere) is shrunk until the line passes
// beside it, and the line is traced again, until none is blocked.
//
// Lines of sight are -fscan's own shadow rays from each point's measuring
// station (scan_surfel_ray, with the estimate's bands), so a point within its
// surface's noise of a disc is not a crossing: noise never carves.

#include <cstddef>
#include <string>
#include <vector>

#include "occlusion/core/point_cloud.hpp"
#include "occlusion/core/progress.hpp"

namespace occlusion {

struct SurfelEstimate;

// Above this share of a station's lines of sight blocked before carving,
// the station is left uncarved (sight_line_carving.cpp says why). Scans from
// the right place block about 1 % (docs/simulate.md).
inline constexpr double kMaxBlockedShare = 0.1;

struct SightLineCarving {
  struct UncarvedStation {
    std::string name;
    double blocked_share = 0.0;  // of its lines, blocked before carving
    // In beam order, so judged by the other stations' discs alone: this
    // share of its lines crosses them.
    bool beam_order = false;
    double by_others_share = 0.0;
  };
  std::vector<UncarvedStation> implausible;  // stations left uncarved (kMaxBlockedShare)
  std::size_t lines = 0;                     // lines of sight traced (points with a known station)
  // Of them, blocked before carving (the uncarved stations' too).
  std::size_t blocked = 0;
  std::size_t shrunk = 0;         // discs and spheres made smaller
  std::size_t still_blocked = 0;  // blocked after the last pass
};

// Shrinks estimate.surfels' radii in place. Needs the estimate's thickness
// and noise (SurfelOptions::keep_thickness); does nothing for a cloud whose
// points' stations are unknown. Throws Cancelled on cancel.
SightLineCarving carve_sight_lines(const PointCloud& cloud, SurfelEstimate& estimate,
                                   unsigned threads, const Progress& progress = {});

}  // namespace occlusion
