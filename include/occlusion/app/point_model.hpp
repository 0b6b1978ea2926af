#pragma once
// What a cloud job (-poc, -fscan, the study's scans) traced its points as:
// discs from the cloud's own surfel model (the default) or the thesis'
// spheres. The settings are keys of each job (shared_keys.hpp:
// primitive, point_radius, disc_coverage, normal_neighbours).

#include <optional>
#include <string>
#include <vector>

#include "occlusion/analysis/point_spacing.hpp"
#include "occlusion/analysis/surfel_estimation.hpp"

namespace occlusion {

struct PointModelReport {
  std::string primitive = "disc";  // "disc" or "sphere"
  // Spheres: the radius traced. Discs: the fixed radius when one was given
  // (automatic false), else the median of the per-point radii. The spacing is
  // measured either way.
  PointRadius radius;
  std::optional<SurfelStats> surfels;       // discs
  std::vector<StationNoise> noise;          // discs, where the job reads it (surface_noise.hpp)
  std::optional<SightLineCarving> carving;  // discs, where the job carves (sight_line_carving.hpp)
  double disc_coverage = 0.0;               // discs with point_radius auto
  unsigned normal_neighbours = 0;           // discs
  // -poc with discs: the share of a cloud's surfaces its discs leave open
  // (cloud_occlusion.hpp, open_surface_share).
  std::optional<double> open_surface_share;
};

}  // namespace occlusion
