#include <cstdio>
#include <iostream>

#include "arguments.hpp"
#include "commands.hpp"
#include "occlusion/analysis/viewpoints.hpp"
#include "occlusion/app/config.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/json_output.hpp"
#include "occlusion/app/mesh_occlusion_job.hpp"
#include "progress_printer.hpp"

namespace occlusion::cli {

namespace {

struct MeshOcclusionCommand {
  MeshOcclusionRequest request;
  bool json = false;
  bool quiet = false;
  bool help = false;
};

MeshOcclusionCommand parse(const std::vector<std::string>& raw) {
  MeshOcclusionCommand command;
  // The config is applied first so that every other option overrides it,
  // wherever it stands on the line.
  for (std::size_t i = 0; i < raw.size(); ++i) {
    if (raw[i] == "--config") {
      if (i + 1 >= raw.size()) throw UsageError("--config needs a value");
      apply_mesh_config(load_config(raw[i + 1]), command.request);
    }
  }
  Arguments args(raw);
  bool pattern_given = false;
  bool path_given = false;
  std::vector<Eigen::Vector3d> viewpoints;
  while (!args.done()) {
    const std::string arg = args.take();
    if (arg == "--config") {
      args.take();
    } else if (arg == "-h" || arg == "--help") {
      command.help = true;
    } else if (arg == "--json") {
      command.json = true;
    } else if (arg == "--quiet" || arg == "-q") {
      command.quiet = true;
    } else if (arg == "--pattern") {
      const auto pattern = parse_unsigned(arg, args.value_of(arg));
      if (pattern < kMinPattern || pattern > kMaxPattern) {
        throw UsageError("--pattern must be 1..7, got " + std::to_string(pattern));
      }
      command.request.pattern = static_cast<int>(pattern);
      pattern_given = true;
    } else if (arg == "--viewpoint") {
      viewpoints.push_back(parse_point(arg, args.value_of(arg)));
    } else if (arg == "--samples-per-unit-area") {
      command.request.samples_per_unit_area = parse_number(arg, args.value_of(arg));
    } else if (arg == "--octree-resolution") {
      command.request.octree_resolution = parse_number(arg, args.value_of(arg));
    } else if (arg == "--enable-acceleration") {
      command.request.enable_acceleration = parse_bool(arg, args.value_of(arg));
    } else if (arg == "--seed") {
      command.request.seed = parse_unsigned(arg, args.value_of(arg));
    } else if (arg == "--threads") {
      const auto threads = parse_unsigned(arg, args.value_of(arg));
      if (threads > 1024) throw UsageError("--threads must be at most 1024");
      command.request.threads = static_cast<unsigned>(threads);
    } else if (arg == "--out") {
      command.request.out = args.value_of(arg);
    } else if (!arg.empty() && arg[0] == '-') {
      throw UsageError("unknown option '" + arg + "' for -moc (see occlusion -moc --help)");
    } else if (!path_given) {
      command.request.path = arg;  // overrides the config's path
      path_given = true;
    } else {
      throw UsageError("unexpected argument '" + arg + "': -moc takes one mesh");
    }
  }
  if (pattern_given && !viewpoints.empty()) {
    throw UsageError("give either --pattern or --viewpoint, not both");
  }
  if (pattern_given) command.request.viewpoints.clear();
  if (!viewpoints.empty()) command.request.viewpoints = viewpoints;
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

void print_mesh_occlusion_help() {
  std::printf(
      "usage: occlusion -moc MESH.obj [options]\n"
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
  if (command.help) {
    print_mesh_occlusion_help();
    return 0;
  }
  const MeshOcclusionReport report =
      run_mesh_occlusion(command.request, make_progress_printer("moc", command.quiet));
  for (const auto& warning : report.warnings) {
    std::fprintf(stderr, "occlusion: warning: %s\n", warning.c_str());
  }
  if (command.json) {
    std::cout << format_json(to_json(report)) << std::endl;
  } else {
    print_human(report);
  }
  return 0;
}

}  // namespace occlusion::cli
