#include <cstdio>
#include <string>

#include "arguments.hpp"
#include "commands.hpp"
#include "common_options.hpp"
#include "interrupt.hpp"
#include "job_options.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/study_job.hpp"
#include "option_table.hpp"
#include "run_command.hpp"

namespace occlusion::cli {

namespace {

struct StudyCommand {
  StudyRequest request;
  OutputOptions output;
};

StudyCommand parse(const std::vector<std::string>& args) {
  StudyCommand command;
  StudyRequest& request = command.request;
  if (const auto config = config_path(args)) apply_config(load_config(*config), request);

  OptionTable table("study");
  add_output_options(table, command.output);
  add_tracing_options(table, request.tracing);
  add_estimation_options(table, request.estimation);
  bool scenes_given = false;
  table.value({"--scene"}, [&](const std::string&, const std::string& v) {
    add_to_list(request.scenes, scenes_given, v);
  });
  bool patterns_given = false;
  table.value({"--pattern"}, [&](const std::string& option, const std::string& v) {
    const auto pattern = parse_unsigned(option, v);
    if (!patterns_given) request.configurations.clear();
    patterns_given = true;
    request.configurations.push_back(
        {"pattern_" + v,
         ViewpointChoice::from_pattern(static_cast<int>(std::min<std::uint64_t>(pattern, 1000)))});
  });
  table.value({"--self-tolerance"}, [&](const std::string& option, const std::string& v) {
    request.self_tolerance = parse_number(option, v);
  });
  table.value({"--format"}, [&](const std::string&, const std::string& v) { request.format = v; });
  table.value({"--occlusion-num-vp"}, [&](const std::string& option, const std::string& v) {
    const auto count = parse_unsigned(option, v);
    if (count > 10000) throw UsageError("--occlusion-num-vp must be at most 10000");
    request.occlusion_num_vp = static_cast<unsigned>(count);
  });
  table.value({"--segmenter"},
              [&](const std::string&, const std::string& v) { request.segmenter = v; });
  table.value({"--segmenter-output"},
              [&](const std::string&, const std::string& v) { request.segmenter_output = v; });
  table.value({"--mapping-path", "--mapping"},
              [&](const std::string&, const std::string& v) { request.mapping_path = v; });
  table.value({"--ignored-classes"}, [&](const std::string&, const std::string& v) {
    request.ignored_classes = split_list(v);
  });
  table.value({"--max-distance"}, [&](const std::string& option, const std::string& v) {
    request.max_distance = parse_number(option, v);
  });
  table.value({"--shard"}, [&](const std::string&, const std::string& v) { request.shard = v; });
  table.value({"--out"}, [&](const std::string&, const std::string& v) { request.out = v; });
  table.parse(args, [](const std::string& v) {
    throw UsageError(
        "unexpected argument '" + v +
        "': the study's scenes come from --scene or the config (occlusion.study.scenes)");
  });
  return command;
}

void print_help() {
  std::printf(
      "usage: occlusion study --config study.json [options]\n"
      "       occlusion study merge OUT A.csv B.csv ...\n"
      "\n"
      "How much does occlusion hurt semantic segmentation? For each labelled scene x viewpoint\n"
      "configuration (a run): scan the scene from the configuration's viewpoints (-fscan),\n"
      "measure the scanned cloud's occlusion (-poc and its exterior variant), segment it,\n"
      "and score the segmentation against the scanned cloud's labels (-eval). One row per\n"
      "run goes to OUT/study.csv; OUT/study.md and OUT/study.svg correlate each occlusion\n"
      "measure with mIoU. Runs already in study.csv are skipped, so a study resumes.\n"
      "'study merge' joins the CSVs of shards into OUT. docs/study.md has the details.\n"
      "\n"
      "options (each is also a key of the config section occlusion.study, which also\n"
      "holds the configurations: [{\"name\": ..., \"pattern\" | \"num_vp\" | \"viewpoints\": "
      "...}]):\n"
      "  --config FILE                JSON config; options on the command line override it\n"
      "  --scene PATH                 a labelled scene (repeatable; replaces the config's)\n"
      "  --pattern N                  a configuration 'pattern_N' (repeatable; replaces the\n"
      "                               config's configurations)\n"
      "  --segmenter CMD              'baseline' (default: a geometric baseline on the\n"
      "                               region-growing planes, not a network) or a command with\n"
      "                               {input} (the scanned cloud) and {output} (its prediction:\n"
      "                               evaluation ids, as -eval reads them), e.g.\n"
      "                               'python infer.py {input} {output}'\n"
      "  --segmenter-output EXT       extension of {output}: labels (default), ply, pcd, txt\n"
      "                               A run whose segmenter fails (exit status, timeout, a\n"
      "                               prediction that cannot be read) is a 'failed' row; the\n"
      "                               study goes on, exits 1 at the end, and a resume retries\n"
      "                               it. Resuming with other parameters is an error naming\n"
      "                               them (study.parameters.json records them).\n"
      "  --format ply|pcd             format of the scanned clouds in OUT/runs (default ply)\n"
      "  --shard I/N                  make only the runs k with k mod N = I (default 0/1)\n"
      "  --out DIR                    study.csv, study.md, study.svg, study.json, runs/\n"
      "scan and occlusion (as -fscan and -poc; the exterior variant is on by default):\n"
      "  --point-radius R  --self-tolerance D  --num-rays-per-vp N  --polygon-path FILE\n"
      "  --sampling uniform|fibonacci  --light-radius R  --exterior-classes A,B,...\n"
      "  --octree-resolution X  --enable-acceleration BOOL  --seed N  --threads N\n"
      "  --skip-bad-lines\n"
      "  --occlusion-num-vp N         measure occlusion from N grid viewpoints (the same for\n"
      "                               every configuration) instead of the configuration's own\n"
      "scoring (as -eval):\n"
      "  --mapping-path FILE  --ignored-classes A,B,...  --max-distance D\n"
      "the baseline's region growing (as -rgoc; max cluster size unlimited by default):\n"
      "  --normal-k K  --min-cluster-size N  --max-cluster-size N  --neighbours N\n"
      "  --smoothness-degrees A  --curvature-threshold C  --ransac-distance D\n"
      "  --ransac-iterations N  --recover-edges BOOL\n"
      "output:\n"
      "  --json                       print one JSON object (headline: correlations)\n"
      "  -q, --quiet                  no progress on stderr\n");
}

std::string figure(const std::optional<double>& value) {
  return optional_figure(value, "%+.3f", "     -");
}

void print_human(const StudyReport& report) {
  if (report.job == "study") {
    std::printf(
        "occlusion study: %zu runs made, %zu already in study.csv (shard %s of %zu runs), %zu "
        "failed\n",
        report.runs_computed, report.runs_skipped, report.request.shard.c_str(), report.runs_total,
        report.runs_failed);
  } else {
    std::printf("occlusion study: %zu runs merged from %zu CSV files\n", report.table.rows.size(),
                report.inputs.size());
  }
  std::printf("  correlation with mIoU over %zu runs:\n", report.table.rows.size());
  for (const auto& m : report.correlations) {
    std::printf("    %-26s n %3zu   Pearson %s   Spearman %s\n", m.measure.c_str(), m.correlation.n,
                figure(m.correlation.pearson).c_str(), figure(m.correlation.spearman).c_str());
  }
  std::printf("  time %.3f s\n", report.total_seconds);
  for (const auto& path : report.outputs) std::printf("  wrote %s\n", path.c_str());
}

// The study goes on past a failed run, but must not look like a success.
int failed_status(int status, std::size_t failed) {
  if (status != 0 || failed == 0) return status;
  std::fprintf(stderr, "occlusion: %zu runs failed (status 'failed' in study.csv)\n", failed);
  return 1;
}

int run_merge(const std::vector<std::string>& args) {
  OutputOptions output;
  OptionTable table("study merge");
  table.flag({"--json"}, [&output] { output.json = true; });
  table.flag({"-q", "--quiet"}, [&output] { output.quiet = true; });
  table.flag({"-h", "--help"}, [&output] { output.help = true; });
  std::vector<std::string> positional;
  table.parse(args, [&](const std::string& v) { positional.push_back(v); });
  if (!output.help && positional.size() < 2) {
    throw UsageError("usage: occlusion study merge OUT A.csv [B.csv ...]");
  }
  std::size_t failed = 0;
  const int status = run_command<StudyReport>(
      output, "study", print_help,
      [&](const Progress&) {
        StudyReport report =
            run_study_merge({positional.begin() + 1, positional.end()}, positional.front());
        failed = report.runs_failed;
        return report;
      },
      print_human);
  return failed_status(status, failed);
}

}  // namespace

int run_study_command(const std::vector<std::string>& args) {
  if (!args.empty() && args.front() == "merge") return run_merge({args.begin() + 1, args.end()});
  const StudyCommand command = parse(args);
  std::size_t failed = 0;
  const int status = run_command<StudyReport>(
      command.output, "study", print_help,
      [&](const Progress& progress) {
        Progress interruptible = progress;
        interruptible.cancel = cancel_on_interrupt();
        StudyReport report = run_study(command.request, interruptible);
        failed = report.runs_failed;
        return report;
      },
      print_human);
  return failed_status(status, failed);
}

}  // namespace occlusion::cli
