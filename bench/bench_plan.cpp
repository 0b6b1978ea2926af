// bench_plan [--points N] [--triangles N] [--candidates N] [--height H] [--threads T]
//            [--seed S] [--repeat N]
//
// Times scan planning's cost, the visibility matrix of candidate stations
// over a cloud's points (cloud_station_coverage: -fscan's rule against the
// disc model, one octree shared by every candidate), against the same matrix
// on Intel Embree: the same discs as oriented disc points, the same rays
// (scan_surfel_ray per candidate and point), occluded queries. See README.md.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench_args.hpp"
#include "bench_common.hpp"
#include "cloud_replay.hpp"
#include "embree_points.hpp"
#include "occlusion/analysis/station_visibility.hpp"
#include "occlusion/analysis/surfel_estimation.hpp"
#include "room_generator.hpp"
#include "trace_compare.hpp"

namespace {

using namespace occlusion;
using namespace occlusion::bench;

constexpr const char* kUsage =
    "usage: bench_plan [--points N] [--triangles N] [--candidates N] [--height H] [--threads T]\n"
    "                  [--seed S] [--repeat N]\n";

struct Options {
  std::size_t points = 200'000;
  std::size_t triangles = 100'000;
  std::size_t candidates = 1'000;
  double height = 1.5;  // the candidates' height above the floor, in metres
  unsigned threads = 2;
  std::uint64_t seed = 2;
  int repeat = 3;
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--points") {
      o.points = parse_unsigned(arg, flag_value(argc, argv, i));
    } else if (arg == "--triangles") {
      o.triangles = parse_unsigned(arg, flag_value(argc, argv, i));
    } else if (arg == "--candidates") {
      o.candidates = parse_unsigned(arg, flag_value(argc, argv, i));
    } else if (arg == "--height") {
      const std::string text = flag_value(argc, argv, i);
      char* end = nullptr;
      o.height = std::strtod(text.c_str(), &end);
      if (text.empty() || end != text.c_str() + text.size()) {
        throw UsageError(arg + " expects a number, got '" + text + "'");
      }
    } else if (arg == "--threads") {
      o.threads = parse_threads(arg, flag_value(argc, argv, i));
    } else if (arg == "--seed") {
      o.seed = parse_unsigned(arg, flag_value(argc, argv, i));
    } else if (arg == "--repeat") {
      o.repeat = static_cast<int>(
          std::min<std::uint64_t>(1000, parse_unsigned(arg, flag_value(argc, argv, i))));
    } else {
      throw UsageError("unknown argument '" + arg + "'");
    }
  }
  if (o.points == 0 || o.triangles == 0 || o.candidates == 0 || o.threads == 0 || o.repeat == 0) {
    throw UsageError("--points, --triangles, --candidates, --threads and --repeat must be > 0");
  }
  if (!(o.height > 0.0 && o.height < kRoomSize.z())) {
    throw UsageError("--height must lie inside the room, 0 to 3 m");
  }
  return o;
}

// About `count` candidates on a square grid over the floor, 30 cm clear of
// the walls, at `height`. Some stand in furniture, as a plan's grid before
// its clearance test would.
std::vector<Eigen::Vector3d> floor_grid(std::size_t count, double height) {
  const double inset = 0.3;
  const double width = kRoomSize.x() - 2 * inset, depth = kRoomSize.y() - 2 * inset;
  const double spacing = std::sqrt(width * depth / static_cast<double>(count));
  const auto nx = std::max<std::size_t>(1, static_cast<std::size_t>(std::round(width / spacing)));
  const auto ny = std::max<std::size_t>(1, static_cast<std::size_t>(std::round(depth / spacing)));
  std::vector<Eigen::Vector3d> grid;
  for (std::size_t i = 0; i < nx; ++i) {
    for (std::size_t j = 0; j < ny; ++j) {
      grid.emplace_back(inset + (static_cast<double>(i) + 0.5) * width / static_cast<double>(nx),
                        inset + (static_cast<double>(j) + 0.5) * depth / static_cast<double>(ny),
                        height);
    }
  }
  return grid;
}

// The matrix as a program on Embree would fill it: per candidate, every
// point's shadow ray made as it is traced, rtcOccluded1 on T threads.
CoverageMatrix embree_matrix(const EmbreeDiscs& embree, const SurfelEstimate& estimate,
                             const std::vector<Eigen::Vector3d>& candidates, unsigned threads) {
  const std::size_t points = estimate.surfels.size();
  CoverageMatrix matrix(candidates.size(), std::vector<double>(points, 1.0));
  const double near_viewpoint = 2.0 * estimate.stats.radius_median;
  std::vector<std::uint8_t> blocked(points);
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    embree.occluded_made(
        points,
        [&](std::size_t i, Ray& ray) {
          ray = scan_surfel_ray(candidates[c], estimate.surfels[i], estimate.thickness[i],
                                near_viewpoint);
          return true;
        },
        blocked.data(), threads);
    for (std::size_t i = 0; i < points; ++i) {
      if (!blocked[i]) matrix.set_seen(c, i);
    }
  }
  return matrix;
}

int run(const Options& o) {
  std::fprintf(stderr, "bench_plan: room and cloud ...\n");
  const GeneratedRoom room = generate_room(o.triangles, o.seed);
  const PointCloud cloud = sample_point_cloud(room.mesh, o.points, o.seed);
  SurfelOptions surfel_options;  // the defaults, as the CLI's
  surfel_options.threads = o.threads;
  const SurfelEstimate estimate = estimate_surfels(cloud, surfel_options);
  const std::vector<Eigen::Vector3d> candidates = floor_grid(o.candidates, o.height);
  const std::size_t rays = candidates.size() * cloud.size();

  ScanOptions scan;
  scan.threads = o.threads;
  scan.surfels = &estimate;
  const std::vector<double> weight(cloud.size(), 1.0);
  EmbreeDiscs embree(o.threads);
  CoverageMatrix ours, theirs;
  Samples embree_builds;
  std::fprintf(stderr, "bench_plan: %zu candidates x %zu points, ours and Embree in turn ...\n",
               candidates.size(), cloud.size());
  const auto [our_times, embree_times] = alternating_samples(
      o.repeat,
      [&] {
        return timed([&] { ours = cloud_station_coverage(cloud, candidates, weight, scan, {}); });
      },
      [&] {
        return timed([&] {
          embree_builds.seconds.push_back(embree.build(estimate.surfels));
          theirs = embree_matrix(embree, estimate, candidates, o.threads);
        });
      });

  std::size_t same = 0, seen_ours = 0, seen_theirs = 0;
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      const bool a = ours.seen(c, i), b = theirs.seen(c, i);
      same += a == b;
      seen_ours += a;
      seen_theirs += b;
    }
  }
  const SurfelStats& st = estimate.stats;
  std::printf("bench_plan: generated room, seed %llu, %u thread(s), %d runs\n",
              static_cast<unsigned long long>(o.seed), o.threads, o.repeat);
  std::printf("cloud    %s points of %s triangles; %s discs, %s spheres, radius median %.4g\n",
              grouped(cloud.size()).c_str(), grouped(room.mesh.face_count()).c_str(),
              grouped(st.oriented).c_str(), grouped(st.unoriented).c_str(), st.radius_median);
  std::printf("matrix   %s candidates (floor grid at %.2f m) x %s points = %s shadow rays\n",
              grouped(candidates.size()).c_str(), o.height, grouped(cloud.size()).c_str(),
              grouped(rays).c_str());
  std::printf("seen     ours %.4f, embree %.4f of all pairs; bits agree on %.5f%%\n",
              static_cast<double>(seen_ours) / static_cast<double>(rays),
              static_cast<double>(seen_theirs) / static_cast<double>(rays), percent(same, rays));
  std::printf("embree   %s, discs %s + spheres %s, build %.3f s (min)\n",
              EmbreeTracer::version().c_str(), grouped(embree.discs()).c_str(),
              grouped(embree.spheres()).c_str(), embree_builds.min());
  print_ratio("matrix", our_times, embree_times, rays);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return occlusion::bench::run_tool("bench_plan", kUsage, argc, argv, parse, run);
}
