// bench_poc [--points N] [--triangles N] [--rays-per-vp N] [--num-vp N] [--threads T]
//           [--seed S] [--cli PATH] [--repeat N]
//
// Times the point-cloud hot paths (-poc closest hits, -fscan shadow rays) on a
// sampled furnished room against Intel Embree's sphere points, and the
// `occlusion -poc` and `-fscan` commands end to end. See README.md.

#include <malloc.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "bench_args.hpp"
#include "bench_common.hpp"
#include "child_process.hpp"
#include "cloud_replay.hpp"
#include "embree_points.hpp"
#include "occlusion/analysis/cloud_occlusion.hpp"
#include "occlusion/analysis/scan.hpp"
#include "occlusion/analysis/viewpoints.hpp"
#include "occlusion/core/sphere_octree.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "room_generator.hpp"
#include "trace_compare.hpp"

namespace {

using namespace occlusion;
using namespace occlusion::bench;
namespace fs = std::filesystem;

constexpr int kPattern = 7;
constexpr double kPointRadius = 0.01;
// Hit parameters of both tracers agree if within this, relative.
constexpr double kTTolerance = 1e-4;
constexpr const char* kUsage =
    "usage: bench_poc [--points N] [--triangles N] [--rays-per-vp N] [--num-vp N] [--threads T]\n"
    "                 [--seed S] [--cli PATH] [--repeat N]\n";

struct Options : PointBenchOptions {
  std::string cli;  // empty: <build dir>/occlusion
};

Options parse(int argc, char** argv) {
  Options o;
  o.repeat = kRepetitions;  // whole processes of the CLI and embree_job, alternating
  for (int i = 1; i < argc; ++i) {
    if (parse_point_bench_flag(o, argc, argv, i)) continue;
    const std::string arg = argv[i];
    if (arg == "--cli") {
      o.cli = flag_value(argc, argv, i);
    } else {
      throw UsageError("unknown argument '" + arg + "'");
    }
  }
  check_point_bench_options(o);
  return o;
}

// One line per command: wall time from fork to exit, the job's time after
// loading (total - load in its JSON, what the 2 s goal is about), and peak RSS.
bool print_end_to_end(const char* name, const CliRun& run, bool after_loading_goal) {
  const ChildResult& c = run.best;
  if (c.exit_code != 0) {
    std::printf("%s end-to-end: FAILED (exit %d)\n%s", name, c.exit_code, c.err.c_str());
    return false;
  }
  std::printf("%s end-to-end: %.2f s", name, c.wall_seconds);
  if (run.json.isMember("timings")) {
    const Json::Value& t = run.json["timings"];
    std::printf(", after loading %.2f s%s",
                (t["total_seconds"].asDouble() - t["load_seconds"].asDouble()),
                after_loading_goal ? " (goal < 2 s)" : "");
  }
  std::printf(", peak RSS: %.0f MB (goal < 400 MB)\n", static_cast<double>(c.peak_rss_bytes) / 1e6);
  return true;
}

int run(const Options& o) {
  const fs::path bench_dir = fs::read_symlink("/proc/self/exe").parent_path();
  const std::string cli = o.cli.empty() ? (bench_dir.parent_path() / "occlusion").string() : o.cli;
  const std::string cloud_path = (bench_dir / "bench_cloud.pcd").string();

  // The room is generated, sampled, written and dropped before the CLI runs.
  double generate_seconds = 0.0;
  std::size_t triangles = 0;
  {
    const auto start = std::chrono::steady_clock::now();
    const GeneratedRoom room = generate_room(o.triangles, o.seed);
    const PointCloud sampled = sample_point_cloud(room.mesh, o.points, o.seed);
    generate_seconds = seconds_since(start);
    triangles = room.mesh.face_count();
    write_cloud(cloud_path, sampled, {}, CloudFormat::kPcdBinary);
  }

  // The CLI runs first, while this process is small: see child_process.hpp on ru_maxrss.
  malloc_trim(0);
  const std::string threads = std::to_string(o.threads);
  const std::string radius = exact(kPointRadius);
  std::fprintf(stderr, "bench_poc: running %s -poc on %s and embree_job -poc, in turn ...\n",
               cli.c_str(), cloud_path.c_str());
  const auto [poc_cli, poc_embree] = run_job_and_embree_job(
      bench_dir, cli, "poc", cloud_path,
      {"--num-vp", std::to_string(o.num_vp), "--num-rays-per-vp", std::to_string(o.rays_per_vp),
       "--primitive", "sphere", "--point-radius", radius, "--threads", threads, "--seed",
       std::to_string(o.seed)},
      o.repeat);
  std::fprintf(stderr, "bench_poc: running %s -fscan and embree_job -fscan, in turn ...\n",
               cli.c_str());
  const auto [scan_cli, scan_embree] =
      run_job_and_embree_job(bench_dir, cli, "fscan", cloud_path,
                             {"--pattern", std::to_string(kPattern), "--primitive", "sphere",
                              "--point-radius", radius, "--threads", threads},
                             o.repeat);

  auto start = std::chrono::steady_clock::now();
  const PointCloud cloud = read_cloud(cloud_path);
  const double read_seconds = seconds_since(start);
  Eigen::Vector3f lo_f, hi_f;
  cloud.bounds(lo_f, hi_f);  // what the jobs place viewpoints in
  const Eigen::Vector3d lo = lo_f.cast<double>(), hi = hi_f.cast<double>();

  CloudOcclusionOptions poc;  // the analysis' defaults, as the CLI passes them
  poc.point_radius = kPointRadius;
  poc.num_rays_per_vp = o.rays_per_vp;
  poc.seed = o.seed;
  poc.threads = o.threads;
  const std::vector<Eigen::Vector3d> grid = grid_viewpoints(o.num_vp, lo, hi);
  const std::vector<Ray> poc_rays = make_poc_rays(grid, poc);
  ScanOptions scan;
  scan.point_radius = kPointRadius;
  scan.threads = o.threads;
  const std::vector<Eigen::Vector3d> pattern = pattern_viewpoints(kPattern, lo, hi);
  const ScanRays scan_rays = make_scan_rays(cloud, pattern, scan);
  const std::size_t np = poc_rays.size(), ns = scan_rays.rays.size();

  std::fprintf(stderr, "bench_poc: builds ...\n");
  std::optional<SphereOctree> tree;
  EmbreePoints embree(o.threads);
  const LargeVector<Sphere> spheres =
      make_spheres(cloud.positions, static_cast<float>(kPointRadius));
  const int traces = std::max(o.repeat, kRepetitions);
  const auto [our_build, embree_build] = alternating_samples(
      traces,
      [&] {
        tree.reset();
        return timed([&] {
          tree.emplace(make_spheres(cloud.positions, static_cast<float>(kPointRadius)), poc.octree);
        });
      },
      [&] { return embree.build(spheres); });
  std::fprintf(stderr, "bench_poc: traces ...\n");
  const auto& [our_poc, embree_poc, our_scan, embree_scan, our_hits, their_hits, our_blocked,
               their_blocked] = trace_both(*tree, embree, poc_rays, scan_rays, o.threads, traces);

  std::fprintf(stderr, "bench_poc: compute_cloud_occlusion and scan_cloud in process ...\n");
  start = std::chrono::steady_clock::now();
  const CloudOcclusionResult poc_library = compute_cloud_occlusion(cloud, grid, {}, poc);
  const double poc_library_seconds = seconds_since(start);
  start = std::chrono::steady_clock::now();
  const ScanResult scan_library = scan_cloud(cloud, pattern, scan);
  const double scan_library_seconds = seconds_since(start);

  const HitAgreement poc_agreement =
      compare_hits(our_hits.data(), their_hits.data(), np, kTTolerance);
  const FlagAgreement scan_agreement = compare_flags(our_blocked.data(), their_blocked.data(), ns);
  std::vector<std::uint8_t> ours_hit(np), theirs_hit(np);
  for (std::size_t i = 0; i < np; ++i) {
    ours_hit[i] = our_hits[i].has_value();
    theirs_hit[i] = their_hits[i].has_value();
  }

  std::printf(
      "bench_poc: furnished room sampled as points, seed %llu, %u thread(s), best of %d "
      "(builds and traces, alternating)\n",
      static_cast<unsigned long long>(o.seed), o.threads, traces);
  std::printf(
      "cloud    %s points of %s triangles (generated in %.3f s), radius %g; binary PCD %.1f MiB, "
      "read in %.3f s\n",
      grouped(cloud.size()).c_str(), grouped(triangles).c_str(), generate_seconds, kPointRadius,
      mib(static_cast<std::size_t>(fs::file_size(cloud_path))), read_seconds);
  std::printf("poc      %zu grid viewpoints x %s rays = %s rays, closest hit\n", grid.size(),
              grouped(o.rays_per_vp).c_str(), grouped(np).c_str());
  std::printf("fscan    pattern %d: %zu viewpoints x %s points = %s shadow rays, any hit\n\n",
              kPattern, pattern.size(), grouped(cloud.size()).c_str(), grouped(ns).c_str());
  const std::string embree_name = "embree " + EmbreePoints::version() + " SPHERE_POINT";
  print_trace_header();
  const auto row = print_trace_row;
  row("poc   ours   SphereOctree intersect_batch", our_build.min(), our_poc.min(), np,
      percent(poc_agreement.ours, np));
  row("poc   " + embree_name + " rtcIntersect1", embree_build.min(), embree_poc.min(), np,
      percent(poc_agreement.theirs, np));
  row("fscan ours   SphereOctree occluded_batch", our_build.min(), our_scan.min(), ns,
      percent(scan_agreement.ours, ns));
  row("fscan " + embree_name + " rtcOccluded1", embree_build.min(), embree_scan.min(), ns,
      percent(scan_agreement.theirs, ns));

  const OctreeStats& s = tree->stats();
  std::printf("\noctree   %s inner nodes, %s leaves, depth %d, largest leaf %zu, %.1f MiB\n",
              grouped(s.inner_nodes).c_str(), grouped(s.leaves).c_str(), s.depth, s.largest_leaf,
              mib(s.memory_bytes));
  print_hit_agreement("poc", poc_agreement, kTTolerance);
  print_flag_agreement("fscan", scan_agreement);
  std::printf("level    poc occlusion level: ours %.6f, embree %.6f, compute_cloud_occlusion %.6f",
              poc_level_from_hits(ours_hit.data(), np), poc_level_from_hits(theirs_hit.data(), np),
              poc_library.occlusion_level);
  if (poc_cli.json.isMember("occlusion_level")) {
    std::printf(", CLI %.6f", poc_cli.json["occlusion_level"].asDouble());
  }
  if (poc_embree.json.isMember("occlusion_level")) {
    std::printf(", Embree program %.6f", poc_embree.json["occlusion_level"].asDouble());
  }
  std::printf("\n         fscan visible fraction: ours %.6f, embree %.6f, scan_cloud %.6f",
              visible_fraction_from_flags(scan_rays, our_blocked.data()),
              visible_fraction_from_flags(scan_rays, their_blocked.data()),
              scan_library.visible_fraction);
  if (scan_cli.json.isMember("visible_fraction")) {
    std::printf(", CLI %.6f", scan_cli.json["visible_fraction"].asDouble());
  }
  if (scan_embree.json.isMember("visible_fraction")) {
    std::printf(", Embree program %.6f", scan_embree.json["visible_fraction"].asDouble());
  }
  std::printf(
      "\nlibrary  compute_cloud_occlusion %.3f s (build %.3f, trace %.3f); scan_cloud %.3f s "
      "(build %.3f, trace %.3f)\n",
      poc_library_seconds, poc_library.build_seconds, poc_library.trace_seconds,
      scan_library_seconds, scan_library.build_seconds, scan_library.trace_seconds);
  if (poc_cli.json.isMember("timings")) {
    std::printf("CLI      -poc   %s\n", stage_timings(poc_cli.json).c_str());
  }
  if (scan_cli.json.isMember("timings")) {
    std::printf("CLI      -fscan %s\n", stage_timings(scan_cli.json).c_str());
  }

  std::printf("\n");
  print_ratio("build", our_build, embree_build, 0);
  print_ratio("poc", our_poc, embree_poc, np);
  print_ratio("fscan", our_scan, embree_scan, ns);
  std::printf("poc ours/embree throughput: %.2f\n", embree_poc.min() / our_poc.min());
  std::printf("fscan ours/embree throughput: %.2f\n", embree_scan.min() / our_scan.min());
  const bool poc_ok = print_end_to_end("poc", poc_cli, true);
  const bool scan_ok = print_end_to_end("fscan", scan_cli, false);
  const bool poc_whole = print_whole_process("poc", poc_cli, poc_embree);
  const bool scan_whole = print_whole_process("fscan", scan_cli, scan_embree);
  return poc_ok && scan_ok && poc_whole && scan_whole ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  return occlusion::bench::run_tool("bench_poc", kUsage, argc, argv, parse, run);
}
