// bench_discs [--points N] [--triangles N] [--rays-per-vp N] [--num-vp N] [--threads T]
//             [--seed S] [--repeat N] [--leaf N] [--whole N]
//
// Times the point-cloud hot paths traced as surfels (the default point model:
// -poc closest hits, -fscan shadow rays) on a sampled furnished room against
// Intel Embree's oriented disc points, on the same discs and rays, and the
// `occlusion -poc` and `-fscan` commands against embree_job's, whole process.
// See README.md.

#include <malloc.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "bench_args.hpp"
#include "bench_common.hpp"
#include "cloud_replay.hpp"
#include "embree_points.hpp"
#include "occlusion/analysis/cloud_occlusion.hpp"
#include "occlusion/analysis/scan.hpp"
#include "occlusion/analysis/surfel_estimation.hpp"
#include "occlusion/analysis/viewpoints.hpp"
#include "occlusion/core/surfel_octree.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "room_generator.hpp"
#include "trace_compare.hpp"

namespace {

using namespace occlusion;
using namespace occlusion::bench;
namespace fs = std::filesystem;

constexpr int kPattern = 7;
// Hit parameters of both tracers agree if within this, relative.
constexpr double kTTolerance = 1e-4;
// A crossing this close to a disc's rim (relative to its radius) or to an end of the
// ray's interval (relative to t), or a ray this
// close to its plane (|d.n| / |d|), is one float rounding may put either side.
constexpr double kRimTolerance = 1e-4;
constexpr double kGrazing = 1e-3;
constexpr const char* kUsage =
    "usage: bench_discs [--points N] [--triangles N] [--rays-per-vp N] [--num-vp N] [--threads T]\n"
    "                   [--seed S] [--repeat N] [--leaf N] [--whole N]\n";

struct Options : PointBenchOptions {
  std::size_t leaf = 0;  // our octree's max_leaf_size; 0: surfel_octree_options()'s
  int whole = 3;         // whole processes of the CLI and embree_job each, alternating
};

Options parse(int argc, char** argv) {
  Options o;
  o.repeat = 5;  // traces of ours and Embree's, alternating
  for (int i = 1; i < argc; ++i) {
    if (parse_point_bench_flag(o, argc, argv, i)) continue;
    const std::string arg = argv[i];
    if (arg == "--leaf") {
      o.leaf = parse_unsigned(arg, flag_value(argc, argv, i));
    } else if (arg == "--whole") {
      o.whole = static_cast<int>(
          std::min<std::uint64_t>(100, parse_unsigned(arg, flag_value(argc, argv, i))));
    } else {
      throw UsageError("unknown argument '" + arg + "'");
    }
  }
  check_point_bench_options(o);
  return o;
}

// Why two tracers can disagree on a ray: where it meets the surfel one of
// them hit, recomputed in double.
struct Diagnosis {
  std::size_t spheres = 0;  // the surfel is a sphere
  std::size_t rim = 0;      // crossing within kRimTolerance of the rim
  std::size_t grazing = 0;  // ray within kGrazing of the disc's plane
  std::size_t end = 0;      // crossing within kRimTolerance (relative) of t_min or t_max
  std::size_t target = 0;   // the shadow ray's own target (Embree cannot skip it)
  std::size_t other = 0;
  double worst_rim = 0.0;  // of the others: largest | |crossing - centre| / r - 1 |
  void add(const Ray& ray, const Surfel& surfel, bool is_target) {
    if (is_target) {
      ++target;
      return;
    }
    if (!surfel.oriented()) {
      ++spheres;
      return;
    }
    const Eigen::Vector3d o = ray.origin.cast<double>(), d = ray.direction.cast<double>();
    const Eigen::Vector3d c = surfel.center.cast<double>(), n = surfel.normal.cast<double>();
    const double facing = d.dot(n);
    if (std::abs(facing) <= kGrazing * d.norm()) {
      ++grazing;
      return;
    }
    const double t = (c - o).dot(n) / facing;
    const double t_min = ray.t_min, t_max = ray.t_max;
    if (std::abs(t - t_min) <= kRimTolerance * std::abs(t) ||
        std::abs(t - t_max) <= kRimTolerance * std::abs(t)) {
      ++end;
      return;
    }
    const double off_rim = std::abs((o + t * d - c).norm() / surfel.radius - 1.0);
    if (off_rim <= kRimTolerance) {
      ++rim;
    } else {
      ++other;
      worst_rim = std::max(worst_rim, off_rim);
    }
  }
  void print(const char* label) const {
    std::printf(
        "%-8s disagreements: %zu at a disc's rim (within %g r), %zu grazing (|d.n| <= %g |d|), "
        "%zu at an end of the ray's interval (within %g t), %zu on spheres, %zu on the target "
        "itself, "
        "%zu other",
        label, rim, kRimTolerance, grazing, kGrazing, end, kRimTolerance, spheres, target, other);
    if (other > 0) std::printf(" (farthest from a rim: %.2g r)", worst_rim);
    std::printf("\n");
  }
};

int run(const Options& o) {
  const fs::path bench_dir = fs::read_symlink("/proc/self/exe").parent_path();
  const std::string cli = (bench_dir.parent_path() / "occlusion").string();
  const std::string cloud_path = (bench_dir / "bench_discs_cloud.pcd").string();
  auto start = std::chrono::steady_clock::now();
  std::size_t triangles = 0;
  {
    const GeneratedRoom room = generate_room(o.triangles, o.seed);
    const PointCloud sampled = sample_point_cloud(room.mesh, o.points, o.seed);
    triangles = room.mesh.face_count();
    write_cloud(cloud_path, sampled, {}, CloudFormat::kPcdBinary);
  }
  const double generate_seconds = seconds_since(start);

  // The CLI and embree_job (discs, estimate_surfels' defaults), while this
  // process is small: see child_process.hpp on ru_maxrss.
  malloc_trim(0);
  const std::string threads = std::to_string(o.threads);
  std::pair<CliRun, CliRun> poc_whole, scan_whole;
  if (o.whole > 0) {
    std::fprintf(stderr, "bench_discs: %s -poc and embree_job -poc, in turn ...\n", cli.c_str());
    poc_whole = run_job_and_embree_job(
        bench_dir, cli, "poc", cloud_path,
        {"--num-vp", std::to_string(o.num_vp), "--num-rays-per-vp", std::to_string(o.rays_per_vp),
         "--threads", threads, "--seed", std::to_string(o.seed)},
        o.whole);
    std::fprintf(stderr, "bench_discs: %s -fscan and embree_job -fscan, in turn ...\n",
                 cli.c_str());
    scan_whole = run_job_and_embree_job(
        bench_dir, cli, "fscan", cloud_path,
        {"--pattern", std::to_string(kPattern), "--threads", threads}, o.whole);
  }
  const PointCloud cloud = read_cloud(cloud_path);
  Eigen::Vector3f lo_f, hi_f;
  cloud.bounds(lo_f, hi_f);
  const Eigen::Vector3d lo = lo_f.cast<double>(), hi = hi_f.cast<double>();

  std::fprintf(stderr, "bench_discs: estimate_surfels ...\n");
  SurfelOptions surfel_options;  // the defaults, as the CLI's
  surfel_options.threads = o.threads;
  const SurfelEstimate estimate = estimate_surfels(cloud, surfel_options);
  const LargeVector<Surfel>& surfels = estimate.surfels;

  CloudOcclusionOptions poc;  // the analysis' defaults, as the CLI passes them
  poc.num_rays_per_vp = o.rays_per_vp;
  poc.seed = o.seed;
  poc.threads = o.threads;
  poc.surfels = &estimate;
  const std::vector<Eigen::Vector3d> grid = grid_viewpoints(o.num_vp, lo, hi);
  const std::vector<Ray> poc_rays = make_poc_rays(grid, poc);
  ScanOptions scan;
  scan.threads = o.threads;
  scan.surfels = &estimate;
  const std::vector<Eigen::Vector3d> pattern = pattern_viewpoints(kPattern, lo, hi);
  const ScanRays scan_rays = make_scan_surfel_rays(estimate, pattern, scan);
  const std::size_t np = poc_rays.size(), ns = scan_rays.rays.size();

  std::fprintf(stderr, "bench_discs: builds ...\n");
  std::optional<SurfelOctree> tree;
  OctreeOptions octree = surfel_octree_options();
  if (o.leaf > 0) octree.max_leaf_size = o.leaf;
  EmbreeDiscs embree(o.threads);
  const auto [our_builds, embree_builds] = alternating_samples(
      o.repeat,
      [&] {
        tree.reset();
        return timed([&] { tree.emplace(LargeVector<Surfel>(surfels), octree); });
      },
      [&] { return embree.build(surfels); });

  std::fprintf(stderr, "bench_discs: traces ...\n");
  const auto& [our_poc, embree_poc, our_scan, embree_scan, our_hits, their_hits, our_blocked,
               their_blocked] = trace_both(*tree, embree, poc_rays, scan_rays, o.threads, o.repeat);

  std::fprintf(stderr, "bench_discs: compute_cloud_occlusion and scan_cloud in process ...\n");
  const CloudOcclusionResult poc_library = compute_cloud_occlusion(cloud, grid, {}, poc);
  const ScanResult scan_library = scan_cloud(cloud, pattern, scan);

  const HitAgreement poc_agreement =
      compare_hits(our_hits.data(), their_hits.data(), np, kTTolerance);
  const FlagAgreement scan_agreement = compare_flags(our_blocked.data(), their_blocked.data(), ns);
  Diagnosis poc_why, scan_why;
  for (const std::size_t i : poc_agreement.disagreeing) {
    const Hit& hit = our_hits[i] ? *our_hits[i] : *their_hits[i];
    poc_why.add(poc_rays[i], surfels[hit.primitive_id], false);
  }
  for (const std::size_t i : scan_agreement.disagreeing) {
    // The blocker, as the closest hit of the tracer that found one.
    const Ray& ray = scan_rays.rays[i];
    std::optional<Hit> hit;
    if (our_blocked[i]) {
      hit = tree->intersect(ray, scan_rays.ignore[i]);
    } else {
      embree.intersect(&ray, 1, &hit, 1);
    }
    if (hit)
      scan_why.add(ray, surfels[hit->primitive_id], hit->primitive_id == scan_rays.ignore[i]);
  }
  std::vector<std::uint8_t> ours_hit(np), theirs_hit(np);
  for (std::size_t i = 0; i < np; ++i) {
    ours_hit[i] = our_hits[i].has_value();
    theirs_hit[i] = their_hits[i].has_value();
  }

  const SurfelStats& st = estimate.stats;
  std::printf("bench_discs: furnished room sampled as surfels, seed %llu, %u thread(s), %d runs\n",
              static_cast<unsigned long long>(o.seed), o.threads, o.repeat);
  std::printf(
      "cloud    %s points of %s triangles (generated in %.3f s); estimate_surfels %.3f s: %s "
      "discs, %s spheres, radius median %.4g (10%% %.4g, 90%% %.4g)\n",
      grouped(cloud.size()).c_str(), grouped(triangles).c_str(), generate_seconds, st.seconds,
      grouped(st.oriented).c_str(), grouped(st.unoriented).c_str(), st.radius_median,
      st.radius_quantile_10, st.radius_quantile_90);
  std::printf("poc      %zu grid viewpoints x %s rays = %s rays, closest hit\n", grid.size(),
              grouped(o.rays_per_vp).c_str(), grouped(np).c_str());
  std::printf("fscan    pattern %d: %zu viewpoints x %s points = %s shadow rays, any hit\n\n",
              kPattern, pattern.size(), grouped(cloud.size()).c_str(), grouped(ns).c_str());
  const std::string embree_name = "embree " + EmbreeTracer::version() + " DISC+SPHERE";
  print_trace_header();
  print_trace_row("poc   ours   SurfelOctree intersect_batch", our_builds.min(), our_poc.min(), np,
                  percent(poc_agreement.ours, np));
  print_trace_row("poc   " + embree_name + " rtcIntersect1", embree_builds.min(), embree_poc.min(),
                  np, percent(poc_agreement.theirs, np));
  print_trace_row("fscan ours   SurfelOctree occluded_batch", our_builds.min(), our_scan.min(), ns,
                  percent(scan_agreement.ours, ns));
  print_trace_row("fscan " + embree_name + " rtcOccluded1", embree_builds.min(), embree_scan.min(),
                  ns, percent(scan_agreement.theirs, ns));

  const OctreeStats& s = tree->stats();
  std::printf(
      "\noctree   leaves of up to %zu, %s inner nodes, %s leaves, depth %d, largest leaf %zu, %.1f "
      "MiB\n",
      octree.max_leaf_size, grouped(s.inner_nodes).c_str(), grouped(s.leaves).c_str(), s.depth,
      s.largest_leaf, mib(s.memory_bytes));
  print_hit_agreement("poc", poc_agreement, kTTolerance);
  poc_why.print("poc");
  print_flag_agreement("fscan", scan_agreement);
  scan_why.print("fscan");
  std::printf(
      "level    poc occlusion level: ours %.6f, embree %.6f, compute_cloud_occlusion %.6f\n",
      poc_level_from_hits(ours_hit.data(), np), poc_level_from_hits(theirs_hit.data(), np),
      poc_library.occlusion_level);
  std::printf("         fscan visible fraction: ours %.6f, embree %.6f, scan_cloud %.6f\n\n",
              visible_fraction_from_flags(scan_rays, our_blocked.data()),
              visible_fraction_from_flags(scan_rays, their_blocked.data()),
              scan_library.visible_fraction);
  print_ratio("build", our_builds, embree_builds, 0);
  print_ratio("poc", our_poc, embree_poc, np);
  print_ratio("fscan", our_scan, embree_scan, ns);
  if (o.whole == 0) return 0;
  for (const auto& [job, runs, key] : {std::tuple("poc", &poc_whole, "occlusion_level"),
                                       std::tuple("fscan", &scan_whole, "visible_fraction")}) {
    std::printf("%-6s CLI %s %.6f, Embree program %.6f\n", job, key,
                runs->first.json[key].asDouble(), runs->second.json[key].asDouble());
  }
  const bool poc_ok = print_whole_process("poc", poc_whole.first, poc_whole.second);
  const bool scan_ok = print_whole_process("fscan", scan_whole.first, scan_whole.second);
  return poc_ok && scan_ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  return occlusion::bench::run_tool("bench_discs", kUsage, argc, argv, parse, run);
}
