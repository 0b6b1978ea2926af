#include <cstdio>

#include "commands.hpp"
#include "occlusion/app/job_registry.hpp"
#include "occlusion/app/plan_job.hpp"

namespace occlusion::cli {

namespace {

void print_human(const PlanReport& report) {
  const StationSelection& s = report.selection;
  const PlanRequest& q = report.request;
  std::printf("scan plan of %s (%zu %s)\n", q.path.c_str(), report.target_count,
              report.targets.c_str());
  const CandidateRejections& no = report.candidates.rejected;
  std::printf(
      "  candidates  %zu kept of %zu (%s; %zu too near, %zu inside solids, %zu outside), %zu "
      "placed\n",
      report.candidates.positions.size(), report.candidates.tested, report.candidate_source.c_str(),
      no.clearance, no.inside_solid, no.outside, report.placed.size());
  if (q.stations > 0) {
    std::printf("  question    the best %zu new station(s)\n", q.stations);
  } else {
    std::printf("  question    the fewest new stations for %.1f %%: ", 100.0 * q.target_coverage);
    if (s.target_reached) {
      std::printf("reached\n");
    } else {
      std::printf("NOT reachable (the candidates see %.1f %% at most; aimed at %.1f %%)\n",
                  100.0 * s.reachable_coverage, 100.0 * s.aimed_coverage);
    }
  }
  std::printf("  coverage    %.4f   (greedy %.4f with %zu station(s), %zu improvement move(s))\n",
              s.coverage, s.greedy_coverage, s.greedy.size(), s.improvement_moves);
  for (std::size_t r = 0; r < s.stations.size(); ++r) {
    const SelectedStation& station = s.stations[r];
    const Eigen::Vector3d& p = report.candidate_positions.at(station.candidate);
    const std::string& name = report.candidate_names.at(station.candidate);
    std::printf("    %2zu %-10s (%8.3f, %8.3f, %8.3f)  +%.4f -> %.4f%s\n", r + 1,
                name.empty() ? ("S" + std::to_string(r + 1)).c_str() : name.c_str(), p.x(), p.y(),
                p.z(), station.gain, station.coverage, station.existing ? "  (placed)" : "");
  }
  std::printf("  guarantee   %s\n", s.guarantee.c_str());
  std::printf(
      "  time: load %.3f s, candidates %.3f s, model %.3f s, coverage %.3f s, selection %.3f s, "
      "total %.3f s\n",
      report.load_seconds, report.candidate_seconds, report.model_seconds, report.coverage_seconds,
      report.selection_seconds, report.total_seconds);
  for (const auto& path : report.outputs) std::printf("  wrote %s\n", path.c_str());
}

}  // namespace

void print_plan(const JobRun& run, const FaceOptions&) {
  print_human(run.report_as<PlanReport>());
}

}  // namespace occlusion::cli
