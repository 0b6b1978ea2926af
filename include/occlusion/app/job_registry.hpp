#pragma once
// Every job, once: its names on every face, its config section, its keys, and
// how to run it. The CLI's dispatch and --help, the config reader, the
// server's command table and `hello`, and the Python module iterate this
// registry; adding a job is one entry in job_registry.cpp.

#include <json/value.h>

#include <functional>
#include <memory>
#include <string>
#include <typeindex>
#include <vector>

#include "occlusion/app/key.hpp"
#include "occlusion/app/key_sources.hpp"
#include "occlusion/core/progress.hpp"

namespace occlusion {

// What a run gives back, whatever the job: its JSON report (with the headline
// figure), its warnings, and the typed report for faces that show more of it
// (per-element arrays): report_as<Report>().
struct JobRun {
  Json::Value json;
  std::vector<std::string> warnings;
  std::shared_ptr<const void> report;
  std::type_index type = typeid(void);

  template <class Report>
  const Report& report_as() const {
    if (type != typeid(Report)) throw std::logic_error("JobRun holds another report type");
    return *static_cast<const Report*>(report.get());
  }
};

struct JobInfo {
  std::string name;                    // "cloud_occlusion": server command, report "job"
  std::vector<std::string> cli_names;  // {"-poc", "cloud-occlusion"}
  std::string section;                 // config section: "point_cloud"
  std::string tag;                     // progress lines and output suffixes: "poc"
  std::string positional;              // the key the command line's bare arguments fill
  std::string synopsis;                // "CLOUD [options]"
  std::string summary;                 // one line for `occlusion --help`
  std::string description;             // the command's --help, before its options
  std::vector<KeyInfo> keys;
  // Fills a default request from `sources` in order, checks it, runs it.
  // KeyErrors come back re-spelled as the user wrote the key.
  std::function<JobRun(const std::vector<KeySource>&, const Progress&)> run;
};

const std::vector<JobInfo>& jobs();
// By name ("cloud_occlusion") or command-line name ("-poc", "cloud-occlusion").
const JobInfo* find_job(const std::string& name);
// The job whose config section is `section`.
const JobInfo* find_job_by_section(const std::string& section);

// The command's `--help` text: usage, description, then one line per key.
std::string job_help(const JobInfo& job);
// Every job's keys as Markdown tables (docs/options.md is this text).
std::string keys_markdown();

// For registry entries: the typed runner of one job.
template <class Request, class Report>
std::function<JobRun(const std::vector<KeySource>&, const Progress&)> job_runner(
    const Keys<Request>& (*keys)(), Report (*run)(const Request&, const Progress&)) {
  return [keys, run](const std::vector<KeySource>& sources, const Progress& progress) {
    Request request;
    try {
      apply_sources(keys(), sources, request);
      auto report = std::make_shared<Report>(run(request, progress));
      JobRun result;
      result.json = to_json(*report);
      result.warnings = report->warnings;
      result.type = typeid(Report);
      result.report = std::move(report);
      return result;
    } catch (const KeyError& e) {
      throw respelled(e, sources, key_infos(keys()));
    }
  };
}

}  // namespace occlusion
