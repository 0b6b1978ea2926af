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
  if (report.candidate_source == "grid") {
    std::printf("  grid        spacing %.3g%s at height %.3g, clearance %.3g\n", report.spacing,
                q.spacing ? "" : " (auto)", q.height, q.clearance);
  }
  if (q.stations > 0) {
    std::printf("  question    the best %zu new station(s)\n", q.stations);
  } else {
    std::printf("  question    the fewest new stations for %.1f %%: ", 100.0 * q.target_coverage);
    if (s.target_reached) {
      std::printf("reached\n");
    } else if (s.share_stations > 0) {
      // What was asked, what can be reached, what was chosen, and the other choice.
      std::printf("NOT reachable: the candidates see %.1f %% at most\n",
                  100.0 * s.reachable_coverage);
      std::printf("  chosen      %s: aimed at %.1f %%%s\n", q.out_of_reach.c_str(),
                  100.0 * s.aimed_coverage,
                  q.out_of_reach == "most" ? " (all that can be reached)" : "");
      std::printf(
          "  the choice  all %.1f %% with %zu new station(s)%s; %.0f %% of it (%.1f %%) "
          "reached by the first %zu (at %.1f %%)%s\n",
          100.0 * s.reachable_coverage, s.most_stations,
          q.out_of_reach == "share" ? " (greedy from these on: --out-of-reach most)" : "",
          100.0 * q.target_coverage, 100.0 * q.target_coverage * s.reachable_coverage,
          s.share_stations, 100.0 * s.share_coverage,
          q.out_of_reach == "most" ? " (--out-of-reach share aims there instead)" : "");
    } else {
      std::printf("NOT reached (aimed at %.1f %%)\n", 100.0 * s.aimed_coverage);
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
  if (report.refinement) {
    const Refinement& r = *report.refinement;
    std::printf(
        "  refinement  %.4f -> %.4f, %zu of %zu new station(s) searched, %zu positions "
        "traced (budget %zu), %.3f s\n",
        r.coverage_before, r.coverage_after, report.refined_stations, r.stations.size(),
        r.positions_traced, report.refine_budget, report.refine_seconds);
    for (const RefinedStation& station : r.stations) {
      if (station.moves == 0) continue;
      const Eigen::Vector3d from = station.from + report.shift, to = station.to + report.shift;
      std::printf(
          "    moved     (%8.3f, %8.3f, %8.3f) -> (%8.3f, %8.3f, %8.3f), %.3f away: "
          "+%.4f -> +%.4f\n",
          from.x(), from.y(), from.z(), to.x(), to.y(), to.z(), (to - from).norm(),
          station.gain_before, station.gain_after);
    }
  }
  std::printf("  guarantee   %s\n", s.guarantee.c_str());
  std::printf(
      "  time: load %.3f s, candidates %.3f s, model %.3f s, coverage %.3f s, selection %.3f s, "
      "refinement %.3f s, total %.3f s\n",
      report.load_seconds, report.candidate_seconds, report.model_seconds, report.coverage_seconds,
      report.selection_seconds, report.refine_seconds, report.total_seconds);
  for (const auto& path : report.outputs) std::printf("  wrote %s\n", path.c_str());
}

}  // namespace

void print_plan(const JobRun& run, const FaceOptions&) {
  print_human(run.report_as<PlanReport>());
}

}  // namespace occlusion::cli
