// The jobs of the app layer as commands: params are the job's config section,
// the result is the job's JSON report, per-element data follows as frames.

#include <json/value.h>

#include <cstdint>
#include <type_traits>
#include <utility>

#include "command_table.hpp"
#include "job_params.hpp"
#include "loaded_scene.hpp"
#include "occlusion/app/cloud_occlusion_job.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/evaluate_job.hpp"
#include "occlusion/app/extract_polygons_job.hpp"
#include "occlusion/app/mesh_occlusion_job.hpp"
#include "occlusion/app/reconstruct_job.hpp"
#include "occlusion/app/region_growing_job.hpp"
#include "occlusion/app/scan_job.hpp"
#include "occlusion/app/study_job.hpp"
#include "occlusion/io/cloud_io.hpp"

namespace occlusion::server {

namespace {

template <class Request, class = void>
struct HasMemoryBudget : std::false_type {};
template <class Request>
struct HasMemoryBudget<Request, std::void_t<decltype(Request::max_memory_mb)>> : std::true_type {};

// A job's memory budget on the server is the server's; a request may lower it.
template <class Request>
void apply_memory_budget(Request& request, std::uint64_t server_mb) {
  if constexpr (HasMemoryBudget<Request>::value) {
    if (request.max_memory_mb == 0 || request.max_memory_mb > server_mb) {
      request.max_memory_mb = server_mb;
    }
  }
}

template <class Request, class Report>
Command job_command(const std::string& name, const JobParams& spec,
                    Report (*run)(const Request&, const Progress&),
                    void (*send_frames)(CommandContext&, const Report&)) {
  return Command{name, Where::kWorker, [=](CommandContext& context) {
                   Request request;
                   apply_config(job_config(context.params, spec, context.server.root), request);
                   apply_memory_budget(request, context.server.limits.max_memory_mb);
                   const Report report = run(request, context.progress());
                   context.progress().check_cancel();
                   if (send_frames != nullptr) send_frames(context, report);
                   Json::Value json = to_json(report);
                   context.server.root.relativise(json);
                   return json;
                 }};
}

void mesh_frames(CommandContext& context, const MeshOcclusionReport& report) {
  const auto& fraction = report.result.face_visible_fraction;
  context.send(make_frame(FrameKind::kFaceVisibleFraction, fraction.data(), fraction.size(), 1));
}

void escape_frames(CommandContext& context, const CloudOcclusionReport& report) {
  const auto& viewpoints = report.result.viewpoints;
  for (std::size_t v = 0; v < viewpoints.size(); ++v) {
    const auto& directions = viewpoints[v].escape_directions;
    context.send(make_frame(FrameKind::kEscapeDirections,
                            reinterpret_cast<const float*>(directions.data()), directions.size(), 3,
                            static_cast<std::uint32_t>(v)));
  }
}

void scan_frames(CommandContext& context, const ScanReport& report) {
  const auto& count = report.result.visible_count;
  context.send(make_frame(FrameKind::kVisibleCount, count.data(), count.size(), 1));
}

Frame point_clusters_frame(const MeshEstimate& estimate) {
  const auto& clusters = estimate.point_cluster;
  return make_frame(FrameKind::kPointClusters, clusters.data(), clusters.size(), 1);
}

// The estimated mesh (as `load` sends a mesh), how much of each face is
// visible, and which cluster each input point fell in.
void region_growing_frames(CommandContext& context, const RegionGrowingReport& report) {
  context.send(mesh_scene(report.estimate.mesh)->frames);
  const auto& fraction = report.occlusion.face_visible_fraction;
  context.send(make_frame(FrameKind::kFaceVisibleFraction, fraction.data(), fraction.size(), 1));
  context.send(point_clusters_frame(report.estimate));
}

// The planes as a mesh, and which cluster (= face group) each input point fell in.
void extract_polygons_frames(CommandContext& context, const ExtractPolygonsReport& report) {
  context.send(mesh_scene(report.estimate.mesh)->frames);
  context.send(point_clusters_frame(report.estimate));
}

// A segmenter command would let whatever reaches the server run a shell
// command as the server's user; over the protocol the study segments with the
// built-in baseline only, and a network runs from the command line.
StudyReport run_baseline_study(const StudyRequest& request, const Progress& progress) {
  if (request.segmenter != kBaselineSegmenter) {
    throw UsageError(
        "'segmenter': only \"baseline\" over the server; a segmenter command runs with "
        "'occlusion study' on the command line");
  }
  return run_study(request, progress);
}

// The reconstructed cloud itself, read back from what the job wrote, so the
// viewer shows exactly the file.
void reconstruct_frames(CommandContext& context, const ReconstructReport& report) {
  if (report.outputs.empty()) return;
  context.progress()("sending", 0.9);
  context.send(cloud_frames(read_cloud(report.outputs.front())));
}

}  // namespace

std::vector<Command> job_commands() {
  return {
      job_command("mesh_occlusion", {"mesh", true, {}}, &run_mesh_occlusion, &mesh_frames),
      job_command("cloud_occlusion", {"point_cloud", true, {}}, &run_cloud_occlusion,
                  &escape_frames),
      job_command("region_growing_occlusion", {"region_growing", true, {}},
                  &run_region_growing_occlusion, &region_growing_frames),
      job_command("scan", {"point_cloud", true, {}}, &run_scan, &scan_frames),
      job_command("reconstruct", {"reconstruct", true, {}}, &run_reconstruct, &reconstruct_frames),
      job_command<EvaluateRequest, EvaluateReport>(
          "evaluate", {"evaluate", true, {"ground_truth", "predictions"}}, &run_evaluate, nullptr),
      job_command<ExtractPolygonsRequest, ExtractPolygonsReport>(
          "extract_polygons", {"region_growing", true, {}}, &run_extract_polygons,
          &extract_polygons_frames),
      job_command<StudyRequest, StudyReport>("study", {"study", true, {"scenes"}},
                                             &run_baseline_study, nullptr),
  };
}

}  // namespace occlusion::server
