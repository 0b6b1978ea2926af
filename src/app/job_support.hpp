#pragma once
// Pieces every job's run function shares (internal to app/).

#include <json/value.h>

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "occlusion/analysis/mesh_occlusion.hpp"
#include "occlusion/analysis/point_spacing.hpp"
#include "occlusion/analysis/scene_frame.hpp"
#include "occlusion/analysis/spherical_field_of_view.hpp"
#include "occlusion/analysis/surfel_estimation.hpp"
#include "occlusion/analysis/up_axis.hpp"
#include "occlusion/app/json_output.hpp"
#include "occlusion/app/point_model.hpp"
#include "occlusion/app/viewpoint_choice.hpp"
#include "occlusion/core/mesh.hpp"
#include "occlusion/core/point_cloud.hpp"
#include "occlusion/core/polygon.hpp"
#include "occlusion/core/progress.hpp"
#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/mesh_read_report.hpp"

namespace occlusion::job {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// <out>/<stem of input><suffix>, e.g. ("out", "room.pcd", ".poc.json") -> out/room.poc.json.
std::string output_path(const std::string& out, const std::string& input,
                        const std::string& suffix);

// Viewpoints for a cloud, in its local frame (explicit ones are given in the
// file's frame and converted here, the one place; Resolved::shift is the
// cloud's global shift): a job's default (ViewpointChoice::stations_else) on a
// cloud with stations (scan_stations) gives them, named after them; the rest
// are placed on its robust frame or its bounding box
// (`frame`: robust|bbox, scene_frame.hpp) with `up` a signed axis
// (up_axis.hpp). Resolved::frame reports both boxes and the up axis; warnings
// name each viewpoint outside the occupied space (the robust box; a station
// is exempt) and, for a
// grid (whose mid-height follows up), data that disagree with up. UsageError
// for an unknown frame or up.
ViewpointChoice::Resolved resolve_for_cloud(const ViewpointChoice& choice, const PointCloud& cloud,
                                            const std::string& frame = "robust",
                                            const std::string& up = "+z");
// A report's parameters for viewpoints that are the cloud's stations: the
// default pattern or grid they replaced was not used, so it is not listed.
void stations_in_parameters(const std::string& viewpoint_source, Json::Value& parameters);
// Meshes keep their bounding box (scene_frame.hpp says why); this warns for
// each viewpoint that is inside a closed solid (inside_solid.hpp), from the
// shares compute_mesh_occlusion measured with its own tree.
void warn_viewpoints_inside_solids(const std::vector<ViewpointVisibility>& visibility,
                                   const ViewpointChoice::Resolved& viewpoints,
                                   std::vector<std::string>& warnings);

// A laser station's window (spherical_field_of_view.hpp) when the cloud is
// one station's gridded scan, else none; a station whose window cannot be
// measured is warned about (naming `path`) and has none.
std::optional<SphericalFieldOfView> station_field_of_view(const PointCloud& cloud,
                                                          const std::string& path,
                                                          std::vector<std::string>& warnings);
// {"station", "elevation_degrees": [lo, hi], "full_turn", "azimuth_degrees":
// [start, span], "outside_view_rays"}; null without a window.
Json::Value station_field_of_view_json(const std::optional<SphericalFieldOfView>& view,
                                       const Station& station, std::size_t outside_view_rays);

// The parsed settings, or UsageError naming the option.
FrameKind parse_frame(const std::string& frame);
UpAxis parse_up(const std::string& up);

// The point radius a job traces with: the request's, or for kAutoPointRadius
// the measured spacing times kScanRadiusPerSpacing (`job` "-fscan") or
// kTracingRadiusPerSpacing ("-poc"). The spacing is measured either way,
// unless `measured` already holds it (the disc model's search measures it),
// on `threads` (0 = all cores).
PointRadius choose_point_radius(const PointCloud& cloud, double requested, const std::string& job,
                                const std::optional<PointSpacing>& measured, unsigned threads);
Json::Value point_radius_json(const PointRadius& radius);

// A cloud job's point settings, as its keys hold them.
struct PointSettings {
  std::string primitive;  // "disc" or "sphere"
  double point_radius = kAutoPointRadius;
  double disc_coverage = kDefaultDiscCoverage;
  unsigned normal_neighbours = kDefaultNormalNeighbours;
  unsigned threads = 0;
};

// The points as the job traces them: `surfels` is set for discs. Warns
// (naming what goes wrong, only where it does) about a setting that leaves
// surfaces open or a model with many points it could not orient.
struct PointModel {
  PointModelReport report;
  std::optional<SurfelEstimate> surfels;
};
PointModel choose_point_model(const PointCloud& cloud, const PointSettings& settings,
                              const std::string& job, std::vector<std::string>& warnings,
                              const Progress& progress);
// The point settings of a cloud job's request (-poc's and -fscan's hold the same keys).
template <class Request>
PointSettings point_settings(const Request& request) {
  return {request.primitive, request.point_radius, request.disc_coverage, request.normal_neighbours,
          request.threads};
}
Json::Value point_model_json(const PointModelReport& model);

// [{"name": ..., "position": [x, y, z], <figures>...}, ...] built by the caller.
Json::Value viewpoint_json(const std::string& name, const Eigen::Vector3d& position);
// A result's per-viewpoint positions (local, as traced) in the file's frame,
// as reports give them.
template <class PerViewpoint>
void viewpoints_to_original(std::vector<PerViewpoint>& viewpoints, const PointCloud& cloud) {
  for (auto& viewpoint : viewpoints) viewpoint.position = cloud.to_original(viewpoint.position);
}
// The report's "global_shift": what was subtracted from the cloud's
// coordinates (point_cloud.hpp); positions in reports are in the file's frame.
Json::Value global_shift_json(const Eigen::Vector3d& shift);
// Openings (given in the file's frame) in the cloud's local frame. InputError
// naming `polygon_path` for an opening that lies more than ten times the cloud's
// diagonal outside its bounding box: such an opening can change nothing, and
// is almost always in another frame (e.g. a viewer's local one).
std::vector<PlanarPolygon> openings_in_frame(const std::vector<PlanarPolygon>& openings,
                                             const PointCloud& cloud,
                                             const std::string& polygon_path);

// Throws UsageError unless format is "ply" or "pcd"; returns the file extension.
std::string cloud_extension(const std::string& format);

// Writes a job's JSON report atomically.
void write_json_report(const std::string& path, const Json::Value& json);

// The end of every job that writes files: the JSON report last (it lists
// them all, `paths`), then every output renamed into place at once.
template <class Report>
void commit_outputs(OutputSet& outputs, Report& report, const std::string& json_path,
                    std::vector<std::string> paths, Clock::time_point start) {
  report.outputs = std::move(paths);
  report.total_seconds = seconds_since(start);
  write_json_report(outputs.add(json_path), to_json(report));
  outputs.commit();
}

// The end of every report: the files written and what the user should know.
template <class Report>
void add_outputs_and_warnings(const Report& report, Json::Value& json) {
  json["outputs"] = to_json(report.outputs);
  json["warnings"] = to_json(report.warnings);
}

// A mesh as the mesh jobs load it (-moc, simulate): reported as the stage
// "loading", with what the reader skipped and the seconds it took.
struct LoadedMesh {
  TriangleMesh mesh;
  MeshReadReport read;
  double seconds = 0.0;
};
LoadedMesh load_mesh(const std::string& path, const Progress& progress);
// The warning, naming `path` and the first, for the zero-area faces the
// reader skipped; none when it skipped none.
void warn_degenerate_faces(const std::string& path, const MeshReadReport& read,
                           std::vector<std::string>& warnings);

// A cloud as the point-cloud jobs load it, with what reading dropped or skipped.
struct LoadedCloud {
  PointCloud cloud;
  std::size_t dropped_nan = 0;
  std::size_t skipped_lines = 0;
  std::vector<std::string> rooms;
  std::vector<std::string> unverified_order;  // CloudReadReport::unverified_order
  std::vector<std::size_t> annotation_order;  // CloudReadReport::annotation_order
  std::vector<std::string> warnings;          // CloudReadReport::warnings: the job reports them
};
// `shift` fixes the global shift (CloudReadOptions::shift); unset, the
// reader chooses it. `max_memory_mb` (0: the machine's memory) bounds what
// a depth frame may decode to, checked before it is decoded
// (CloudReadOptions::max_memory_mb); the job's own estimate follows the load.
LoadedCloud load_cloud(const std::string& path, bool skip_bad_lines,
                       const std::optional<Eigen::Vector3d>& shift = std::nullopt,
                       std::uint64_t max_memory_mb = 0);
// Puts what reading the cloud found (LoadedCloud::warnings) first among a
// job's warnings: they come before anything the job made of the cloud.
void add_read_warnings(const LoadedCloud& loaded, std::vector<std::string>& warnings);
// Names the labels of `cloud` (read from `path`) from the class_names file
// `class_names_path` (io/class_names_file.hpp); nothing when it is empty.
void name_classes(PointCloud& cloud, const std::string& path, const std::string& class_names_path);

}  // namespace occlusion::job
