#include <cstdio>

#include "commands.hpp"
#include "occlusion/app/job_registry.hpp"
#include "occlusion/app/register_job.hpp"

namespace occlusion::cli {

namespace {

void print_fit(const char* when, const RegistrationFit& fit, double distance) {
  std::printf(
      "  %-7s RMS %.4g, overlap %.1f %% (%zu source points with a target point within %.3g)\n",
      when, fit.rms, 100.0 * fit.overlap, fit.matched, distance);
}

void print_pose(const char* name, const Eigen::Isometry3d& pose) {
  const Eigen::AngleAxisd rotation(pose.linear());
  const Eigen::Vector3d t = pose.translation();
  std::printf(
      "  %-7s translation (%.6g, %.6g, %.6g), rotation %.6g degrees about (%.4f, %.4f, %.4f)\n",
      name, t.x(), t.y(), t.z(), rotation_degrees(pose), rotation.axis().x(), rotation.axis().y(),
      rotation.axis().z());
}

}  // namespace

void print_register(const JobRun& run, const FaceOptions&) {
  const RegisterReport& report = run.report_as<RegisterReport>();
  const RegistrationResult& r = report.result;
  if (!report.project_scans.empty()) {
    std::printf("registered the scans of %s onto its first scan (%zu points), %s\n",
                report.request.path.c_str(), report.target_points, report.request.method.c_str());
    for (const ProjectScanRegistration& scan : report.project_scans) {
      std::printf(
          "  %s (%zu points): moved %.4g, %.4g degrees; RMS %.4g -> %.4g, overlap %.1f %% -> "
          "%.1f %%\n",
          scan.path.c_str(), scan.points, scan.result.moved_translation,
          scan.result.moved_rotation_deg, scan.result.before.rms, scan.result.after.rms,
          100.0 * scan.result.before.overlap, 100.0 * scan.result.after.overlap);
      print_pose("refined", scan.result.refined);
    }
    for (const auto& path : report.outputs) std::printf("  wrote %s\n", path.c_str());
    return;
  }
  std::printf("registered %s (%zu points) onto %s (%zu points), %s\n", report.request.path.c_str(),
              report.source_points, report.request.target.c_str(), report.target_points,
              report.request.method.c_str());
  print_pose("initial", r.initial);
  print_pose("refined", r.refined);
  std::printf("  moved   %.4g (translation), %.4g degrees\n", r.moved_translation,
              r.moved_rotation_deg);
  print_fit("before", r.before, r.evaluation_distance);
  print_fit("after", r.after, r.evaluation_distance);
  for (std::size_t l = 0; l < r.levels.size(); ++l) {
    const RegistrationLevel& level = r.levels[l];
    std::printf("  level %zu: voxel %.3g, search %.3g, %zu / %zu points, %u iterations%s\n", l + 1,
                level.voxel, level.search_distance, level.source_points, level.target_points,
                level.iterations, level.converged ? ", converged" : "");
  }
  std::printf("  time: load %.3f s, registration %.3f s, total %.3f s\n", report.load_seconds,
              r.seconds, report.total_seconds);
  for (const auto& path : report.outputs) std::printf("  wrote %s\n", path.c_str());
}

}  // namespace occlusion::cli
