#include <cstdio>

#include "arguments.hpp"
#include "commands.hpp"
#include "common_options.hpp"
#include "occlusion/app/config.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/mesh_occlusion_job.hpp"
#include "option_table.hpp"
#include "run_command.hpp"

namespace occlusion::cli {

namespace {

struct MeshOcclusionCommand {
  MeshOcclusionRequest request;
  OutputOptions output;
};

MeshOcclusionCommand parse(const std::vector<std::string>& args) {
  MeshOcclusionCommand command;
  MeshOcclusionRequest& request = command.request;
  if (const auto config = config_path(args)) apply_config(load_config(*config), request);

  ViewpointOptions viewpoints;
  OptionTable table("-moc");
  add_output_options(table, command.output);
  add_viewpoint_options(table, viewpoints, /*allow_grid=*/true);
  add_seed_option(table, request.seed);
  add_threads_option(table, request.threads);
  table.value({"--samples-per-unit-area"}, [&](const std::string& option, const std::string& v) {
    request.samples_per_unit_area = parse_number(option, v);
  });
  table.value({"--octree-resolution"}, [&](const std::string& option, const std::string& v) {
    request.octree_resolution = parse_number(option, v);
  });
  table.value({"--enable-acceleration"}, [&](const std::string& option, const std::string& v) {
    request.enable_acceleration = parse_bool(option, v);
  });
  table.value({"--out"}, [&](const std::string&, const std::string& v) { request.out = v; });
  table.parse(args, single_input(request.path, "-moc"));
  viewpoints.apply_to(request.viewpoints);
  return command;
}

void print_human(const MeshOcclusionReport& report) {
  const MeshOcclusionResult& r = report.result;
  std::printf("mesh occlusion of %s\n", report.request.path.c_str());
  std::printf("  occlusion level  %.4f   (visible area %.4g of %.4g)\n", r.occlusion_level,
              r.visible_area, r.total_area);
  std::printf("  faces %zu, samples %zu, rays %zu\n", r.faces, r.samples, r.rays);
  std::printf("  viewpoints:\n");
  for (std::size_t v = 0; v < r.viewpoints.size(); ++v) {
    const auto& vp = r.viewpoints[v];
    std::printf("    %-12s (%8.3f, %8.3f, %8.3f)  sees %.4f of the area\n",
                report.viewpoint_names[v].c_str(), vp.position.x(), vp.position.y(),
                vp.position.z(), vp.visible_fraction);
  }
  if (r.groups.size() > 1) {
    std::printf("  groups:%*s faces        area  occlusion\n", 22, "");
    for (const auto& g : r.groups) {
      std::printf("    %-24s %7zu %11.4g  %9.4f\n", g.name.c_str(), g.faces, g.total_area,
                  g.occlusion_level);
    }
  }
  std::printf("  time: load %.3f s, sampling %.3f s, octree %.3f s, tracing %.3f s, total %.3f s\n",
              report.load_seconds, r.timings.sampling_seconds, r.timings.build_seconds,
              r.timings.trace_seconds, report.total_seconds);
  for (const auto& path : report.outputs) std::printf("  wrote %s\n", path.c_str());
}

}  // namespace

static void print_mesh_occlusion_help() {
  std::printf(
      "usage: occlusion -moc MESH.obj|MESH.ply [options]\n"
      "\n"
      "Visible-area occlusion level of a triangle mesh: every face is sampled by area,\n"
      "a shadow ray goes from each sample to each viewpoint, and a sample is visible if\n"
      "any viewpoint sees it. occlusion_level = 1 - visible area / total area.\n"
      "\n"
      "options (each is also a key of the config section occlusion.mesh):\n"
      "  --config FILE                 JSON config; options on the command line override it\n"
      "  --pattern N                   viewpoint pattern 1..7 (default 7) on the bounding box:\n"
      "                                C = centre, U = midpoint centre-max, L = midpoint "
      "centre-min;\n"
      "                                1 C, 2 U, 3 L, 4 C+U, 5 C+L, 6 U+L, 7 C+U+L\n"
      "  --viewpoint X,Y,Z             explicit viewpoint (repeatable; instead of --pattern)\n"
      "  --num-vp N                    N viewpoints on a grid at mid-height (instead of "
      "--pattern)\n"
      "  --samples-per-unit-area X     samples per unit of area (default 100; every face gets\n"
      "                                at least one)\n"
      "  --octree-resolution X         smallest octree cell edge in scene units (default 0 = no "
      "limit)\n"
      "  --enable-acceleration BOOL    false: test every ray against every face (default true)\n"
      "  --seed N                      random seed (default 0); same seed, same result\n"
      "  --threads N                   worker threads (default 0 = all cores)\n"
      "  --out DIR                     write MESH.moc.json, MESH.moc.ply (per-face\n"
      "                                visible_fraction + colour) and MESH.moc.csv\n"
      "  --json                        print one JSON object on stdout (headline: "
      "occlusion_level)\n"
      "  -q, --quiet                   no progress on stderr\n");
}

int run_mesh_occlusion_command(const std::vector<std::string>& args) {
  const MeshOcclusionCommand command = parse(args);
  return run_command<MeshOcclusionReport>(
      command.output, "moc", print_mesh_occlusion_help,
      [&](const Progress& progress) { return run_mesh_occlusion(command.request, progress); },
      print_human);
}

}  // namespace occlusion::cli
