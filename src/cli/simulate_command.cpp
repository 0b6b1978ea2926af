#include <cstdio>

#include "commands.hpp"
#include "occlusion/app/job_registry.hpp"
#include "occlusion/app/simulate_job.hpp"

namespace occlusion::cli {

namespace {

// "N points of M beams (no return a, out of range b, beyond max incidence c)":
// the four counts add up to the beams.
void print_counts(const char* indent, const BeamCounts& c) {
  std::printf(
      "%s%zu points of %zu beams (no return %zu, out of range %zu, beyond max incidence "
      "%zu)\n",
      indent, c.returns, c.beams, c.no_hit, c.out_of_range, c.grazing);
}

void print_human(const SimulateReport& report) {
  const SimulatedScan& scan = report.scan;
  std::printf("simulated %s scan of %s\n", report.request.sensor.c_str(),
              report.request.path.c_str());
  print_counts("  ", scan.counts);
  std::printf("  stations (%s):\n", report.station_source.c_str());
  for (std::size_t s = 0; s < report.stations.size(); ++s) {
    const auto& p = report.stations[s].position;
    std::printf("    %-12s (%8.3f, %8.3f, %8.3f)  ", report.stations[s].name.c_str(), p.x(), p.y(),
                p.z());
    print_counts("", scan.per_station[s]);
  }
  std::printf("  time: load %.3f s, octree %.3f s, scanning %.3f s, total %.3f s\n",
              report.load_seconds, scan.build_seconds, scan.trace_seconds, report.total_seconds);
  for (const auto& path : report.outputs) std::printf("  wrote %s\n", path.c_str());
}

}  // namespace

void print_simulate(const JobRun& run, const FaceOptions&) {
  print_human(run.report_as<SimulateReport>());
}

}  // namespace occlusion::cli
