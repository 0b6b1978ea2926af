#include <cstdio>

#include "arguments.hpp"
#include "commands.hpp"
#include "common_options.hpp"
#include "job_options.hpp"
#include "occlusion/app/cloud_occlusion_job.hpp"
#include "occlusion/app/errors.hpp"
#include "option_table.hpp"
#include "run_command.hpp"

namespace occlusion::cli {

namespace {

struct CloudOcclusionCommand {
  CloudOcclusionRequest request;
  OutputOptions output;
};

CloudOcclusionCommand parse(const std::vector<std::string>& args) {
  CloudOcclusionCommand command;
  CloudOcclusionRequest& request = command.request;
  if (const auto config = config_path(args)) apply_config(load_config(*config), request);

  ViewpointOptions viewpoints;
  OptionTable table("-poc");
  add_output_options(table, command.output);
  add_viewpoint_options(table, viewpoints, /*allow_grid=*/true);
  add_tracing_options(table, request);
  table.value({"--out"}, [&](const std::string&, const std::string& v) { request.out = v; });
  table.parse(args, single_input(request.path, "-poc"));
  viewpoints.apply_to(request.viewpoints);
  return command;
}

void print_help() {
  std::printf(
      "usage: occlusion -poc CLOUD [options]\n"
      "\n"
      "Occlusion ray ratio of a point cloud: each point is a sphere of --point-radius;\n"
      "from each viewpoint --num-rays-per-vp rays leave a spherical light source. A ray\n"
      "that hits no point and leaves through no opening is an occlusion ray;\n"
      "occlusion_level = occlusion rays / rays.\n"
      "\n"
      "CLOUD: .pcd, .ply, .txt (x y z [r g b] [label]) or an S3DIS room/Area folder.\n"
      "\n"
      "options (each is also a key of the config section occlusion.point_cloud):\n"
      "  --config FILE                JSON config; options on the command line override it\n"
      "  --num-vp N                   N viewpoints on a grid at mid-height (default 9)\n"
      "  --pattern N                  viewpoint pattern 1..7 on the bounding box (see -moc "
      "--help)\n"
      "  --viewpoint X,Y,Z            explicit viewpoint (repeatable)\n"
      "  --num-rays-per-vp N          rays per viewpoint (default 30000)\n"
      "  --point-radius R             sphere radius of each point (default 0.01)\n"
      "  --polygon-path FILE          openings (windows, doors): see docs/formats.md\n"
      "  --sampling uniform|fibonacci ray directions: the seed's random theta/phi (default) or\n"
      "                               a randomly rotated Fibonacci lattice (lower variance)\n"
      "  --light-radius R             radius of the spherical light source (default 0)\n"
      "  --exterior                   also the exterior-structure variant: only "
      "--exterior-classes\n"
      "                               block rays; adds the interior/exterior point ratio\n"
      "  --exterior-classes A,B,...   classes of the exterior structure (default "
      "wall,floor,ceiling)\n"
      "  --octree-resolution X        smallest octree cell edge (default 0 = no limit)\n"
      "  --enable-acceleration BOOL   false: test every ray against every point\n"
      "  --skip-bad-lines             skip (and count) malformed lines of text inputs\n"
      "  --seed N                     random seed (default 0)\n"
      "  --threads N                  worker threads (default 0 = all cores)\n"
      "  --out DIR                    write CLOUD.poc.json and CLOUD.poc.escapes.csv (directions\n"
      "                               of the occlusion rays, per viewpoint)\n"
      "  --json                       print one JSON object (headline: occlusion_level)\n"
      "  -q, --quiet                  no progress on stderr\n");
}

void print_human(const CloudOcclusionReport& report) {
  const CloudOcclusionResult& r = report.result;
  std::printf("point-cloud occlusion of %s (%zu points, %zu openings)\n",
              report.request.path.c_str(), r.points, report.openings);
  std::printf(
      "  occlusion level  %.4f   (%zu occlusion rays of %zu; %zu hit points, %zu left "
      "through openings)\n",
      r.occlusion_level, r.occlusion_rays, r.rays, r.hits, r.through_openings);
  for (std::size_t v = 0; v < r.viewpoints.size(); ++v) {
    const auto& vp = r.viewpoints[v];
    std::printf("    %-12s (%8.3f, %8.3f, %8.3f)  occlusion %.4f\n",
                report.viewpoint_names[v].c_str(), vp.position.x(), vp.position.y(),
                vp.position.z(), vp.occlusion_level);
  }
  if (report.exterior) {
    std::printf(
        "  exterior structure only: occlusion level %.4f; interior/exterior points "
        "%zu/%zu = %.4f\n",
        report.exterior->result.occlusion_level, report.exterior->interior_points,
        report.exterior->exterior_points, report.exterior->interior_exterior_ratio);
  }
  if (report.dropped_nan > 0) std::printf("  dropped %zu NaN points\n", report.dropped_nan);
  std::printf("  time: load %.3f s, octree %.3f s, tracing %.3f s, total %.3f s\n",
              report.load_seconds, r.build_seconds, r.trace_seconds, report.total_seconds);
  for (const auto& path : report.outputs) std::printf("  wrote %s\n", path.c_str());
}

}  // namespace

int run_cloud_occlusion_command(const std::vector<std::string>& args) {
  const CloudOcclusionCommand command = parse(args);
  return run_command<CloudOcclusionReport>(
      command.output, "poc", print_help,
      [&](const Progress& progress) { return run_cloud_occlusion(command.request, progress); },
      print_human);
}

}  // namespace occlusion::cli
