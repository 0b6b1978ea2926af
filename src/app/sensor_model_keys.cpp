// The sensor models' keys (docs/simulate.md has the models and their sources).

#include "occlusion/app/sensor_model_keys.hpp"

namespace occlusion {

const Keys<LaserScannerModel>& laser_scanner_keys() {
  using M = LaserScannerModel;
  static const Keys<M> keys = {
      key("azimuth_step", &M::azimuth_step_deg)
          .positive_up_to(360)
          .unit("degrees")
          .doc("laser: the beam's horizontal step"),
      key("elevation_step", &M::elevation_step_deg)
          .positive_up_to(180)
          .unit("degrees")
          .doc("laser: the beam's vertical step"),
      key("azimuth_min", &M::azimuth_min_deg)
          .range(-360, 360)
          .unit("degrees")
          .doc("laser: the window's first azimuth (from x towards y in the scanner's frame)"),
      key("azimuth_max", &M::azimuth_max_deg)
          .range(-360, 720)
          .unit("degrees")
          .doc("laser: the window's last azimuth; a span of 360 is a full turn"),
      key("elevation_min", &M::elevation_min_deg)
          .range(-90, 90)
          .unit("degrees")
          .doc("laser: the lowest beam above the horizontal (a tripod hides what is below)"),
      key("elevation_max", &M::elevation_max_deg)
          .range(-90, 90)
          .unit("degrees")
          .doc("laser: the highest beam above the horizontal"),
      key("min_range", &M::min_range)
          .range(0, 1e6)
          .unit("scene units")
          .doc("laser: returns nearer than this are dropped"),
      key("max_range", &M::max_range)
          .positive_up_to(1e6)
          .unit("scene units")
          .doc("laser: nothing farther returns"),
      key("range_noise", &M::range_noise)
          .range(0, 10)
          .unit("scene units")
          .doc("laser: the range noise's sigma, its constant part"),
      key("range_noise_share", &M::range_noise_share)
          .range(0, 1)
          .doc("laser: the range noise's sigma, its part proportional to range"),
      key("beam_divergence", &M::beam_divergence_mrad)
          .range(0, 1000)
          .unit("mrad")
          .doc("laser: the beam's full divergence angle; > 0 samples its footprint with "
               "beam_samples sub-rays, giving mixed returns at depth edges; 0: one ray"),
      key("beam_samples", &M::beam_samples)
          .range(1, 64)
          .doc("laser: sub-rays of a divergent beam (the centre and a spiral across its "
               "footprint)"),
      key("echo_window", &M::echo_window)
          .range(0, 1e6)
          .unit("scene units")
          .doc("laser: echoes of one beam nearer than this to its first merge into one return "
               "at their mean range"),
  };
  return keys;
}

const Keys<DepthCameraModel>& depth_camera_keys() {
  using M = DepthCameraModel;
  static const Keys<M> keys = {
      key("width", &M::width).range(1, 16384).unit("pixels").doc("camera: image columns"),
      key("height", &M::height).range(1, 16384).unit("pixels").doc("camera: image rows"),
      key("fx", &M::fx).positive_up_to(1e6).unit("pixels").doc("camera: focal length along x"),
      key("fy", &M::fy).positive_up_to(1e6).unit("pixels").doc("camera: focal length along y"),
      key("cx", &M::cx)
          .range(-1e6, 1e6)
          .auto_allowed()
          .unit("pixels")
          .doc("camera: principal point's column; auto: the image's centre"),
      key("cy", &M::cy)
          .range(-1e6, 1e6)
          .auto_allowed()
          .unit("pixels")
          .doc("camera: principal point's row; auto: the image's centre"),
      key("min_depth", &M::min_depth)
          .positive_up_to(1e6)
          .unit("scene units")
          .doc("camera: nearer depths are not measured"),
      key("max_depth", &M::max_depth)
          .positive_up_to(1e6)
          .unit("scene units")
          .doc("camera: farther depths are not measured"),
      key("depth_noise_a", &M::depth_noise_a)
          .range(0, 10)
          .unit("scene units")
          .doc("camera: depth noise sigma(z) = a + b (z - c)^2, its constant a (Kinect: "
               "Nguyen et al. 2012)"),
      key("depth_noise_b", &M::depth_noise_b)
          .range(0, 10)
          .doc("camera: depth noise's b, per scene unit"),
      key("depth_noise_c", &M::depth_noise_c)
          .range(-1e6, 1e6)
          .unit("scene units")
          .doc("camera: depth noise's c, the depth of least noise"),
      key("baseline", &M::baseline)
          .positive_up_to(1e3)
          .unit("scene units")
          .doc("camera: projector-camera baseline; disparity = fx x baseline / depth"),
      key("disparity_step", &M::disparity_step)
          .range(0, 100)
          .unit("pixels")
          .doc("camera: disparities are rounded to this (Kinect: 1/8 px), so depths come in "
               "steps growing as depth^2; 0: not quantised"),
  };
  return keys;
}

}  // namespace occlusion
