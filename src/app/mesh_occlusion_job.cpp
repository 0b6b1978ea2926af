#include "occlusion/app/mesh_occlusion_job.hpp"

#include <json/writer.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>

#include "occlusion/analysis/mesh_sampling.hpp"
#include "occlusion/analysis/viewpoints.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/json_output.hpp"
#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/obj_reader.hpp"
#include "occlusion/io/ply_mesh_writer.hpp"

namespace occlusion {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Files written with --out, named after the mesh so that several meshes can
// share one output folder.
struct OutputPaths {
  std::string json, ply, csv;
};

OutputPaths output_paths(const MeshOcclusionRequest& request) {
  const std::string stem = std::filesystem::path(request.path).stem().string();
  const std::filesystem::path dir(request.out);
  return {(dir / (stem + ".moc.json")).string(), (dir / (stem + ".moc.ply")).string(),
          (dir / (stem + ".moc.csv")).string()};
}

void write_face_csv(const std::string& path, const TriangleMesh& mesh,
                    const MeshOcclusionReport& report) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << "face,group,area,samples,visible_fraction\n" << std::setprecision(9);
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
      const double area = mesh.face_area(f);
      out << f << ',' << csv_field(mesh.group_names[mesh.face_group[f]]) << ',' << area << ','
          << samples_for_area(area, report.request.samples_per_unit_area) << ','
          << report.result.face_visible_fraction[f] << '\n';
    }
  });
}

}  // namespace

void validate(const MeshOcclusionRequest& request) {
  if (request.path.empty()) throw UsageError("no mesh given (-moc MESH or occlusion.mesh.path)");
  if (request.viewpoints.empty() &&
      (request.pattern < kMinPattern || request.pattern > kMaxPattern)) {
    throw UsageError("--pattern must be 1..7, got " + std::to_string(request.pattern));
  }
  for (const auto& vp : request.viewpoints) {
    if (!vp.allFinite()) throw UsageError("--viewpoint must be finite");
  }
  if (!std::isfinite(request.samples_per_unit_area) || request.samples_per_unit_area <= 0.0) {
    throw UsageError("--samples-per-unit-area must be a number > 0");
  }
  if (!std::isfinite(request.octree_resolution) || request.octree_resolution < 0.0) {
    throw UsageError("--octree-resolution must be a number >= 0");
  }
}

MeshOcclusionReport run_mesh_occlusion(const MeshOcclusionRequest& request,
                                       const Progress& progress) {
  validate(request);
  const auto start = Clock::now();
  MeshOcclusionReport report;
  report.request = request;

  progress("loading", 0.0);
  const TriangleMesh mesh = read_obj(request.path);
  report.load_seconds = seconds_since(start);
  progress.check_cancel();

  Eigen::Vector3d lo, hi;
  mesh.bounds(lo, hi);
  std::vector<Eigen::Vector3d> viewpoints = request.viewpoints;
  if (viewpoints.empty()) {
    viewpoints = pattern_viewpoints(request.pattern, lo, hi);
    report.viewpoint_names = pattern_viewpoint_names(request.pattern);
  } else {
    for (std::size_t v = 0; v < viewpoints.size(); ++v) {
      report.viewpoint_names.push_back("viewpoint_" + std::to_string(v + 1));
    }
  }
  const double half_extent = 0.5 * (hi - lo).maxCoeff();
  if (request.enable_acceleration && request.octree_resolution >= half_extent) {
    report.warnings.push_back("octree_resolution " + std::to_string(request.octree_resolution) +
                              " is at least half the scene's extent (" +
                              std::to_string(half_extent) +
                              "): the octree cannot subdivide, so every ray tests every triangle");
  }

  MeshOcclusionOptions options;
  options.samples_per_unit_area = request.samples_per_unit_area;
  options.octree.min_cell_size = static_cast<float>(request.octree_resolution);
  options.octree.enable_acceleration = request.enable_acceleration;
  options.seed = request.seed;
  options.threads = request.threads;
  report.result = compute_mesh_occlusion(mesh, viewpoints, options, progress);

  if (!request.out.empty()) {
    ensure_directory(request.out);
    const OutputPaths paths = output_paths(request);
    write_mesh_ply(paths.ply, mesh, report.result.face_visible_fraction, "visible_fraction");
    write_face_csv(paths.csv, mesh, report);
    report.outputs = {paths.json, paths.ply, paths.csv};
    report.total_seconds = seconds_since(start);
    const Json::Value json = to_json(report);
    write_file_atomically(paths.json, [&](std::ostream& out) { out << format_json(json) << '\n'; });
  }
  report.total_seconds = seconds_since(start);
  return report;
}

Json::Value to_json(const MeshOcclusionReport& report) {
  const MeshOcclusionResult& r = report.result;
  const MeshOcclusionRequest& q = report.request;
  Json::Value json(Json::objectValue);
  json["job"] = "mesh_occlusion";
  json["input"] = q.path;
  json["occlusion_level"] = r.occlusion_level;
  json["visible_area"] = r.visible_area;
  json["total_area"] = r.total_area;
  json["faces"] = Json::UInt64(r.faces);
  json["samples"] = Json::UInt64(r.samples);
  json["rays"] = Json::UInt64(r.rays);

  Json::Value viewpoints(Json::arrayValue);
  for (std::size_t v = 0; v < r.viewpoints.size(); ++v) {
    Json::Value vp(Json::objectValue);
    vp["name"] = report.viewpoint_names.at(v);
    vp["position"] = to_json(r.viewpoints[v].position);
    vp["visible_area"] = r.viewpoints[v].visible_area;
    vp["visible_fraction"] = r.viewpoints[v].visible_fraction;
    viewpoints.append(vp);
  }
  json["viewpoints"] = viewpoints;

  Json::Value groups(Json::arrayValue);
  for (const auto& g : r.groups) {
    Json::Value group(Json::objectValue);
    group["name"] = g.name;
    group["faces"] = Json::UInt64(g.faces);
    group["total_area"] = g.total_area;
    group["visible_area"] = g.visible_area;
    group["occlusion_level"] = g.occlusion_level;
    groups.append(group);
  }
  json["groups"] = groups;

  Json::Value parameters(Json::objectValue);
  parameters["pattern"] = q.viewpoints.empty() ? Json::Value(q.pattern) : Json::Value();
  parameters["samples_per_unit_area"] = q.samples_per_unit_area;
  parameters["octree_resolution"] = q.octree_resolution;
  parameters["enable_acceleration"] = q.enable_acceleration;
  parameters["seed"] = Json::UInt64(q.seed);
  parameters["threads"] = q.threads;
  json["parameters"] = parameters;

  Json::Value octree(Json::objectValue);
  octree["inner_nodes"] = Json::UInt64(r.octree.inner_nodes);
  octree["leaves"] = Json::UInt64(r.octree.leaves);
  octree["depth"] = r.octree.depth;
  octree["largest_leaf"] = Json::UInt64(r.octree.largest_leaf);
  octree["memory_bytes"] = Json::UInt64(r.octree.memory_bytes);
  json["octree"] = octree;

  Json::Value timings(Json::objectValue);
  timings["load_seconds"] = report.load_seconds;
  timings["sampling_seconds"] = r.timings.sampling_seconds;
  timings["build_seconds"] = r.timings.build_seconds;
  timings["trace_seconds"] = r.timings.trace_seconds;
  timings["total_seconds"] = report.total_seconds;
  json["timings"] = timings;

  json["outputs"] = to_json(report.outputs);
  json["warnings"] = to_json(report.warnings);
  return json;
}

}  // namespace occlusion
