#pragma once
// The command line: every job of the registry is one command, parsed from its
// key declarations (job_command.cpp); what stays per job here is how its
// report reads to a person.

#include <string>
#include <vector>

#include "occlusion/app/job_registry.hpp"

namespace occlusion::cli {

// The command line's own options, beside the job's keys.
struct FaceOptions {
  bool json = false;
  bool quiet = false;
  bool help = false;
  bool confusion = false;  // -eval: print the confusion matrix
  std::string config;      // --config FILE
};

// Each returns the process exit code; errors propagate as exceptions that
// main() maps to exit codes.
int run_job_command(const JobInfo& job, const std::vector<std::string>& args);
int run_study_merge_command(const std::vector<std::string>& args);
int run_serve_command(const std::vector<std::string>& args);

// The human summary of each job's report (stdout without --json).
void print_mesh_occlusion(const JobRun& run, const FaceOptions& face);
void print_cloud_occlusion(const JobRun& run, const FaceOptions& face);
void print_region_growing(const JobRun& run, const FaceOptions& face);
void print_scan(const JobRun& run, const FaceOptions& face);
void print_reconstruct(const JobRun& run, const FaceOptions& face);
void print_evaluate(const JobRun& run, const FaceOptions& face);
void print_extract_polygons(const JobRun& run, const FaceOptions& face);
void print_study(const JobRun& run, const FaceOptions& face);
void print_plan(const JobRun& run, const FaceOptions& face);
void print_simulate(const JobRun& run, const FaceOptions& face);
void print_register(const JobRun& run, const FaceOptions& face);

// A job that completes with some parts failed (the study's failed runs) exits 1.
int study_exit_status(const JobRun& run);

}  // namespace occlusion::cli
