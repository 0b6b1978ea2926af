// bench_moc [--triangles N] [--samples N] [--threads T] [--seed S] [--cli PATH]
//           [--repeat N]
//
// Times the mesh-occlusion hot path on a generated furnished room against
// Intel Embree, and the `occlusion -moc` command end to end. See README.md.

#include <malloc.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <json/json.h>

#include "bench_args.hpp"
#include "bench_common.hpp"
#include "child_process.hpp"
#include "embree_scene.hpp"
#include "moc_replay.hpp"
#include "occlusion/analysis/mesh_occlusion.hpp"
#include "occlusion/analysis/mesh_sampling.hpp"
#include "occlusion/analysis/viewpoints.hpp"
#include "occlusion/core/triangle_octree.hpp"
#include "occlusion/io/obj_writer.hpp"
#include "room_generator.hpp"

namespace {

using namespace occlusion;
using namespace occlusion::bench;
namespace fs = std::filesystem;

constexpr int kPattern = 7;
constexpr const char* kUsage =
    "usage: bench_moc [--triangles N] [--samples N] [--threads T] [--seed S] [--cli PATH]\n"
    "                 [--repeat N]\n";

struct Options {
  std::size_t triangles = 100'000;
  std::size_t samples = 100'000;
  unsigned threads = 2;
  std::uint64_t seed = 1;
  std::string cli;  // empty: <build dir>/occlusion
  // Traces of each tracer, and whole processes of each program, alternating;
  // the best counts.
  int repeat = kRepetitions;
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--triangles") {
      o.triangles = parse_unsigned(arg, flag_value(argc, argv, i));
    } else if (arg == "--samples") {
      o.samples = parse_unsigned(arg, flag_value(argc, argv, i));
    } else if (arg == "--threads") {
      o.threads = parse_threads(arg, flag_value(argc, argv, i));
    } else if (arg == "--seed") {
      o.seed = parse_unsigned(arg, flag_value(argc, argv, i));
    } else if (arg == "--repeat") {
      o.repeat = static_cast<int>(
          std::min<std::size_t>(1000, parse_unsigned(arg, flag_value(argc, argv, i))));
    } else if (arg == "--cli") {
      o.cli = flag_value(argc, argv, i);
    } else {
      throw UsageError("unknown argument '" + arg + "'");
    }
  }
  if (o.triangles == 0 || o.samples == 0 || o.threads == 0 || o.repeat == 0) {
    throw UsageError("--triangles, --samples, --threads and --repeat must be > 0");
  }
  return o;
}

int run(const Options& o) {
  const fs::path bench_dir = fs::read_symlink("/proc/self/exe").parent_path();
  const std::string cli = o.cli.empty() ? (bench_dir.parent_path() / "occlusion").string() : o.cli;
  const std::string room_path = (bench_dir / "bench_room.obj").string();

  auto start = std::chrono::steady_clock::now();
  const GeneratedRoom room = generate_room(o.triangles, o.seed);
  const double generate_seconds = seconds_since(start);
  const TriangleMesh& mesh = room.mesh;
  write_obj(room_path, mesh, "bench_moc room, seed " + std::to_string(o.seed));
  const double density = samples_per_unit_area_for(mesh, o.samples);

  // The CLI runs first, while this process is small: see child_process.hpp on ru_maxrss.
  malloc_trim(0);
  std::fprintf(stderr, "bench_moc: running %s -moc on %s and embree_job -moc, in turn ...\n",
               cli.c_str(), room_path.c_str());
  const auto [cli_run, embree_run] = run_job_and_embree_job(
      bench_dir, cli, "moc", room_path,
      {"--pattern", std::to_string(kPattern), "--samples-per-unit-area", exact(density),
       "--threads", std::to_string(o.threads), "--seed", std::to_string(o.seed)},
      o.repeat);

  const MeshSamples samples = sample_mesh(mesh, density, o.seed);
  Eigen::Vector3d lo, hi;
  mesh.bounds(lo, hi);
  const std::vector<Eigen::Vector3d> viewpoints = pattern_viewpoints(kPattern, lo, hi);
  MeshOcclusionOptions moc;  // the analysis' defaults, including its epsilon
  moc.samples_per_unit_area = density;
  moc.seed = o.seed;
  moc.threads = o.threads;
  const ShadowRays shadow = make_shadow_rays(samples, viewpoints, mesh_shadow_epsilon(mesh, moc));
  const std::size_t n = shadow.rays.size();

  std::fprintf(stderr, "bench_moc: our octree ...\n");
  std::optional<TriangleOctree> tree;
  const double our_build = best_of([&] {
    tree.reset();
    const auto t0 = std::chrono::steady_clock::now();
    tree.emplace(pack_triangles(mesh.triangles()));
    return seconds_since(t0);
  });
  std::fprintf(stderr, "bench_moc: embree ...\n");
  EmbreeScene embree(o.threads);
  const double embree_build = best_of([&] { return embree.build(mesh); });

  std::fprintf(stderr, "bench_moc: tracing, ours and embree in turn, %d times ...\n", o.repeat);
  std::vector<std::uint8_t> ours(n), theirs(n);
  const auto [our_trace, embree_trace] = best_of_alternating(
      o.repeat,
      [&] {
        const auto t0 = std::chrono::steady_clock::now();
        tree->occluded_batch(shadow.rays.data(), n, shadow.ignore.data(), ours.data(), o.threads,
                             BatchOrder::kAsGiven);
        return seconds_since(t0);
      },
      [&] {
        const auto t0 = std::chrono::steady_clock::now();
        embree.occluded(shadow.rays.data(), n, theirs.data(), o.threads);
        return seconds_since(t0);
      });

  std::fprintf(stderr, "bench_moc: compute_mesh_occlusion in process ...\n");
  start = std::chrono::steady_clock::now();
  const MeshOcclusionResult library = compute_mesh_occlusion(mesh, viewpoints, moc);
  const double library_seconds = seconds_since(start);

  std::size_t our_hits = 0, their_hits = 0, only_ours = 0, only_theirs = 0;
  for (std::size_t i = 0; i < n; ++i) {
    our_hits += ours[i];
    their_hits += theirs[i];
    only_ours += ours[i] && !theirs[i];
    only_theirs += theirs[i] && !ours[i];
  }
  const double agreement =
      1.0 - static_cast<double>(only_ours + only_theirs) / static_cast<double>(n);
  const auto percent = [n](std::size_t k) {
    return 100.0 * static_cast<double>(k) / static_cast<double>(n);
  };

  double area = 0.0;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) area += mesh.face_area(f);
  std::printf("bench_moc: furnished room, seed %llu, %u thread(s), best of %d\n",
              static_cast<unsigned long long>(o.seed), o.threads, kRepetitions);
  std::printf("scene    %s triangles, %s vertices, %zu groups, %.1f m^2 (generated in %.3f s)\n",
              grouped(mesh.face_count()).c_str(), grouped(mesh.vertices.size()).c_str(),
              mesh.group_names.size(), area, generate_seconds);
  std::printf("samples  %s at %.3f per m^2; pattern %d: %zu viewpoints; %s shadow rays\n\n",
              grouped(samples.size()).c_str(), density, kPattern, viewpoints.size(),
              grouped(n).c_str());
  std::printf("%-30s %10s %10s %12s %10s\n", "", "build (s)", "trace (s)", "rays/s", "occluded");
  std::printf("%-30s %10.4f %10.4f %10.2f M %9.3f%%\n", "ours   TriangleOctree", our_build,
              our_trace, static_cast<double>(n) / our_trace / 1e6, percent(our_hits));
  std::printf("%-30s %10.4f %10.4f %10.2f M %9.3f%%\n",
              ("embree " + EmbreeScene::version() + " rtcOccluded1").c_str(), embree_build,
              embree_trace, static_cast<double>(n) / embree_trace / 1e6, percent(their_hits));
  const OctreeStats& s = tree->stats();
  std::printf("\noctree   %s inner nodes, %s leaves, depth %d, largest leaf %zu, %.1f MiB\n",
              grouped(s.inner_nodes).c_str(), grouped(s.leaves).c_str(), s.depth, s.largest_leaf,
              mib(s.memory_bytes));
  std::printf(
      "flags    agree on %.4f%% of rays (goal > 99.9%%): %zu occluded only for us, %zu only for "
      "Embree\n",
      100.0 * agreement, only_ours, only_theirs);
  std::printf("level    ours %.6f, embree %.6f, compute_mesh_occlusion %.6f",
              occlusion_level_from_flags(mesh, samples, shadow, ours.data()),
              occlusion_level_from_flags(mesh, samples, shadow, theirs.data()),
              library.occlusion_level);
  if (cli_run.json.isMember("occlusion_level")) {
    std::printf(", CLI %.6f", cli_run.json["occlusion_level"].asDouble());
  }
  if (embree_run.json.isMember("occlusion_level")) {
    std::printf(", Embree program %.6f", embree_run.json["occlusion_level"].asDouble());
  }
  std::printf(
      "\nlibrary  compute_mesh_occlusion %.3f s (sampling %.3f, build %.3f, trace %.3f)\n\n",
      library_seconds, library.timings.sampling_seconds, library.timings.build_seconds,
      library.timings.trace_seconds);

  std::printf("ours/embree throughput: %.2f\n", embree_trace / our_trace);
  const ChildResult& c = cli_run.best;
  if (c.exit_code != 0) {
    std::printf("moc end-to-end: FAILED (exit %d)\n%s", c.exit_code, c.err.c_str());
    return 1;
  }
  std::printf("moc end-to-end: %.2f s (goal < 1 s), peak RSS: %.0f MB\n", c.wall_seconds,
              static_cast<double>(c.peak_rss_bytes) / 1e6);
  if (!print_whole_process("moc", cli_run, embree_run)) return 1;
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return occlusion::bench::run_tool("bench_moc", kUsage, argc, argv, parse, run);
}
