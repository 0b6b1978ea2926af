// bench_simulate [--triangles N] [--step DEG] [--threads T] [--seed S] [--repeat N]
//
// The virtual scanner (occlusion simulate) against Intel Embree on the same
// rays and mesh: one laser station at the generated furnished room's centre,
// 1.5 m above its floor, its beams (a full turn, elevation -60 to 90 degrees
// in DEG steps) traced as closest hits by our triangle octree in the
// scanner's order and packets (8 x 4 tiles as given, beam_tiles.hpp), by
// rtcIntersect1 on the same rays in the same order, and by our octree in the
// grid's order sorted by direction (the scanner's trace before tiles), in
// turn; then the whole simulate_scan (rays made, traced, turned into returns
// with noise) against the Embree trace alone. See README.md.

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "bench_args.hpp"
#include "bench_common.hpp"
#include "embree_scene.hpp"
#include "occlusion/analysis/beam_tiles.hpp"
#include "occlusion/analysis/virtual_scanner.hpp"
#include "occlusion/core/triangle_octree.hpp"
#include "room_generator.hpp"

namespace {

using namespace occlusion;
using namespace occlusion::bench;

constexpr const char* kUsage =
    "usage: bench_simulate [--triangles N] [--step DEG] [--threads T] [--seed S] [--repeat N]\n";

struct Options {
  std::size_t triangles = 100'000;
  double step = 0.1;
  unsigned threads = 2;
  std::uint64_t seed = 1;
  int repeat = kRepetitions;
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--triangles") {
      o.triangles = parse_unsigned(arg, flag_value(argc, argv, i));
    } else if (arg == "--step") {
      o.step = std::stod(flag_value(argc, argv, i));
      if (!(o.step > 0.0 && o.step <= 10.0)) throw UsageError("--step must be in (0, 10]");
    } else if (arg == "--threads") {
      o.threads = parse_threads(arg, flag_value(argc, argv, i));
    } else if (arg == "--seed") {
      o.seed = parse_unsigned(arg, flag_value(argc, argv, i));
    } else if (arg == "--repeat") {
      o.repeat = static_cast<int>(parse_unsigned(arg, flag_value(argc, argv, i)));
      if (o.repeat < 1) throw UsageError("--repeat must be at least 1");
    } else {
      throw UsageError("unknown argument '" + arg + "'");
    }
  }
  return o;
}

// The station's beams as simulate_scan makes them for a laser with no
// divergence (unit directions, t up to max_range), in the grid's order
// (row by row) or in the order it traces them (BeamTiles: 8 x 4 tiles).
std::vector<Ray> laser_rays(const LaserScannerModel& laser, const Eigen::Vector3f& origin,
                            bool tiled) {
  constexpr double kDegree = 3.14159265358979323846 / 180.0;
  const BeamTiles tiles{laser.columns(), laser.rows()};
  std::vector<Ray> rays;
  rays.reserve(tiles.columns * tiles.rows);
  const auto add = [&](std::size_t row, std::size_t column) {
    const double azimuth = laser.azimuth_deg(column) * kDegree;
    const double elevation = laser.elevation_deg(row) * kDegree;
    Ray ray;
    ray.origin = origin;
    ray.direction = Eigen::Vector3d(std::cos(elevation) * std::cos(azimuth),
                                    std::cos(elevation) * std::sin(azimuth), std::sin(elevation))
                        .cast<float>();
    ray.t_max = static_cast<float>(laser.max_range);
    rays.push_back(ray);
  };
  for (std::size_t row = 0; row < tiles.rows && !tiled; ++row) {
    for (std::size_t column = 0; column < tiles.columns; ++column) add(row, column);
  }
  for (std::size_t strip = 0; strip < tiles.strips() && tiled; ++strip) {
    tiles.visit(strip, 0, tiles.tiles_per_strip(), add);
  }
  return rays;
}

int run(const Options& o) {
  std::fprintf(stderr, "bench_simulate: generating the room ...\n");
  const TriangleMesh mesh = generate_room(o.triangles, o.seed).mesh;
  Eigen::Vector3d lo, hi;
  mesh.bounds(lo, hi);
  const Eigen::Vector3d station(0.5 * (lo.x() + hi.x()), 0.5 * (lo.y() + hi.y()), lo.z() + 1.5);
  LaserScannerModel laser;
  laser.azimuth_step_deg = laser.elevation_step_deg = o.step;
  // The mesh is near the origin: no global shift, so these are simulate_scan's rays.
  const std::vector<Ray> rays = laser_rays(laser, station.cast<float>(), true);
  const std::vector<Ray> rows = laser_rays(laser, station.cast<float>(), false);
  const std::size_t n = rays.size();

  const TriangleOctree tree(pack_triangles(mesh.triangles()));
  EmbreeScene embree(o.threads);
  embree.build(mesh);
  std::vector<std::optional<Hit>> ours(n), theirs(n), by_rows(n);
  std::fprintf(stderr, "bench_simulate: tracing %zu beams, ours and embree in turn ...\n", n);
  // In turn, so that a busy machine slows all three alike: the scanner's
  // tiles as it traces them (packets as given), Embree on the same rays in
  // the same order, and the grid's rows sorted by direction (before tiles).
  Samples our_samples, embree_samples, rows_samples;
  for (int k = 0; k < o.repeat; ++k) {
    our_samples.seconds.push_back(timed([&] {
      tree.intersect_batch(rays.data(), n, nullptr, ours.data(), o.threads, BatchOrder::kAsGiven);
    }));
    embree_samples.seconds.push_back(
        timed([&] { embree.intersect(rays.data(), n, theirs.data(), o.threads); }));
    rows_samples.seconds.push_back(
        timed([&] { tree.intersect_batch(rows.data(), n, nullptr, by_rows.data(), o.threads); }));
  }
  const double our_trace = our_samples.min(), embree_trace = embree_samples.min();
  const double rows_trace = rows_samples.min();
  std::size_t hits = 0, same = 0;
  for (std::size_t i = 0; i < n; ++i) {
    hits += ours[i] ? 1 : 0;
    const bool both = ours[i] && theirs[i];
    same += (!ours[i] && !theirs[i]) || (both && std::abs(ours[i]->t_hit - theirs[i]->t_hit) <=
                                                     1e-4f * std::max(1.0f, theirs[i]->t_hit))
                ? 1
                : 0;
  }

  std::fprintf(stderr, "bench_simulate: simulate_scan, %d times ...\n", o.repeat);
  SimulationOptions simulation;
  simulation.threads = o.threads;
  simulation.seed = o.seed;
  SimulatedScan scan;
  const double whole = best_of([&] {
    const auto t0 = std::chrono::steady_clock::now();
    scan = simulate_scan(mesh, {{"centre", station}}, laser, simulation);
    return seconds_since(t0);
  });

  std::printf("bench_simulate: furnished room, seed %llu, %u thread(s), best of %d\n",
              static_cast<unsigned long long>(o.seed), o.threads, o.repeat);
  std::printf(
      "scene    %s triangles; one laser station, %.3g degree steps: %s beams (%zu x %zu)\n\n",
      grouped(mesh.face_count()).c_str(), o.step, grouped(n).c_str(), laser.columns(),
      laser.rows());
  std::printf("%-34s %10s %12s\n", "", "trace (s)", "beams/s");
  std::printf("%-34s %10.4f %10.2f M\n", "ours   tiles, packets as given", our_trace,
              static_cast<double>(n) / our_trace / 1e6);
  std::printf("%-34s %10.4f %10.2f M\n", "ours   rows, sorted by direction", rows_trace,
              static_cast<double>(n) / rows_trace / 1e6);
  std::printf("%-34s %10.4f %10.2f M\n",
              ("embree " + EmbreeScene::version() + " rtcIntersect1").c_str(), embree_trace,
              static_cast<double>(n) / embree_trace / 1e6);
  std::printf("%-34s %10.4f %10.2f M   (%s points; octree %.3f s, scan %.3f s)\n",
              "ours   simulate_scan, whole", whole, static_cast<double>(n) / whole / 1e6,
              grouped(scan.cloud.size()).c_str(), scan.build_seconds, scan.trace_seconds);
  std::printf("\nhits     %s of %s beams; the same hit as Embree's on %.4f%% (goal > 99.9%%)\n",
              grouped(hits).c_str(), grouped(n).c_str(),
              100.0 * static_cast<double>(same) / static_cast<double>(n));
  std::printf(
      "ours/embree throughput: trace %.2f (rows sorted: %.2f), whole simulate_scan %.2f (goal >= "
      "1.0)\n",
      embree_trace / our_trace, embree_trace / rows_trace, embree_trace / whole);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(parse(argc, argv));
  } catch (const UsageError& e) {
    std::fprintf(stderr, "bench_simulate: %s\n%s", e.what(), kUsage);
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_simulate: %s\n", e.what());
    return 1;
  }
}
