#include "occlusion/analysis/spherical_field_of_view.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace occlusion {

namespace {

constexpr double kTurn = 2.0 * M_PI;

double degrees(double radians) {
  return radians * 180.0 / M_PI;
}

double elevation(const Eigen::Vector3d& d) {
  return std::atan2(d.z(), std::hypot(d.x(), d.y()));
}

// In [0, 2 pi).
double azimuth(const Eigen::Vector3d& d) {
  const double a = std::atan2(d.y(), d.x());
  return a < 0.0 ? a + kTurn : a;
}

// Half of one of `cells` equal steps across `span`: points are cell centres.
double half_step(double span, std::size_t cells) {
  return cells > 1 ? 0.5 * span / static_cast<double>(cells - 1) : 0.0;
}

}  // namespace

bool SphericalFieldOfView::contains(const Eigen::Vector3d& direction) const {
  const Eigen::Vector3d d = orientation.conjugate() * direction;
  const double e = elevation(d);
  if (!(e >= elevation_lo && e <= elevation_hi)) return false;
  if (full_turn) return true;
  const double past_start = std::fmod(azimuth(d) - azimuth_start + 2.0 * kTurn, kTurn);
  return past_start <= azimuth_span;
}

double SphericalFieldOfView::elevation_lo_degrees() const {
  return degrees(elevation_lo);
}

double SphericalFieldOfView::elevation_hi_degrees() const {
  return degrees(elevation_hi);
}

double SphericalFieldOfView::azimuth_span_degrees() const {
  return full_turn ? 360.0 : degrees(azimuth_span);
}

bool is_laser_station(const PointCloud& cloud) {
  if (cloud.stations.size() != 1 || cloud.sensor.single_view()) return false;
  const SensorFrame& frame = cloud.stations.front().frame;
  return frame.width > 0 && frame.height > 0;
}

SphericalFieldOfView measure_spherical_field_of_view(const PointCloud& cloud) {
  if (!is_laser_station(cloud)) {
    throw std::invalid_argument("spherical field of view: the cloud is no single gridded station");
  }
  if (cloud.size() == 0) throw std::invalid_argument("spherical field of view: no points");
  const SensorFrame& frame = cloud.stations.front().frame;
  SphericalFieldOfView view;
  view.orientation = frame.orientation.normalized();
  const Eigen::Quaterniond to_scanner = view.orientation.conjugate();
  view.elevation_lo = std::numeric_limits<double>::infinity();
  view.elevation_hi = -std::numeric_limits<double>::infinity();
  std::vector<double> azimuths(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Eigen::Vector3d p = to_scanner * (cloud.positions[i].cast<double>() - frame.origin);
    if (!(p.norm() > 0.0)) {
      throw std::invalid_argument("spherical field of view: point " + std::to_string(i) +
                                  " lies at the station itself and has no direction");
    }
    view.elevation_lo = std::min(view.elevation_lo, elevation(p));
    view.elevation_hi = std::max(view.elevation_hi, elevation(p));
    azimuths[i] = azimuth(p);
  }
  const double rows = half_step(view.elevation_hi - view.elevation_lo, frame.height);
  view.elevation_lo = std::max(view.elevation_lo - rows, -0.5 * M_PI);
  view.elevation_hi = std::min(view.elevation_hi + rows, 0.5 * M_PI);

  // The turn's end is the widest gap between neighbouring azimuths (the one
  // across 0 included).
  std::sort(azimuths.begin(), azimuths.end());
  double gap = azimuths.front() + kTurn - azimuths.back();
  double gap_end = azimuths.front();
  for (std::size_t i = 1; i < azimuths.size(); ++i) {
    if (azimuths[i] - azimuths[i - 1] > gap) {
      gap = azimuths[i] - azimuths[i - 1];
      gap_end = azimuths[i];
    }
  }
  const double full_turn_column = kTurn / static_cast<double>(frame.width);
  if (gap <= std::max(kMinAzimuthGapDegrees * M_PI / 180.0, 4.0 * full_turn_column)) return view;
  view.full_turn = false;
  const double span = kTurn - gap;
  const double columns = half_step(span, frame.width);
  view.azimuth_start = std::fmod(gap_end - columns + kTurn, kTurn);
  view.azimuth_span = std::min(span + 2.0 * columns, kTurn);
  return view;
}

}  // namespace occlusion
