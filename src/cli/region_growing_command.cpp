#include <cstdio>

#include "arguments.hpp"
#include "commands.hpp"
#include "common_options.hpp"
#include "job_options.hpp"
#include "occlusion/app/config.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/region_growing_job.hpp"
#include "option_table.hpp"
#include "run_command.hpp"

namespace occlusion::cli {

namespace {

struct RegionGrowingCommand {
  RegionGrowingRequest request;
  OutputOptions output;
};

RegionGrowingCommand parse(const std::vector<std::string>& args) {
  RegionGrowingCommand command;
  RegionGrowingRequest& request = command.request;
  if (const auto config = config_path(args)) apply_config(load_config(*config), request);

  ViewpointOptions viewpoints;
  OptionTable table("-rgoc");
  add_output_options(table, command.output);
  add_viewpoint_options(table, viewpoints, /*allow_grid=*/true);
  add_seed_option(table, request.seed);
  add_threads_option(table, request.threads);
  add_estimation_options(table, request.estimation);
  table.value({"--samples-per-unit-area"}, [&](const std::string& option, const std::string& v) {
    request.samples_per_unit_area = parse_number(option, v);
  });
  table.value({"--octree-resolution"}, [&](const std::string& option, const std::string& v) {
    request.octree_resolution = parse_number(option, v);
  });
  table.value({"--enable-acceleration"}, [&](const std::string& option, const std::string& v) {
    request.enable_acceleration = parse_bool(option, v);
  });
  table.flag({"--skip-bad-lines"}, [&] { request.skip_bad_lines = true; });
  table.value({"--out"}, [&](const std::string&, const std::string& v) { request.out = v; });
  table.parse(args, single_input(request.path, "-rgoc"));
  viewpoints.apply_to(request.viewpoints);
  return command;
}

void print_help() {
  std::printf(
      "usage: occlusion -rgoc CLOUD [options]\n"
      "\n"
      "Region-growing mesh estimation and its occlusion: PCL normals and region growing\n"
      "split the cloud into smooth clusters; each becomes a RANSAC plane, the convex hull\n"
      "of its projected inliers, and a fan of triangles from the hull's centroid. The\n"
      "mesh's occlusion is then measured as -moc does, from viewpoints on the cloud's box.\n"
      "Clusters that give no polygon (lines, no plane, qhull failures) are skipped and\n"
      "reported.\n"
      "\n"
      "options (each is also a key of the config section occlusion.region_growing):\n"
      "  --config FILE                 JSON config; options on the command line override it\n"
      "  --pattern N                   viewpoint pattern 1..7 (default 7; see -moc --help)\n"
      "  --viewpoint X,Y,Z             explicit viewpoint (repeatable)\n"
      "  --num-vp N                    N viewpoints on a grid at mid-height\n"
      "region growing (defaults: the thesis' listing 4.7):\n"
      "  --normal-k K                  neighbours per normal (default 50)\n"
      "  --min-cluster-size N          smaller regions are dropped (default 100)\n"
      "  --max-cluster-size N          larger regions are dropped (default 100000; raise it\n"
      "                                for dense clouds, whose walls and floors are larger)\n"
      "  --neighbours N                neighbours region growing compares (default 40)\n"
      "  --smoothness-degrees A        largest angle between neighbouring normals (default 4)\n"
      "  --curvature-threshold C       points above it join regions but seed none (default 1)\n"
      "  --ransac-distance D           plane inlier distance in scene units (default 0.02)\n"
      "  --ransac-iterations N         RANSAC iterations at most (default 1000)\n"
      "  --recover-edges BOOL          planes take the unclustered points along their edges\n"
      "                                (default true; false: the thesis' method as is)\n"
      "mesh occlusion (as -moc):\n"
      "  --samples-per-unit-area X     samples per unit of area (default 100)\n"
      "  --octree-resolution X         smallest octree cell edge (default 0 = no limit)\n"
      "  --enable-acceleration BOOL    false: test every ray against every face\n"
      "  --seed N                      random seed of the samples (default 0)\n"
      "  --threads N                   worker threads (default 0 = all cores)\n"
      "  --skip-bad-lines              skip (and count) malformed lines of text inputs\n"
      "  --out DIR                     write CLOUD.rgoc.obj and CLOUD.rgoc.ply (the estimated\n"
      "                                mesh, group = cluster; the PLY with per-face\n"
      "                                visible_fraction), CLOUD.segmented.ply (every point\n"
      "                                with its `cluster`, -1 for none) and CLOUD.rgoc.json\n"
      "  --json                        print one JSON object on stdout (headline: "
      "occlusion_level)\n"
      "  -q, --quiet                   no progress on stderr\n");
}

void print_human(const RegionGrowingReport& report) {
  const MeshEstimate& e = report.estimate;
  const MeshOcclusionResult& r = report.occlusion;
  std::printf("region-growing occlusion of %s\n", report.request.path.c_str());
  std::printf("  occlusion level  %.4f   (visible area %.4g of %.4g)\n", r.occlusion_level,
              r.visible_area, r.total_area);
  std::printf("  points %zu, clusters found %zu, used %zu, skipped %zu\n", report.points,
              e.clusters_found, e.clusters_used, e.skipped.size());
  std::printf("  planes cover %.1f %% of the points (%zu edge points recovered)\n",
              100.0 * e.covered_fraction, e.edge_points);
  std::printf("  mesh: %zu faces, %zu samples, %zu rays\n", r.faces, r.samples, r.rays);
  for (std::size_t v = 0; v < r.viewpoints.size(); ++v) {
    const auto& vp = r.viewpoints[v];
    std::printf("    %-12s (%8.3f, %8.3f, %8.3f)  sees %.4f of the area\n",
                report.viewpoint_names[v].c_str(), vp.position.x(), vp.position.y(),
                vp.position.z(), vp.visible_fraction);
  }
  std::printf(
      "  time: load %.3f s, normals %.3f s, region growing %.3f s, planes %.3f s, hulls %.3f s,\n"
      "        occlusion %.3f s, total %.3f s\n",
      report.load_seconds, e.timings.normals_seconds, e.timings.region_growing_seconds,
      e.timings.planes_seconds, e.timings.hulls_seconds,
      r.timings.sampling_seconds + r.timings.build_seconds + r.timings.trace_seconds,
      report.total_seconds);
  for (const auto& path : report.outputs) std::printf("  wrote %s\n", path.c_str());
}

}  // namespace

int run_region_growing_command(const std::vector<std::string>& args) {
  const RegionGrowingCommand command = parse(args);
  return run_command<RegionGrowingReport>(
      command.output, "rgoc", print_help,
      [&](const Progress& progress) {
        return run_region_growing_occlusion(command.request, progress);
      },
      print_human);
}

}  // namespace occlusion::cli
