#pragma once
// The `cloud_occlusion` job (-poc): occlusion ray ratio of a point cloud from
// spherical light sources at the viewpoints, with openings, and optionally the
// exterior-structure variant and the interior/exterior point ratio.

#include <json/value.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "occlusion/analysis/cloud_occlusion.hpp"
#include "occlusion/analysis/point_spacing.hpp"
#include "occlusion/app/key.hpp"
#include "occlusion/app/level_counts.hpp"
#include "occlusion/app/point_model.hpp"
#include "occlusion/app/station_filter.hpp"
#include "occlusion/app/viewpoint_choice.hpp"

namespace occlusion {

struct CloudOcclusionRequest {
  std::string path;
  // The cloud's stations when it records any (an E57 scan's poses), else a grid of 9.
  ViewpointChoice viewpoints = ViewpointChoice::stations_else(ViewpointChoice::from_grid(9));
  std::uint64_t num_rays_per_vp = 30000;
  // How points meet rays (app/point_model.hpp): discs, or the thesis' spheres.
  std::string primitive = "disc";
  // kAutoPointRadius: discs from their neighbours' density, spheres from the
  // measured point spacing (job_support.hpp).
  double point_radius = kAutoPointRadius;
  double disc_coverage = kDefaultDiscCoverage;
  unsigned normal_neighbours = kDefaultNormalNeighbours;
  std::string polygon_path;  // openings file; empty = none
  double octree_resolution = 0.0;
  bool enable_acceleration = true;
  std::string sampling = "uniform";  // or "fibonacci"
  double light_radius = 0.0;
  // Keep each occlusion ray's direction (for the viewer); always kept with --out.
  bool escape_directions = false;
  // Full angles [horizontal, vertical] in degrees around the sensor's +z
  // (pose from the PCD VIEWPOINT): treat the cloud as a single-view frame.
  // Empty: measured from the frame when it is one (organised PCD, or a
  // VIEWPOINT other than the default), else no field of view.
  std::vector<double> field_of_view;
  bool exterior = false;  // also compute the exterior-structure variant
  std::vector<std::string> exterior_classes = {"wall", "floor", "ceiling"};
  bool skip_bad_lines = false;
  // Laser-scan hygiene at load (station_filter.hpp): the stations kept (by
  // name; empty: all) and the ranges trusted from each point's own station (0: off).
  std::vector<std::string> scans;
  double min_range = 0.0;
  double max_range = 0.0;
  std::string class_names_path;  // names the cloud's labels (io/class_names_file.hpp); "" = none
  // Box the pattern or grid is placed on: "robust" (per-axis quantiles, cuts
  // off stray points) or "bbox" (all points); see analysis/scene_frame.hpp.
  std::string frame = "robust";
  std::string up = "+z";  // signed axis: where height matters (the grid's mid-height)
  std::uint64_t seed = 0;
  unsigned threads = 0;
  std::string out;
  // Refuse, before the work, a request estimated to need more (memory_budget.hpp); 0 = the machine.
  std::uint64_t max_memory_mb = 0;
  // Refuse, before the work, a request estimated to trace more (work_budget.hpp),
  // in G ray steps; 0 = no budget.
  double max_work = 0;
};

struct ExteriorReport {
  CloudOcclusionResult result;
  std::size_t exterior_points = 0;
  std::size_t interior_points = 0;
  double interior_exterior_ratio = 0.0;
};

struct CloudOcclusionReport {
  CloudOcclusionRequest request;
  CloudOcclusionResult result;
  PointModelReport point_model;              // as traced, with the measured spacing
  std::optional<FieldOfView> field_of_view;  // set for a single-view frame
  std::string field_of_view_source;          // why the cloud was taken as one
  // Set for one laser station's gridded scan (spherical_field_of_view.hpp), and that station.
  std::optional<SphericalFieldOfView> station_field_of_view;
  Station field_of_view_station;
  // What the rays outside the view (outside_view_rays) are outside of, and
  // why they are not counted (level_counts.hpp); empty without a field of view.
  std::string outside_view_why;
  std::optional<ExteriorReport> exterior;
  std::vector<std::string> viewpoint_names;
  std::string viewpoint_source;        // ViewpointChoice::Resolved::source
  StationFilterReport station_filter;  // what scans/min_range/max_range dropped
  Json::Value frame;  // how the viewpoints were placed (ViewpointChoice::Resolved::frame)
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();  // the cloud's global shift
  std::size_t openings = 0;
  std::size_t dropped_nan = 0;
  std::size_t skipped_lines = 0;
  std::vector<std::string> outputs;
  std::vector<std::string> warnings;
  double load_seconds = 0.0;
  double total_seconds = 0.0;
};

void validate(const CloudOcclusionRequest& request);
// Every key of the job (config section occlusion.point_cloud), declared once.
const Keys<CloudOcclusionRequest>& cloud_occlusion_keys();
// The tracing keys alone (no path, viewpoints or outputs): the study takes them too.
const Keys<CloudOcclusionRequest>& cloud_tracing_keys();

CloudOcclusionReport run_cloud_occlusion(const CloudOcclusionRequest& request,
                                         const Progress& progress = {});

// What run_cloud_occlusion computes once the cloud is loaded, for a cloud
// already in memory and viewpoints already placed (the study measures each
// scanned cloud from its scan's viewpoints). request.path names the cloud in
// messages; nothing is read or written.
CloudOcclusionReport run_cloud_occlusion_on(const PointCloud& cloud,
                                            const ViewpointChoice::Resolved& viewpoints,
                                            const std::vector<PlanarPolygon>& openings,
                                            const CloudOcclusionRequest& request,
                                            const Progress& progress = {});
// The openings of a polygon file; none for "". InputError naming the file and
// the opening that is no polygon.
std::vector<PlanarPolygon> read_openings(const std::string& polygon_path);
// Headline: occlusion_level.
Json::Value to_json(const CloudOcclusionReport& report);

}  // namespace occlusion
