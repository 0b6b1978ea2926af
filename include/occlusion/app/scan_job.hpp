#pragma once
// The `scan` job (-fscan): keep the points of a full cloud that the
// viewpoints really see, all attributes kept.

#include <json/value.h>

#include <optional>
#include <string>
#include <vector>

#include "occlusion/analysis/point_spacing.hpp"
#include "occlusion/analysis/scan.hpp"
#include "occlusion/app/key.hpp"
#include "occlusion/app/point_model.hpp"
#include "occlusion/app/station_filter.hpp"
#include "occlusion/app/viewpoint_choice.hpp"

namespace occlusion {

struct ScanRequest {
  std::string path;
  // The cloud's stations when it records any (an E57 scan's poses), else pattern 7.
  ViewpointChoice viewpoints = ViewpointChoice::stations_else(ViewpointChoice::from_pattern(7));
  // How points meet rays (app/point_model.hpp): discs, or the thesis' spheres.
  std::string primitive = "disc";
  // kAutoPointRadius: discs from their neighbours' density, spheres from the
  // measured point spacing (job_support.hpp).
  double point_radius = kAutoPointRadius;
  double disc_coverage = kDefaultDiscCoverage;
  unsigned normal_neighbours = kDefaultNormalNeighbours;
  // Negative: spheres 2 * point_radius, discs their own surface's reach (scan.hpp).
  double self_tolerance = -1.0;
  double octree_resolution = 0.0;
  bool enable_acceleration = true;
  std::string format = "ply";  // of the written clouds: ply or pcd
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
  unsigned threads = 0;
  std::string out;
  // Refuse, before the work, a request estimated to need more (memory_budget.hpp); 0 = the machine.
  std::uint64_t max_memory_mb = 0;
  // Refuse, before the work, a request estimated to trace more (work_budget.hpp),
  // in G ray steps; 0 = no budget.
  double max_work = 0;
};

struct ClassVisibility {
  std::string name;
  std::size_t points = 0;
  std::size_t visible = 0;
  double visible_fraction = 0.0;
};

struct ScanReport {
  ScanRequest request;
  ScanResult result;
  PointModelReport point_model;  // as traced, with the measured spacing
  // Set for one laser station's gridded scan: its window (spherical_field_of_view.hpp).
  std::optional<SphericalFieldOfView> field_of_view;
  Station field_of_view_station;  // that station
  std::vector<std::string> viewpoint_names;
  std::string viewpoint_source;  // ViewpointChoice::Resolved::source
  Json::Value frame;  // how the viewpoints were placed (ViewpointChoice::Resolved::frame)
  std::vector<Eigen::Vector3d> viewpoint_positions;  // in the file's frame
  StationFilterReport station_filter;                // what scans/min_range/max_range dropped
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();   // the cloud's global shift
  std::vector<ClassVisibility> classes;              // empty for unlabelled clouds
  std::size_t dropped_nan = 0;
  std::size_t skipped_lines = 0;
  std::vector<std::string> outputs;
  std::vector<std::string> warnings;
  double load_seconds = 0.0;
  double total_seconds = 0.0;
};

void validate(const ScanRequest& request);
// Every key of the job (config section occlusion.scan), declared once.
const Keys<ScanRequest>& scan_keys();
ScanReport run_scan(const ScanRequest& request, const Progress& progress = {});
// What run_scan computes once the cloud is loaded, for a cloud already in
// memory and viewpoints already placed (the study scans each scene it holds
// from several configurations). Nothing is read or written.
ScanReport run_scan_on(const PointCloud& cloud, const ViewpointChoice::Resolved& viewpoints,
                       const ScanRequest& request, const Progress& progress = {});
// Which points the scan kept: visible_count > 0 (PointCloud::subset's mask).
std::vector<bool> seen_points(const ScanResult& result);
// Headline: visible_fraction.
Json::Value to_json(const ScanReport& report);

}  // namespace occlusion
