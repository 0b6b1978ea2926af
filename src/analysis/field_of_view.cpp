#include "occlusion/analysis/field_of_view.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace occlusion {

namespace {

double degrees(double radians) {
  return radians * 180.0 / M_PI;
}

}  // namespace

bool FieldOfView::contains(const Eigen::Vector3d& direction) const {
  const Eigen::Vector3d d = orientation.conjugate() * direction;
  if (!(d.z() > 0.0)) return false;
  return d.x() >= x_lo * d.z() && d.x() <= x_hi * d.z() && d.y() >= y_lo * d.z() &&
         d.y() <= y_hi * d.z();
}

double FieldOfView::horizontal_degrees() const {
  return degrees(std::atan(x_hi) - std::atan(x_lo));
}

double FieldOfView::vertical_degrees() const {
  return degrees(std::atan(y_hi) - std::atan(y_lo));
}

FieldOfView measure_field_of_view(const PointCloud& cloud) {
  if (cloud.size() == 0) throw std::invalid_argument("field of view: no points");
  FieldOfView view;
  view.orientation = cloud.sensor.orientation.normalized();
  const Eigen::Quaterniond to_sensor = view.orientation.conjugate();
  view.x_lo = view.y_lo = std::numeric_limits<double>::infinity();
  view.x_hi = view.y_hi = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Eigen::Vector3d p = to_sensor * (cloud.positions[i].cast<double>() - cloud.sensor.origin);
    if (!(p.z() > 0.0)) {
      throw std::invalid_argument(
          "field of view: point " + std::to_string(i) +
          " is not in front of the sensor (z <= 0 in the sensor frame), so this is no "
          "single-view frame of that sensor");
    }
    view.x_lo = std::min(view.x_lo, p.x() / p.z());
    view.x_hi = std::max(view.x_hi, p.x() / p.z());
    view.y_lo = std::min(view.y_lo, p.y() / p.z());
    view.y_hi = std::max(view.y_hi, p.y() / p.z());
  }
  // Pixel centres span (W - 1) pixels; the image spans W.
  const auto widen = [](double& lo, double& hi, std::size_t pixels) {
    if (pixels < 2) return;
    const double half_pixel = 0.5 * (hi - lo) / static_cast<double>(pixels - 1);
    lo -= half_pixel;
    hi += half_pixel;
  };
  if (cloud.sensor.organised()) {
    widen(view.x_lo, view.x_hi, cloud.sensor.width);
    widen(view.y_lo, view.y_hi, cloud.sensor.height);
  }
  return view;
}

FieldOfView field_of_view_from_angles(const SensorFrame& sensor, double horizontal_degrees,
                                      double vertical_degrees) {
  for (const double angle : {horizontal_degrees, vertical_degrees}) {
    if (!(angle > 0.0 && angle < 180.0)) {
      throw std::invalid_argument("field of view angles must be in (0, 180) degrees");
    }
  }
  FieldOfView view;
  view.orientation = sensor.orientation.normalized();
  view.x_hi = std::tan(0.5 * horizontal_degrees * M_PI / 180.0);
  view.x_lo = -view.x_hi;
  view.y_hi = std::tan(0.5 * vertical_degrees * M_PI / 180.0);
  view.y_lo = -view.y_hi;
  return view;
}

}  // namespace occlusion
