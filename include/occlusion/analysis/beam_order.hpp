#pragma once
// A laser scan is mostly stored in the order its beams swept (E57 rows,
// 3DTK's .3d lines, PCL's room scans, our own simulator's output): a
// station's consecutive points are neighbouring beams, one angular step apart
// as seen from where it stands. Two things follow.
// - The step's regularity checks the station's position: seen from anywhere
//   else, consecutive returns at different ranges are not equally spaced in
//   angle (a position off by d changes a step by about d / range of itself).
// - Three consecutive returns on one flat surface lie on one line (the
//   beams' plane cuts the surface along it), whatever the angle of
//   incidence, so the middle one's offset from its neighbours' chord, along
//   its own beam, is the range noise and nothing of the surface's shape.
//   Noise of standard deviation sigma along each beam gives that offset a
//   standard deviation of about sqrt(3/2) sigma.

#include <cstddef>
#include <functional>
#include <vector>

#include "occlusion/core/point_cloud.hpp"

namespace occlusion {

// Consecutive steps within this share of the station's median step are
// equal (and a row's beams keep to its plane or elevation within this share
// of a step).
inline constexpr double kEqualSteps = 0.02;
// A station is stored in its beams' order when at least this share of its
// points sit between two equal steps (on a grid, all but each row's ends).
// 3DTK's stations: 0.994 from where they stood, 0.80 from 1 cm beside it,
// 0.31 to 0.59 from 5 cm, 0.08 from 20 cm.
inline constexpr double kBeamOrderShare = 0.8;

struct BeamOrder {
  // How a station's steps are equal: the angle between consecutive beams
  // (rows along great circles: 3DTK's tilting line scanner, PCL's room
  // scans, a survey scanner's vertical profiles), or that angle over the
  // cosine of their elevation above the station's horizontal (rows at one
  // elevation, sweeping azimuth: simulate's grid). The one that finds more
  // equal steps is the station's.
  enum class Model { kAngle, kAzimuth };
  // Per station (scan_stations order).
  std::vector<double> step;           // its median step in its model's terms, radians
  std::vector<double> regular_share;  // of its points, those between two equal steps
  std::vector<Model> model;
  bool in_beam_order(std::size_t station) const {
    return station < regular_share.size() && regular_share[station] >= kBeamOrderShare;
  }
};

// Measured on the points in file order (a point stored again right after
// itself is passed over); a station with fewer than three points, or a cloud
// whose points' stations are unknown, is not in beam order.
BeamOrder find_beam_order(const PointCloud& cloud, const std::vector<Station>& stations);

// A return between two equal steps of a station in beam order.
struct BeamTriple {
  std::size_t point = 0;
  double range = 0.0;       // from its station
  double next_range = 0.0;  // the next return's
  // Its offset from its neighbours' chord along its beam (positive: farther).
  double offset = 0.0;
};
using BeamTripleVisit = std::function<void(const BeamTriple&)>;
void for_each_beam_triple(const PointCloud& cloud, const std::vector<Station>& stations,
                          const BeamOrder& order, const BeamTripleVisit& visit);

}  // namespace occlusion
