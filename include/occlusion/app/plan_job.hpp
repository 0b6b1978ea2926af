#pragma once
// The `plan` job (scan planning, issue 28): where to put scanner stations so
// that they see a scene. Candidates on a grid over the floor (or from a file,
// analysis/station_candidates.hpp), what each sees (a coverage matrix with
// -fscan's visibility for clouds, -moc's samples for meshes:
// analysis/station_visibility.hpp), and a choice of stations: the best K, or
// the fewest that cover a share (analysis/station_selection.hpp).

#include <json/value.h>

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "occlusion/analysis/station_candidates.hpp"
#include "occlusion/analysis/station_refinement.hpp"
#include "occlusion/analysis/station_selection.hpp"
#include "occlusion/analysis/station_visibility.hpp"
#include "occlusion/app/first_station_field.hpp"
#include "occlusion/app/key.hpp"
#include "occlusion/app/point_model.hpp"
#include "occlusion/core/mesh.hpp"
#include "occlusion/core/point_cloud.hpp"
#include "occlusion/core/progress.hpp"

namespace occlusion {

struct PlanRequest {
  std::string path;  // a mesh (OBJ, PLY faces) or a cloud (any format of docs/formats.md)
  // The question: exactly one is in force (their keys set one and clear the other).
  std::size_t stations = 0;       // > 0: the best K new stations
  double target_coverage = 0.99;  // > 0: the fewest new stations that cover this share
  bool improve = true;
  bool intervisible = false;
  std::string out_of_reach = "most";  // a target beyond the candidates: "most" or "share"
  // Each new station moved by a local search to where it adds the most
  // (analysis/station_refinement.hpp).
  bool refine = true;
  // Candidates: a grid over the floor plan, or positions from a cloud file.
  // No spacing: auto, kAutoGridPositions over the frame's floor plan.
  std::optional<double> spacing;
  double height = 1.5;
  double clearance = 0.3;
  std::string candidates_path;
  // Stations already there: given ones, and a cloud's own (scan_stations).
  std::vector<Eigen::Vector3d> placed;
  bool existing_stations = true;
  // Scanner limits (analysis/station_visibility.hpp: StationLimits).
  double max_range = 0.0;
  double max_incidence = 0.0;
  double min_elevation = -90.0;
  double max_elevation = 90.0;
  // Coverage counts only these classes' points (clouds' labels) or faces
  // (meshes' groups); empty: everything.
  std::vector<std::string> classes;
  // Clouds: the point model, as -fscan traces it.
  std::string primitive = "disc";
  double point_radius = kAutoPointRadius;
  double disc_coverage = kDefaultDiscCoverage;
  unsigned normal_neighbours = kDefaultNormalNeighbours;
  double self_tolerance = -1.0;
  std::string class_names_path;
  bool skip_bad_lines = false;
  // Meshes: the samples, as -moc draws them.
  double samples_per_unit_area = 100.0;
  std::uint64_t seed = 0;
  std::string frame = "robust";
  std::string up = "+z";
  unsigned threads = 0;
  std::string out;
  std::uint64_t max_memory_mb = 0;
  double max_work = 0;
};

struct PlanReport {
  PlanRequest request;
  std::string targets;  // "points" (clouds) or "samples" (meshes)
  std::size_t target_count = 0;
  std::size_t weighted_targets = 0;  // of the chosen classes (all without `classes`)
  // Every candidate, in the file's frame: the kept grid (or file) positions,
  // then the placed stations.
  std::vector<Eigen::Vector3d> candidate_positions;
  std::vector<std::string> candidate_names;  // a placed station's name, else ""
  std::vector<std::size_t> placed;           // their candidate indices
  StationCandidates candidates;              // the filter's counts (positions local)
  std::size_t grid_positions = 0;            // before the filter
  std::string candidate_source;              // "grid" or the file
  double spacing = 0.0;                      // the grid's (auto or given)
  StationSelection selection;
  // With refine: each new station's search; its moved places are candidates
  // (candidate_positions) after the others.
  std::optional<Refinement> refinement;
  std::size_t refine_budget = 0;  // positions the refinement may trace (in the work estimate)
  std::size_t refined_stations = 0;
  std::optional<PointModelReport> point_model;  // clouds
  // Meshes: the samples (their positions) the PLY of targets holds.
  std::vector<Eigen::Vector3d> sample_positions;
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();
  Json::Value frame;  // the box the grid was placed on, and up
  std::size_t dropped_nan = 0;
  std::size_t skipped_lines = 0;
  std::vector<std::string> outputs;
  std::vector<std::string> warnings;
  double load_seconds = 0.0, candidate_seconds = 0.0, model_seconds = 0.0, coverage_seconds = 0.0,
         selection_seconds = 0.0, refine_seconds = 0.0, total_seconds = 0.0;
};

void validate(const PlanRequest& request);
// Every key of the job (config section occlusion.plan), declared once.
const Keys<PlanRequest>& plan_keys();
// Of those, the scanner's limits and the up axis they are measured from
// (max_range, max_incidence, min_elevation, max_elevation, up): the live
// station (app/live_station.hpp) takes the same keys.
const Keys<PlanRequest>& plan_limit_keys();
// Those keys' values as the coverage applies them. KeyError for
// min_elevation above max_elevation or an unknown up axis.
StationLimits station_limits(const PlanRequest& request);
// Reads the scene (a mesh by its name, else a cloud), plans, writes the
// outputs under request.out: the JSON report, the curve and the candidates as
// CSV, the targets as a PLY with kFirstStationField (the rank of the first
// station that sees each, first_station_field.hpp).
PlanReport run_plan(const PlanRequest& request, const Progress& progress = {});
// The same on a scene in memory; nothing is written (UsageError when
// request.out is set). request.path names it in messages.
PlanReport plan_cloud(const PointCloud& cloud, const PlanRequest& request,
                      const Progress& progress = {});
PlanReport plan_mesh(const TriangleMesh& mesh, const PlanRequest& request,
                     const Progress& progress = {});
// Headline: coverage.
Json::Value to_json(const PlanReport& report);

}  // namespace occlusion
