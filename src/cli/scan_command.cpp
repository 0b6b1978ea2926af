#include <cstdio>

#include "arguments.hpp"
#include "commands.hpp"
#include "common_options.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/scan_job.hpp"
#include "option_table.hpp"
#include "run_command.hpp"

namespace occlusion::cli {

namespace {

struct ScanCommand {
  ScanRequest request;
  OutputOptions output;
};

ScanCommand parse(const std::vector<std::string>& args) {
  ScanCommand command;
  ScanRequest& request = command.request;
  if (const auto config = config_path(args)) apply_config(load_config(*config), request);

  ViewpointOptions viewpoints;
  OptionTable table("-fscan");
  add_output_options(table, command.output);
  add_viewpoint_options(table, viewpoints, /*allow_grid=*/true);
  add_threads_option(table, request.threads);
  table.value({"--point-radius"}, [&](const std::string& option, const std::string& v) {
    request.point_radius = parse_number(option, v);
  });
  table.value({"--self-tolerance"}, [&](const std::string& option, const std::string& v) {
    request.self_tolerance = parse_number(option, v);
  });
  table.value({"--octree-resolution"}, [&](const std::string& option, const std::string& v) {
    request.octree_resolution = parse_number(option, v);
  });
  table.value({"--enable-acceleration"}, [&](const std::string& option, const std::string& v) {
    request.enable_acceleration = parse_bool(option, v);
  });
  table.value({"--format"}, [&](const std::string&, const std::string& v) { request.format = v; });
  table.flag({"--skip-bad-lines"}, [&] { request.skip_bad_lines = true; });
  table.value({"--out"}, [&](const std::string&, const std::string& v) { request.out = v; });
  table.parse(args, single_input(request.path, "-fscan"));
  viewpoints.apply_to(request.viewpoints);
  return command;
}

void print_help() {
  std::printf(
      "usage: occlusion -fscan CLOUD [options]\n"
      "\n"
      "Fixed-viewpoint scan: keep the points of a full cloud that the viewpoints really\n"
      "see. Point P is seen from viewpoint V if the segment V-P meets no other point's\n"
      "sphere (--point-radius), ignoring hits within --self-tolerance of P (its neighbours\n"
      "on the same surface) and within --point-radius of V.\n"
      "\n"
      "options (each is also a key of the config section occlusion.point_cloud):\n"
      "  --config FILE                JSON config; options on the command line override it\n"
      "  --pattern N                  viewpoint pattern 1..7 (default 7; see -moc --help)\n"
      "  --viewpoint X,Y,Z            explicit viewpoint (repeatable)\n"
      "  --num-vp N                   N viewpoints on a grid at mid-height\n"
      "  --point-radius R             sphere radius of each point (default 0.01)\n"
      "  --self-tolerance D           default 2 x point radius\n"
      "  --octree-resolution X        smallest octree cell edge (default 0 = no limit)\n"
      "  --enable-acceleration BOOL   false: test every ray against every point\n"
      "  --format ply|pcd             format of the written clouds (default ply)\n"
      "  --skip-bad-lines             skip (and count) malformed lines of text inputs\n"
      "  --threads N                  worker threads (default 0 = all cores)\n"
      "  --out DIR                    write CLOUD.scan.FMT (the seen points, all attributes),\n"
      "                               CLOUD.scan_full.FMT (every point + visible_count) and\n"
      "                               CLOUD.fscan.json\n"
      "  --json                       print one JSON object (headline: visible_fraction)\n"
      "  -q, --quiet                  no progress on stderr\n");
}

void print_human(const ScanReport& report) {
  const ScanResult& r = report.result;
  std::printf("fixed-viewpoint scan of %s\n", report.request.path.c_str());
  std::printf("  visible fraction  %.4f   (%zu of %zu points)\n", r.visible_fraction,
              r.visible_points, r.visible_count.size());
  for (std::size_t v = 0; v < report.viewpoint_positions.size(); ++v) {
    const auto& p = report.viewpoint_positions[v];
    std::printf("    %-12s (%8.3f, %8.3f, %8.3f)  sees %zu points\n",
                report.viewpoint_names[v].c_str(), p.x(), p.y(), p.z(), r.seen_by_viewpoint[v]);
  }
  if (!report.classes.empty()) {
    std::printf("  classes:%*s points   visible\n", 16, "");
    for (const auto& c : report.classes) {
      if (c.points == 0) continue;
      std::printf("    %-20s %9zu   %.4f\n", c.name.c_str(), c.points, c.visible_fraction);
    }
  }
  std::printf("  time: load %.3f s, octree %.3f s, tracing %.3f s, total %.3f s\n",
              report.load_seconds, r.build_seconds, r.trace_seconds, report.total_seconds);
  for (const auto& path : report.outputs) std::printf("  wrote %s\n", path.c_str());
}

}  // namespace

int run_scan_command(const std::vector<std::string>& args) {
  const ScanCommand command = parse(args);
  return run_command<ScanReport>(
      command.output, "fscan", print_help,
      [&](const Progress& progress) { return run_scan(command.request, progress); }, print_human);
}

}  // namespace occlusion::cli
