// The jobs of the app layer as commands: params are the job's config section,
// the result is the job's JSON report, per-element data follows as frames.

#include <json/value.h>

#include <map>
#include <utility>

#include "command_table.hpp"
#include "job_params.hpp"
#include "loaded_scene.hpp"
#include "occlusion/app/cloud_occlusion_job.hpp"
#include "occlusion/app/command_line.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/evaluate_job.hpp"
#include "occlusion/app/extract_polygons_job.hpp"
#include "occlusion/app/job_registry.hpp"
#include "occlusion/app/mesh_occlusion_job.hpp"
#include "occlusion/app/plan_job.hpp"
#include "occlusion/app/reconstruct_job.hpp"
#include "occlusion/app/region_growing_job.hpp"
#include "occlusion/app/scan_job.hpp"
#include "occlusion/app/study_job.hpp"
#include "occlusion/io/cloud_io.hpp"

namespace occlusion::server {

namespace {

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

// Per point: how many viewpoints see it, and the number (from 1, in the
// report's viewpoints) of the first that does, -1 for none (plan's covered_by).
void scan_frames(CommandContext& context, const ScanReport& report) {
  const auto& count = report.result.visible_count;
  context.send(make_frame(FrameKind::kVisibleCount, count.data(), count.size(), 1));
  const auto& first = report.result.first_viewpoint;
  context.send(make_frame(FrameKind::kCoveredBy, first.data(), first.size(), 1));
}

// Per target (a cloud's point, a mesh's sample): the rank of the first
// station that sees it, -1 for none.
void plan_frames(CommandContext& context, const PlanReport& report) {
  const auto& rank = report.selection.first_rank;
  context.send(make_frame(FrameKind::kCoveredBy, rank.data(), rank.size(), 1));
}

Frame point_clusters_frame(const MeshEstimate& estimate) {
  const auto& clusters = estimate.point_cluster;
  return make_frame(FrameKind::kPointClusters, clusters.data(), clusters.size(), 1);
}

// The estimated mesh (as `load` sends a mesh, in the cloud's local frame as
// its positions were: the report holds it in the file's), how much of each
// face is visible, and which cluster each input point fell in.
void region_growing_frames(CommandContext& context, const RegionGrowingReport& report) {
  context.send(mesh_scene(report.estimate.mesh, report.shift)->frames);
  const auto& fraction = report.occlusion.face_visible_fraction;
  context.send(make_frame(FrameKind::kFaceVisibleFraction, fraction.data(), fraction.size(), 1));
  context.send(point_clusters_frame(report.estimate));
}

// The planes as a mesh (in the cloud's local frame, as above), and which
// cluster (= face group) each input point fell in.
void extract_polygons_frames(CommandContext& context, const ExtractPolygonsReport& report) {
  context.send(mesh_scene(report.estimate.mesh, report.shift)->frames);
  context.send(point_clusters_frame(report.estimate));
}

// A segmenter command would let whatever reaches the server run a shell
// command as the server's user; over the protocol the study segments with the
// built-in baseline only, and a network runs from the command line.
void refuse_segmenter_commands(const Json::Value& params) {
  if (params.isObject() && params.isMember("segmenter") &&
      !(params["segmenter"].isString() && params["segmenter"].asString() == kBaselineSegmenter)) {
    throw UsageError(
        "'segmenter': only \"baseline\" over the server; a segmenter command runs with "
        "'occlusion study' on the command line");
  }
}

// The reconstructed cloud itself, read back from what the job wrote, so the
// viewer shows exactly the file; relative to the report's global_shift, so
// that shift turns its positions into the file's frame.
void reconstruct_frames(CommandContext& context, const ReconstructReport& report) {
  if (report.outputs.empty()) return;
  context.progress()("sending", 0.9);
  CloudReadOptions options;
  options.shift = report.shift;
  context.send(cloud_frames(read_cloud(report.outputs.front(), options)));
}

using Frames = void (*)(CommandContext&, const JobRun&);

template <class Report, void (*send)(CommandContext&, const Report&)>
void typed_frames(CommandContext& context, const JobRun& run) {
  send(context, run.report_as<Report>());
}

// What each job sends beside its JSON report.
const std::map<std::string, Frames>& job_frames() {
  static const std::map<std::string, Frames> table = {
      {"mesh_occlusion", &typed_frames<MeshOcclusionReport, mesh_frames>},
      {"cloud_occlusion", &typed_frames<CloudOcclusionReport, escape_frames>},
      {"region_growing_occlusion", &typed_frames<RegionGrowingReport, region_growing_frames>},
      {"scan", &typed_frames<ScanReport, scan_frames>},
      {"reconstruct", &typed_frames<ReconstructReport, reconstruct_frames>},
      {"extract_polygons", &typed_frames<ExtractPolygonsReport, extract_polygons_frames>},
      {"plan", &typed_frames<PlanReport, plan_frames>},
  };
  return table;
}

}  // namespace

std::vector<Command> job_commands() {
  std::vector<Command> commands;
  for (const JobInfo& job : jobs()) {
    commands.push_back(Command{
        job.name, Where::kWorker, [&job](CommandContext& context) {
          if (job.name == "study") refuse_segmenter_commands(context.params);
          const JobBudget budget{context.server.limits.max_memory_mb, context.max_work};
          const JobRun run = job.run({job_source(context.params, job, context.server.root, budget)},
                                     context.progress());
          context.progress().check_cancel();
          const auto frames = job_frames().find(job.name);
          if (frames != job_frames().end()) frames->second(context, run);
          Json::Value json = run.json;
          context.server.root.relativise(json);
          // The same run from the CLI or Python, in the data directory (client
          // paths are relative to it): the viewer offers it beside the result.
          json["reproduce"]["cli"] = cli_command(job, context.params);
          json["reproduce"]["python"] = python_call(job, context.params);
          return json;
        }});
  }
  return commands;
}

}  // namespace occlusion::server
