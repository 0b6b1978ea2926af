#include "occlusion/analysis/sensor_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace occlusion {

namespace {

// A step count that tolerates the window being a whole number of steps in
// decimal but not quite in binary (150 / 0.2 = 749.9999...).
// Absurdly fine steps saturate at 1e15 (no cast of an unrepresentable value):
// the memory budget then refuses them.
std::size_t steps_in(double span, double step) {
  return static_cast<std::size_t>(std::min(std::floor(span / step + 1e-9), 1e15));
}

void require(bool holds, const std::string& model, const std::string& what) {
  if (!holds) throw std::invalid_argument(model + ": " + what);
}

bool positive(double value) {
  return std::isfinite(value) && value > 0.0;
}
bool non_negative(double value) {
  return std::isfinite(value) && value >= 0.0;
}

}  // namespace

std::size_t LaserScannerModel::columns() const {
  const double span = azimuth_max_deg - azimuth_min_deg;
  if (span >= 360.0 - 1e-9) return std::max<std::size_t>(1, steps_in(360.0, azimuth_step_deg));
  return steps_in(span, azimuth_step_deg) + 1;
}

std::size_t LaserScannerModel::rows() const {
  return steps_in(elevation_max_deg - elevation_min_deg, elevation_step_deg) + 1;
}

double LaserScannerModel::azimuth_deg(std::size_t column) const {
  return azimuth_min_deg + static_cast<double>(column) * azimuth_step_deg;
}

double LaserScannerModel::elevation_deg(std::size_t row) const {
  return elevation_min_deg + static_cast<double>(row) * elevation_step_deg;
}

double DepthCameraModel::quantised_depth(double depth) const {
  if (disparity_step <= 0.0) return depth;
  const double scale = fx * baseline;
  const double steps = std::round(scale / depth / disparity_step);
  if (steps <= 0.0) return std::numeric_limits<double>::infinity();
  return scale / (steps * disparity_step);
}

double DepthCameraModel::depth_step(double depth) const {
  if (disparity_step <= 0.0) return 0.0;
  const double scale = fx * baseline;
  const double steps = std::round(scale / depth / disparity_step);
  if (steps <= 1.0) return std::numeric_limits<double>::infinity();
  return scale / ((steps - 1.0) * disparity_step) - scale / (steps * disparity_step);
}

void validate(const LaserScannerModel& m) {
  const std::string name = "laser scanner";
  require(positive(m.azimuth_step_deg) && m.azimuth_step_deg <= 360.0, name,
          "azimuth_step must be in (0, 360] degrees");
  require(positive(m.elevation_step_deg) && m.elevation_step_deg <= 180.0, name,
          "elevation_step must be in (0, 180] degrees");
  require(std::isfinite(m.azimuth_min_deg) && std::isfinite(m.azimuth_max_deg) &&
              m.azimuth_min_deg < m.azimuth_max_deg &&
              m.azimuth_max_deg - m.azimuth_min_deg <= 360.0,
          name, "the azimuth window must have min < max and span at most 360 degrees");
  require(m.elevation_min_deg >= -90.0 && m.elevation_max_deg <= 90.0 &&
              m.elevation_min_deg < m.elevation_max_deg,
          name, "the elevation window must lie in [-90, 90] degrees with min < max");
  require(non_negative(m.min_range) && positive(m.max_range) && m.min_range < m.max_range, name,
          "min_range must be >= 0 and below max_range");
  require(non_negative(m.range_noise) && non_negative(m.range_noise_share), name,
          "range noise must be >= 0");
  require(non_negative(m.beam_divergence_mrad), name, "beam_divergence must be >= 0");
  require(m.beam_samples >= 1, name, "beam_samples must be at least 1");
  require(non_negative(m.echo_window), name, "echo_window must be >= 0");
}

void validate(const DepthCameraModel& m) {
  const std::string name = "depth camera";
  require(m.width >= 1 && m.height >= 1, name, "the image must have pixels");
  require(positive(m.fx) && positive(m.fy) && std::isfinite(m.principal_x()) &&
              std::isfinite(m.principal_y()),
          name, "fx and fy must be > 0, cx and cy finite");
  require(positive(m.min_depth) && positive(m.max_depth) && m.min_depth < m.max_depth, name,
          "min_depth must be > 0 and below max_depth");
  require(non_negative(m.depth_noise_a) && non_negative(m.depth_noise_b) &&
              std::isfinite(m.depth_noise_c),
          name, "depth noise a and b must be >= 0");
  require(positive(m.baseline), name, "baseline must be > 0");
  require(non_negative(m.disparity_step), name, "disparity_step must be >= 0");
}

}  // namespace occlusion
