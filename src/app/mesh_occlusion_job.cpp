#include "occlusion/app/mesh_occlusion_job.hpp"

#include <json/writer.h>

#include <cmath>

#include "job_support.hpp"
#include "occlusion/analysis/mesh_sampling.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/json_output.hpp"
#include "occlusion/app/memory_budget.hpp"
#include "occlusion/app/work_budget.hpp"
#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/face_table.hpp"
#include "occlusion/io/ply_mesh_writer.hpp"

namespace occlusion {

void validate(const MeshOcclusionRequest& request) {
  if (request.path.empty()) throw UsageError("no mesh given (-moc MESH or occlusion.mesh.path)");
  check_keys(mesh_occlusion_keys(), request);
  request.viewpoints.validate();
}

MeshOcclusionReport run_mesh_occlusion_on(const TriangleMesh& mesh,
                                          const MeshOcclusionRequest& request,
                                          const Progress& progress) {
  validate(request);
  MeshOcclusionReport report;
  report.request = request;

  Eigen::Vector3d lo, hi;
  mesh.bounds(lo, hi);
  ViewpointChoice::Resolved viewpoints = request.viewpoints.resolve(lo, hi);
  report.viewpoint_names = viewpoints.names;
  check_memory_budget(
      mesh_occlusion_memory(mesh, request.samples_per_unit_area, viewpoints.positions.size()),
      request.max_memory_mb);
  check_work_budget(mesh_occlusion_work(mesh, request.samples_per_unit_area,
                                        viewpoints.positions.size(), request.enable_acceleration),
                    request.max_work);
  const double half_extent = 0.5 * (hi - lo).maxCoeff();
  if (request.enable_acceleration && request.octree_resolution >= half_extent) {
    report.warnings.push_back("octree_resolution " + std::to_string(request.octree_resolution) +
                              " is at least half the scene's extent (" +
                              std::to_string(half_extent) +
                              "): the octree cannot subdivide, so every ray tests every triangle");
  }

  const MeshOcclusionOptions options = mesh_occlusion_options(request);
  report.result = compute_mesh_occlusion(mesh, viewpoints.positions, options, progress);
  job::warn_viewpoints_inside_solids(report.result.viewpoints, viewpoints, report.warnings);
  return report;
}

MeshOcclusionReport run_mesh_occlusion(const MeshOcclusionRequest& request,
                                       const Progress& progress) {
  validate(request);
  const auto start = job::Clock::now();

  const job::LoadedMesh loaded = job::load_mesh(request.path, progress);
  const TriangleMesh& mesh = loaded.mesh;

  MeshOcclusionReport report = run_mesh_occlusion_on(mesh, request, progress);
  report.load_seconds = loaded.seconds;
  report.degenerate_faces_skipped = loaded.read.degenerate_faces;
  job::warn_degenerate_faces(request.path, loaded.read, report.warnings);

  if (!request.out.empty()) {
    ensure_directory(request.out);
    // Named after the mesh so that several meshes can share one output folder.
    const std::string json_path = job::output_path(request.out, request.path, ".moc.json");
    const std::string ply_path = job::output_path(request.out, request.path, ".moc.ply");
    const std::string csv_path = job::output_path(request.out, request.path, ".moc.csv");
    OutputSet outputs;
    write_mesh_ply(outputs.add(ply_path), mesh, report.result.face_visible_fraction,
                   "visible_fraction");
    std::vector<std::size_t> samples(mesh.face_count());
    for (std::size_t f = 0; f < samples.size(); ++f) {
      samples[f] = samples_for_area(mesh.face_area(f), request.samples_per_unit_area);
    }
    write_face_table(outputs.add(csv_path), mesh, samples, report.result.face_visible_fraction);
    job::commit_outputs(outputs, report, json_path, {json_path, ply_path, csv_path}, start);
  }
  report.total_seconds = job::seconds_since(start);
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
  json["degenerate_faces_skipped"] = Json::UInt64(report.degenerate_faces_skipped);
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

  json["parameters"] = parameters_json(mesh_occlusion_keys(), q);

  json["octree"] = to_json(r.octree);

  Json::Value timings(Json::objectValue);
  timings["load_seconds"] = report.load_seconds;
  timings["sampling_seconds"] = r.timings.sampling_seconds;
  timings["build_seconds"] = r.timings.build_seconds;
  timings["trace_seconds"] = r.timings.trace_seconds;
  timings["total_seconds"] = report.total_seconds;
  json["timings"] = timings;

  job::add_outputs_and_warnings(report, json);
  return json;
}

}  // namespace occlusion
