#pragma once
// What a real sensor does to the rays it measures: the two models of the
// virtual scanner (virtual_scanner.hpp). Pure functions of a model and a true
// distance, so each is checked on its formula alone.
//
// A terrestrial laser scanner turns its beam in azimuth and elevation steps
// (E57's scanner frame: z up, azimuth from x towards y, elevation from the xy
// plane) and measures a range with noise sigma = range_noise + range_noise_share
// x range. A wide beam (beam_divergence > 0) is sampled by beam_samples
// sub-rays across its footprint; echoes within echo_window of the first merge
// into one return at their mean range, as a pulse too short to separate them
// would (the mixed points that float between an edge and what lies behind it).
//
// A structured-light or stereo depth camera (Kinect v1, PrimeSense) sees
// through a pinhole (OpenCV's convention: +x right, +y down, +z forward; pixel
// (u, v)'s centre at (u, v)) and measures depth z, not range. Its noise grows
// with depth, sigma(z) = depth_noise_a + depth_noise_b (z - depth_noise_c)^2
// (Nguyen, Izadi and Lovell 2012, for the Kinect: 0.0012 + 0.0019 (z - 0.4)^2
// metres), and it reports a disparity d = focal x baseline / z rounded to
// disparity_step pixels, so depths come in steps that grow as z^2: 11 mm at
// 2 m, 27 mm at 3 m with the Kinect's 580 px, 7.5 cm and 1/8 px.

#include <cstddef>
#include <optional>

namespace occlusion {

struct LaserScannerModel {
  double azimuth_step_deg = 0.2;
  double elevation_step_deg = 0.2;
  double azimuth_min_deg = 0.0;  // the window the beam sweeps, in the scanner's frame
  double azimuth_max_deg = 360.0;
  double elevation_min_deg = -60.0;
  double elevation_max_deg = 90.0;
  double min_range = 0.5;  // metres (scene units): nearer returns are dropped
  double max_range = 120.0;
  double range_noise = 0.003;         // sigma's constant part
  double range_noise_share = 0.0;     // sigma's part proportional to range
  double beam_divergence_mrad = 0.0;  // full angle; 0: one ray per beam
  unsigned beam_samples = 7;          // sub-rays of a divergent beam
  double echo_window = 0.5;           // echoes nearer than this to the first merge

  // Columns and rows of the beam's grid: the steps that fit the window
  // (a full turn does not measure 360 degrees twice).
  std::size_t columns() const;
  std::size_t rows() const;
  // Beam (column, row)'s angles in degrees.
  double azimuth_deg(std::size_t column) const;
  double elevation_deg(std::size_t row) const;
  double range_sigma(double range) const { return range_noise + range_noise_share * range; }
};

struct DepthCameraModel {
  std::size_t width = 640, height = 480;
  double fx = 580.0, fy = 580.0;  // pixels
  // The principal point in pixels; unset: the image's centre ((width - 1) / 2).
  std::optional<double> cx, cy;
  double min_depth = 0.5, max_depth = 8.0;  // metres (scene units)
  double depth_noise_a = 0.0012, depth_noise_b = 0.0019, depth_noise_c = 0.4;
  double baseline = 0.075;        // metres: with fx, the disparity's scale
  double disparity_step = 0.125;  // pixels; 0: depths are not quantised

  double principal_x() const { return cx.value_or(0.5 * static_cast<double>(width - 1)); }
  double principal_y() const { return cy.value_or(0.5 * static_cast<double>(height - 1)); }
  double depth_sigma(double depth) const {
    const double from_c = depth - depth_noise_c;
    return depth_noise_a + depth_noise_b * from_c * from_c;
  }
  // The depth the camera reports for a (noisy) depth: its disparity rounded to
  // disparity_step, turned back into depth. Unchanged when disparity_step is 0.
  double quantised_depth(double depth) const;
  // The distance between the two reported depths around `depth`.
  double depth_step(double depth) const;
};

// Throw std::invalid_argument naming the field for a model no sensor has: a
// step or window that is empty, ranges out of order, negative noise, a
// divergent beam of no sub-rays.
void validate(const LaserScannerModel& model);
void validate(const DepthCameraModel& model);

}  // namespace occlusion
