// One command-line command per job of the registry: its options are the
// job's declared keys (app/key_sources parses them), plus the command line's
// own --config, --json, --quiet and --help.

#include <cstdio>
#include <map>

#include "commands.hpp"
#include "common_options.hpp"
#include "interrupt.hpp"
#include "occlusion/app/config.hpp"
#include "occlusion/app/errors.hpp"
#include "progress_printer.hpp"

namespace occlusion::cli {

namespace {

// What the command line adds to each job: how its report reads to a person,
// whether a completed run can still end with failures (the study's failed
// runs), and whether it takes --confusion.
struct JobFace {
  void (*print)(const JobRun&, const FaceOptions&);
  int (*exit_status)(const JobRun&) = nullptr;
  bool takes_confusion = false;
};

const std::map<std::string, JobFace>& job_faces() {
  static const std::map<std::string, JobFace> table = {
      {"mesh_occlusion", {&print_mesh_occlusion}},
      {"cloud_occlusion", {&print_cloud_occlusion}},
      {"region_growing_occlusion", {&print_region_growing}},
      {"scan", {&print_scan}},
      {"reconstruct", {&print_reconstruct}},
      {"evaluate", {&print_evaluate, nullptr, true}},
      {"extract_polygons", {&print_extract_polygons}},
      {"study", {&print_study, &study_exit_status}},
      {"plan", {&print_plan}},
      {"simulate", {&print_simulate}},
      {"register", {&print_register}},
  };
  return table;
}

// Takes the command line's own options out of `args`; the rest are the job's.
std::vector<std::string> take_face_options(const std::vector<std::string>& args, const JobInfo& job,
                                           FaceOptions& face) {
  std::vector<std::string> rest;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg == "--json") {
      face.json = true;
    } else if (arg == "-q" || arg == "--quiet") {
      face.quiet = true;
    } else if (arg == "-h" || arg == "--help") {
      face.help = true;
    } else if (arg == "--confusion" && job_faces().at(job.name).takes_confusion) {
      face.confusion = true;
    } else if (arg == "--config" || arg.rfind("--config=", 0) == 0) {
      if (!face.config.empty()) throw UsageError("--config given twice");
      if (arg != "--config") {
        face.config = arg.substr(9);
      } else if (i + 1 < args.size()) {
        face.config = args[++i];
      } else {
        throw UsageError("--config needs a value");
      }
    } else {
      rest.push_back(arg);
    }
  }
  return rest;
}

}  // namespace

int run_job_command(const JobInfo& job, const std::vector<std::string>& args) {
  FaceOptions face;
  const std::vector<std::string> job_args = take_face_options(args, job, face);
  if (face.help) {
    std::printf("%s", job_help(job).c_str());
    if (job_faces().at(job.name).takes_confusion) {
      std::printf(
          "  --confusion                 print the confusion matrix (the JSON always has it)\n");
    }
    return 0;
  }
  std::vector<KeySource> sources;
  if (!face.config.empty()) sources.push_back(config_source(load_config(face.config), job));
  sources.push_back(
      source_from_arguments(job_args, job.keys, job.cli_names.front(), job.positional));
  Progress progress = make_progress_printer(job.tag, face.quiet);
  progress.cancel = &interrupt_flag();
  const JobRun run = job.run(sources, progress);
  print_warnings(run.warnings);
  if (face.json) {
    print_json(run.json);
  } else {
    job_faces().at(job.name).print(run, face);
  }
  const JobFace& job_face = job_faces().at(job.name);
  return job_face.exit_status != nullptr ? job_face.exit_status(run) : 0;
}

}  // namespace occlusion::cli
