// bench_rgoc [--points N] [--triangles N] [--threads T] [--seed S] [--max-cluster-size N]
//
// Times `-rgoc`'s stages (normals, region growing, planes, hulls, occlusion)
// on a sampled furnished room, with the process's peak memory, and compares
// the estimated mesh's occlusion level with the exact room's. See README.md.

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <fstream>
#include <string>
#include <vector>

#include "bench_args.hpp"
#include "occlusion/analysis/mesh_estimation.hpp"
#include "occlusion/analysis/mesh_occlusion.hpp"
#include "occlusion/analysis/mesh_sampling.hpp"
#include "occlusion/analysis/viewpoints.hpp"
#include "room_generator.hpp"

namespace {

using occlusion::bench::flag_value;
using occlusion::bench::parse_threads;
using occlusion::bench::parse_unsigned;
using occlusion::bench::UsageError;

constexpr int kPattern = 7;
constexpr const char* kUsage =
    "usage: bench_rgoc [--points N] [--triangles N] [--threads T] [--seed S]\n"
    "                  [--max-cluster-size N]\n";

struct Options {
  std::size_t points = 1'000'000;
  std::size_t triangles = 100'000;
  unsigned threads = 2;
  std::uint64_t seed = 1;
  // At ~3,750 points per square metre the room's floor alone has ~180,000
  // points, so the seed's 100,000 would drop it.
  std::size_t max_cluster_size = 1'000'000;
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--points") {
      o.points = parse_unsigned(arg, flag_value(argc, argv, i));
    } else if (arg == "--triangles") {
      o.triangles = parse_unsigned(arg, flag_value(argc, argv, i));
    } else if (arg == "--threads") {
      o.threads = parse_threads(arg, flag_value(argc, argv, i));
    } else if (arg == "--seed") {
      o.seed = parse_unsigned(arg, flag_value(argc, argv, i));
    } else if (arg == "--max-cluster-size") {
      o.max_cluster_size = parse_unsigned(arg, flag_value(argc, argv, i));
    } else {
      throw UsageError("unknown argument '" + arg + "'");
    }
  }
  if (o.points == 0 || o.triangles == 0 || o.threads == 0 || o.max_cluster_size == 0) {
    throw UsageError("--points, --triangles, --threads and --max-cluster-size must be > 0");
  }
  if (o.points > 100'000'000) throw UsageError("--points must be at most 100000000");
  return o;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Resident memory now and at its peak, in MiB (Linux).
double resident_mib() {
  std::ifstream statm("/proc/self/statm");
  std::size_t pages = 0, resident = 0;
  statm >> pages >> resident;
  return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE)) /
         (1024.0 * 1024.0);
}

double peak_resident_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

double total_area(const occlusion::TriangleMesh& mesh) {
  double area = 0.0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) area += mesh.face_area(f);
  return area;
}

int run(const Options& o) {
  using namespace occlusion;
  std::printf("bench_rgoc: %zu points from a %zu-triangle room, %u threads, seed %llu\n", o.points,
              o.triangles, o.threads, static_cast<unsigned long long>(o.seed));
  const TriangleMesh room = bench::generate_room(o.triangles, o.seed).mesh;
  const double area = total_area(room);
  PointCloud cloud;
  {
    // The density that gives `points` samples on average; sample_mesh rounds per face.
    const MeshSamples samples = sample_mesh(room, static_cast<double>(o.points) / area, o.seed);
    cloud.positions.reserve(samples.size());
    for (const auto& p : samples.points) cloud.positions.push_back(p.cast<float>());
  }
  std::printf("room: %zu triangles, %.1f m2; cloud: %zu points (%.0f per m2)\n", room.face_count(),
              area, cloud.size(), static_cast<double>(cloud.size()) / area);
  const double resident_before = resident_mib();

  RegionGrowingOptions estimation;
  estimation.max_cluster_size = o.max_cluster_size;
  estimation.threads = o.threads;
  auto start = std::chrono::steady_clock::now();
  const MeshEstimate estimate = estimate_mesh(cloud, estimation);
  const double estimate_seconds = seconds_since(start);

  Eigen::Vector3f lo, hi;
  cloud.bounds(lo, hi);
  const auto viewpoints = pattern_viewpoints(kPattern, lo.cast<double>(), hi.cast<double>());
  MeshOcclusionOptions occlusion;
  occlusion.seed = o.seed;
  occlusion.threads = o.threads;
  start = std::chrono::steady_clock::now();
  const MeshOcclusionResult estimated =
      compute_mesh_occlusion(estimate.mesh, viewpoints, occlusion);
  const double occlusion_seconds = seconds_since(start);
  const double peak = peak_resident_mib();
  const MeshOcclusionResult exact = compute_mesh_occlusion(room, viewpoints, occlusion);

  const MeshEstimationTimings& t = estimate.timings;
  std::printf("\nstage                 seconds\n");
  std::printf("normals               %7.3f   (kd-tree, one k = %u search per point, normals)\n",
              t.normals_seconds, std::max(estimation.normal_k, estimation.neighbours));
  std::printf("region growing        %7.3f   (%u neighbours from that search)\n",
              t.region_growing_seconds, estimation.neighbours);
  std::printf("planes                %7.3f   (RANSAC, projection, edge points)\n",
              t.planes_seconds);
  std::printf("hulls                 %7.3f   (convex hulls, centroids, fans)\n", t.hulls_seconds);
  std::printf("occlusion             %7.3f   (sampling %.3f, octree %.3f, tracing %.3f)\n",
              occlusion_seconds, estimated.timings.sampling_seconds,
              estimated.timings.build_seconds, estimated.timings.trace_seconds);
  std::printf("total                 %7.3f   (goal < 5 s on 2 cores)\n",
              estimate_seconds + occlusion_seconds);
  std::printf("\nmemory: %.0f MiB resident with the cloud, peak %.0f MiB (ru_maxrss)\n",
              resident_before, peak);
  std::printf(
      "clusters: %zu regions grown, %zu found, %zu used, %zu skipped; "
      "%zu too small (%zu points), %zu too large (%zu points)\n",
      estimate.regions.regions, estimate.clusters_found, estimate.clusters_used,
      estimate.skipped.size(), estimate.regions.too_small, estimate.regions.too_small_points,
      estimate.regions.too_large, estimate.regions.too_large_points);
  std::printf("covered: %.1f %% of the points (%zu edge points recovered)\n",
              100.0 * estimate.covered_fraction, estimate.edge_points);
  std::printf("mesh: %zu faces, %.1f m2 (room %.1f m2)\n", estimate.mesh.face_count(),
              estimated.total_area, area);
  std::printf("occlusion level: estimated mesh %.4f, exact room %.4f (pattern %d)\n",
              estimated.occlusion_level, exact.occlusion_level, kPattern);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return occlusion::bench::run_tool("bench_rgoc", kUsage, argc, argv, parse, run);
}
