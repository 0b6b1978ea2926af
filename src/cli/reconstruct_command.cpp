#include <cstdio>

#include "commands.hpp"
#include "common_options.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/reconstruct_job.hpp"
#include "option_table.hpp"
#include "run_command.hpp"

namespace occlusion::cli {

namespace {

struct ReconstructCommand {
  ReconstructRequest request;
  OutputOptions output;
};

ReconstructCommand parse(const std::vector<std::string>& args) {
  ReconstructCommand command;
  ReconstructRequest& request = command.request;
  if (const auto config = config_path(args)) apply_config(load_config(*config), request);

  OptionTable table("-recon");
  add_output_options(table, command.output);
  table.value({"--format"}, [&](const std::string&, const std::string& v) { request.format = v; });
  table.flag({"--skip-bad-lines"}, [&] { request.skip_bad_lines = true; });
  table.value({"--out"}, [&](const std::string&, const std::string& v) { request.out = v; });
  table.parse(args, single_input(request.path, "-recon"));
  return command;
}

void print_help() {
  std::printf(
      "usage: occlusion -recon FOLDER [options]\n"
      "\n"
      "Reconstruct an S3DIS room folder (<room>/Annotations/<class>_<k>.txt) or a whole\n"
      "Area_N folder into one labelled cloud: semantic ids of the 13 S3DIS classes\n"
      "(ceiling 0, floor 1, wall 2, beam 3, column 4, window 5, door 6, table 7, chair 8,\n"
      "sofa 9, bookcase 10, board 11, clutter 12; 'stairs' counts as clutter) and\n"
      "instance ids, plus a JSON summary of points per class.\n"
      "\n"
      "options (each is also a key of the config section occlusion.reconstruct):\n"
      "  --config FILE        JSON config; options on the command line override it\n"
      "  --format ply|pcd     output format (default ply)\n"
      "  --skip-bad-lines     skip (and count) malformed lines, as found in real S3DIS files\n"
      "  --out DIR            write FOLDER.FMT and FOLDER.recon.json there (default .)\n"
      "  --json               print the summary as one JSON object\n"
      "  -q, --quiet          no progress on stderr\n");
}

void print_human(const ReconstructReport& report) {
  std::printf("reconstructed %s: %zu points in %zu room(s)\n", report.request.path.c_str(),
              report.points, report.rooms.size());
  for (const auto& c : report.classes) {
    if (c.points == 0) continue;
    std::printf("  %-10s %9zu points  %4zu instances\n", c.name.c_str(), c.points, c.instances);
  }
  if (report.skipped_lines > 0) std::printf("  skipped %zu bad lines\n", report.skipped_lines);
  for (const auto& path : report.outputs) std::printf("  wrote %s\n", path.c_str());
}

}  // namespace

int run_reconstruct_command(const std::vector<std::string>& args) {
  const ReconstructCommand command = parse(args);
  return run_command<ReconstructReport>(
      command.output, "recon", print_help,
      [&](const Progress& progress) { return run_reconstruct(command.request, progress); },
      print_human);
}

}  // namespace occlusion::cli
