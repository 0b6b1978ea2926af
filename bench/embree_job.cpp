// embree_job -moc MESH [--pattern N] [--samples-per-unit-area X] [--seed S] [--threads T]
//            [--out DIR]
// embree_job -poc CLOUD [--num-vp N] [--num-rays-per-vp N] [--primitive disc|sphere]
//            [--point-radius R] [--seed S] [--threads T] [--out DIR]
// embree_job -fscan CLOUD [--pattern N | --stations] [--primitive disc|sphere]
//            [--point-radius R] [--threads T] [--out DIR]
//
// `occlusion -moc`, `-poc` and `-fscan` as a program built on Intel Embree
// would do them: the same readers, viewpoints, samples, surfels (points are discs
// unless --primitive sphere, as for the CLI) and rays, Embree's BVH
// and rtcOccluded1 / rtcIntersect1 in place of our octree, the same results
// written to DIR. bench_moc and bench_poc time it against the CLI, whole
// process against whole process (issue 17). Prints one JSON object on stdout:
// the result and the timings of each stage.

#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <json/json.h>

#include "bench_args.hpp"
#include "bench_common.hpp"
#include "cloud_replay.hpp"
#include "embree_points.hpp"
#include "embree_scene.hpp"
#include "moc_replay.hpp"
#include "occlusion/analysis/cloud_occlusion.hpp"
#include "occlusion/analysis/mesh_occlusion.hpp"
#include "occlusion/analysis/mesh_sampling.hpp"
#include "occlusion/analysis/scan.hpp"
#include "occlusion/analysis/surfel_estimation.hpp"
#include "occlusion/analysis/viewpoints.hpp"
#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/face_table.hpp"
#include "occlusion/io/mesh_reader.hpp"
#include "occlusion/io/ply_mesh_writer.hpp"

namespace {

using namespace occlusion;
using namespace occlusion::bench;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr const char* kUsage =
    "usage: embree_job -moc MESH [--pattern N] [--samples-per-unit-area X] [--seed S]\n"
    "                  [--threads T] [--out DIR]\n"
    "       embree_job -poc CLOUD [--num-vp N] [--num-rays-per-vp N] [--primitive disc|sphere]\n"
    "                  [--point-radius R] [--seed S] [--threads T] [--out DIR]\n"
    "       embree_job -fscan CLOUD [--pattern N | --stations] [--primitive disc|sphere]\n"
    "                  [--point-radius R] [--threads T] [--out DIR]\n";

// The CLI's defaults for the settings the benches pass.
struct Options {
  std::string job;  // moc, poc or fscan
  std::string input;
  int pattern = 7;
  bool stations = false;  // -fscan from the cloud's stations (the CLI's default when it has any)
  double samples_per_unit_area = 100.0;
  std::size_t num_vp = 9;
  std::size_t num_rays_per_vp = 30'000;
  double point_radius = 0.01;
  bool point_radius_given = false;  // discs: a fixed radius instead of estimate_surfels'
  std::string primitive = "disc";   // or sphere
  std::uint64_t seed = 0;
  unsigned threads = 2;
  std::string out;  // empty: write nothing
};

double parse_positive(const std::string& flag, const std::string& text) {
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !(value > 0.0) || !std::isfinite(value)) {
    throw UsageError(flag + " expects a positive number, got '" + text + "'");
  }
  return value;
}

Options parse(int argc, char** argv) {
  if (argc < 3) throw UsageError("a job (-moc, -poc or -fscan) and an input are needed");
  Options o;
  const std::string job = argv[1];
  if (job != "-moc" && job != "-poc" && job != "-fscan") {
    throw UsageError("unknown job '" + job + "'");
  }
  o.job = job.substr(1);
  o.input = argv[2];
  for (int i = 3; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--pattern" && o.job != "poc") {
      o.pattern = static_cast<int>(parse_unsigned(arg, flag_value(argc, argv, i)));
      if (o.pattern < 1 || o.pattern > 7) throw UsageError("--pattern must be 1..7");
    } else if (arg == "--stations" && o.job == "fscan") {
      o.stations = true;
    } else if (arg == "--samples-per-unit-area" && o.job == "moc") {
      o.samples_per_unit_area = parse_positive(arg, flag_value(argc, argv, i));
    } else if (arg == "--num-vp" && o.job == "poc") {
      o.num_vp = parse_unsigned(arg, flag_value(argc, argv, i));
    } else if (arg == "--num-rays-per-vp" && o.job == "poc") {
      o.num_rays_per_vp = parse_unsigned(arg, flag_value(argc, argv, i));
    } else if (arg == "--point-radius" && o.job != "moc") {
      o.point_radius = parse_positive(arg, flag_value(argc, argv, i));
      o.point_radius_given = true;
    } else if (arg == "--primitive" && o.job != "moc") {
      o.primitive = flag_value(argc, argv, i);
      if (o.primitive != "disc" && o.primitive != "sphere") {
        throw UsageError("--primitive must be disc or sphere, got '" + o.primitive + "'");
      }
    } else if (arg == "--seed" && o.job != "fscan") {
      o.seed = parse_unsigned(arg, flag_value(argc, argv, i));
    } else if (arg == "--threads") {
      o.threads = parse_threads(arg, flag_value(argc, argv, i));
    } else if (arg == "--out") {
      o.out = flag_value(argc, argv, i);
    } else {
      throw UsageError("unknown argument '" + arg + "' for -" + o.job);
    }
  }
  if (o.num_vp == 0 || o.num_rays_per_vp == 0 || o.threads == 0) {
    throw UsageError("--num-vp, --num-rays-per-vp and --threads must be > 0");
  }
  return o;
}

// DIR/<input's stem><suffix>, the CLI's naming.
std::string output_path(const Options& o, const std::string& suffix) {
  return (fs::path(o.out) / fs::path(o.input).stem()).string() + suffix;
}

struct Stages {
  Clock::time_point start = Clock::now();
  Json::Value timings{Json::objectValue};

  // Records the seconds since the last mark as `<name>_seconds`.
  void mark(const char* name) {
    const Clock::time_point now = Clock::now();
    timings[std::string(name) + "_seconds"] = std::chrono::duration<double>(now - last).count();
    last = now;
  }

 private:
  Clock::time_point last = start;
};

void write_json(const std::string& path, const Json::Value& json) {
  write_file_atomically(path, [&](std::ostream& out) { out << json << '\n'; });
}

// Per-face visible fractions (.moc.ply, .moc.csv, .moc.json), as `occlusion -moc --out`.
Json::Value run_moc(const Options& o, Stages& stages) {
  const TriangleMesh mesh = read_mesh(o.input);
  stages.mark("load");

  MeshOcclusionOptions options;
  options.samples_per_unit_area = o.samples_per_unit_area;
  options.seed = o.seed;
  const MeshSamples samples = sample_mesh(mesh, o.samples_per_unit_area, o.seed);
  Eigen::Vector3d lo, hi;
  mesh.bounds(lo, hi);
  const std::vector<Eigen::Vector3d> viewpoints = pattern_viewpoints(o.pattern, lo, hi);
  const double epsilon = mesh_shadow_epsilon(mesh, options);
  stages.mark("sampling");

  EmbreeScene embree(o.threads);
  embree.build(mesh);
  stages.mark("build");

  // Viewpoint-major, as compute_mesh_occlusion casts them; seen is sample-major.
  const std::size_t count = samples.size() * viewpoints.size();
  std::vector<std::uint8_t> occluded(count);
  embree.occluded_made(
      count,
      [&](std::size_t i, Ray& ray) {
        const std::size_t v = i / samples.size(), s = i % samples.size();
        return mesh_shadow_ray(samples.points[s], viewpoints[v], epsilon, ray);
      },
      occluded.data(), o.threads);
  std::vector<std::uint8_t> seen(count);
  for (std::size_t v = 0; v < viewpoints.size(); ++v) {
    for (std::size_t s = 0; s < samples.size(); ++s) {
      seen[s * viewpoints.size() + v] = occluded[v * samples.size() + s] ? 0 : 1;
    }
  }
  const std::vector<double> fractions =
      face_visible_fractions(mesh, samples, viewpoints.size(), seen);
  Json::Value json(Json::objectValue);
  json["job"] = "mesh_occlusion";
  json["input"] = o.input;
  json["occlusion_level"] = occlusion_level_of_faces(mesh, fractions);
  json["faces"] = Json::UInt64(mesh.face_count());
  json["samples"] = Json::UInt64(samples.size());
  json["rays"] = Json::UInt64(count);
  stages.mark("trace");

  if (!o.out.empty()) {
    ensure_directory(o.out);
    const std::vector<float> visible_fraction(fractions.begin(), fractions.end());
    write_mesh_ply(output_path(o, ".moc.ply"), mesh, visible_fraction, "visible_fraction");
    std::vector<std::size_t> face_samples(mesh.face_count());
    for (std::size_t f = 0; f < face_samples.size(); ++f) face_samples[f] = samples.count_on(f);
    write_face_table(output_path(o, ".moc.csv"), mesh, face_samples, visible_fraction);
    write_json(output_path(o, ".moc.json"), json);
  }
  stages.mark("write");
  return json;
}

// What -poc and -fscan start with: the cloud read, its points as Embree
// spheres or as surfels (estimate_surfels with the CLI's defaults, or its fixed
// radius when --point-radius is given) in Embree discs, and its box, which the
// viewpoints are placed in.
struct CloudScene {
  PointCloud cloud;
  std::unique_ptr<EmbreePoints> spheres;
  std::unique_ptr<EmbreeDiscs> discs;
  SurfelEstimate surfels;  // discs only
  Eigen::Vector3d lo, hi;

  void intersect(const std::vector<Ray>& rays, std::vector<std::optional<Hit>>& hits,
                 unsigned threads) const {
    if (discs) {
      discs->intersect(rays.data(), rays.size(), hits.data(), threads);
    } else {
      spheres->intersect(rays.data(), rays.size(), hits.data(), threads);
    }
  }
  const EmbreeTracer& tracer() const {
    return discs ? static_cast<const EmbreeTracer&>(*discs) : *spheres;
  }
};

CloudScene load_cloud_scene(const Options& o, Stages& stages) {
  CloudScene scene;
  scene.cloud = read_cloud(o.input);
  stages.mark("load");
  if (o.primitive == "disc") {
    SurfelOptions options;
    options.fixed_radius = o.point_radius_given ? o.point_radius : 0.0;
    options.threads = o.threads;
    scene.surfels = estimate_surfels(scene.cloud, options);
    stages.mark("surfel");  // the CLI's name for the stage
    scene.discs = std::make_unique<EmbreeDiscs>(o.threads);
    scene.discs->build(scene.surfels.surfels);
  } else {
    scene.spheres = std::make_unique<EmbreePoints>(o.threads);
    scene.spheres->build(make_spheres(scene.cloud.positions, static_cast<float>(o.point_radius)));
  }
  stages.mark("build");
  Eigen::Vector3f lo, hi;
  scene.cloud.bounds(lo, hi);
  scene.lo = lo.cast<double>();
  scene.hi = hi.cast<double>();
  return scene;
}

// Closest hits of rays from a grid of viewpoints; the rays that escape
// (.poc.escapes.csv, .poc.json), as `occlusion -poc --out`.
Json::Value run_poc(const Options& o, Stages& stages) {
  const CloudScene scene = load_cloud_scene(o, stages);
  const PointCloud& cloud = scene.cloud;
  const std::vector<Eigen::Vector3d> viewpoints = grid_viewpoints(o.num_vp, scene.lo, scene.hi);
  CloudOcclusionOptions options;
  options.num_rays_per_vp = o.num_rays_per_vp;
  options.seed = o.seed;
  const std::vector<Ray> rays = make_poc_rays(viewpoints, options);
  std::vector<std::optional<Hit>> hits(rays.size());
  scene.intersect(rays, hits, o.threads);
  std::vector<std::uint8_t> hit(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) hit[i] = hits[i].has_value();
  Json::Value json(Json::objectValue);
  json["job"] = "cloud_occlusion";
  json["input"] = o.input;
  json["occlusion_level"] = poc_level_from_hits(hit.data(), hit.size());
  json["points"] = Json::UInt64(cloud.size());
  json["rays"] = Json::UInt64(rays.size());
  stages.mark("trace");

  if (!o.out.empty()) {
    ensure_directory(o.out);
    write_file_atomically(output_path(o, ".poc.escapes.csv"), [&](std::ostream& out) {
      out << "viewpoint,dx,dy,dz\n";
      out.precision(7);
      for (std::size_t i = 0; i < rays.size(); ++i) {
        if (hit[i]) continue;
        const Eigen::Vector3f& d = rays[i].direction;
        out << i / o.num_rays_per_vp << ',' << d.x() << ',' << d.y() << ',' << d.z() << '\n';
      }
    });
    write_json(output_path(o, ".poc.json"), json);
  }
  stages.mark("write");
  return json;
}

// Shadow rays from a pattern of viewpoints to every point; the points seen
// and every point with its count of viewpoints (.scan.ply, .scan_full.ply,
// .fscan.json), as `occlusion -fscan --out`.
Json::Value run_fscan(const Options& o, Stages& stages) {
  const CloudScene scene = load_cloud_scene(o, stages);
  const PointCloud& cloud = scene.cloud;
  std::vector<Eigen::Vector3d> viewpoints;
  if (o.stations) {
    for (const Station& station : cloud.stations) viewpoints.push_back(station.frame.origin);
    if (viewpoints.empty()) throw UsageError("--stations: " + o.input + " records no station");
  } else {
    viewpoints = pattern_viewpoints(o.pattern, scene.lo, scene.hi);
  }
  ScanOptions options;
  options.point_radius = o.point_radius;
  const std::size_t points = cloud.size();
  std::vector<std::uint8_t> blocked(points * viewpoints.size());
  const SurfelEstimate& model = scene.surfels;
  const double near_viewpoint = 2.0 * model.stats.radius_median;
  scene.tracer().occluded_made(
      blocked.size(),
      [&](std::size_t i, Ray& ray) {
        const std::size_t v = i / points, p = i % points;
        ray = scene.discs ? scan_surfel_ray(viewpoints[v], model.surfels[p], model.thickness[p],
                                            near_viewpoint)
                          : scan_shadow_ray(viewpoints[v], cloud.positions[p], options);
        return true;
      },
      blocked.data(), o.threads);
  ScalarField visible_count{"visible_count", std::vector<float>(points, 0.0f), true};
  for (std::size_t i = 0; i < blocked.size(); ++i) {
    visible_count.values[i % points] += blocked[i] ? 0.0f : 1.0f;
  }
  std::vector<bool> seen(points);
  std::size_t visible_points = 0;
  for (std::size_t i = 0; i < points; ++i) {
    seen[i] = visible_count.values[i] > 0.0f;
    visible_points += seen[i] ? 1 : 0;
  }
  Json::Value json(Json::objectValue);
  json["job"] = "scan";
  json["input"] = o.input;
  json["visible_fraction"] =
      points > 0 ? static_cast<double>(visible_points) / static_cast<double>(points) : 0.0;
  json["points"] = Json::UInt64(points);
  json["visible_points"] = Json::UInt64(visible_points);
  json["rays"] = Json::UInt64(blocked.size());
  stages.mark("trace");

  if (!o.out.empty()) {
    ensure_directory(o.out);
    write_cloud(output_path(o, ".scan.ply"), cloud.subset(seen));
    write_cloud(output_path(o, ".scan_full.ply"), cloud, {visible_count});
    write_json(output_path(o, ".fscan.json"), json);
  }
  stages.mark("write");
  return json;
}

int run(const Options& options) {
  Stages stages;
  Json::Value json = options.job == "moc"   ? run_moc(options, stages)
                     : options.job == "poc" ? run_poc(options, stages)
                                            : run_fscan(options, stages);
  stages.timings["total_seconds"] = seconds_since(stages.start);
  json["timings"] = stages.timings;
  json["tracer"] = "embree " + EmbreeTracer::version();
  std::cout << json << std::endl;
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return run_tool("embree_job", kUsage, argc, argv, parse, run);
}
