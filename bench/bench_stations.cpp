// bench_stations [--points-per-station M] [--stations N,N,...] [--layout rooms|hall]
//                [--triangles N] [--threads T] [--seed S] [--repeat N] [--cli PATH]
//                [--no-embree] [--full]
//
// -fscan over multi-station scenes (issue 42). Layout `rooms` (the default):
// a building of N closed rooms in a row (the generated furnished room,
// 8 x 6 x 3 m, 0.5 m apart), each scanned from one station at its centre
// 1.5 m up, M points a station (the room's surfaces sampled once, the same
// samples in every room). Layout `hall`: one room sampled at N x M points,
// the N stations on its long axis 1.5 m up (every station sees most of the
// room: the rays are long), each point given to its nearest station. The
// scene is written as one binary PLY with its stations and each point's
// station. For each N,
// `occlusion -fscan` (discs, its defaults: the cloud's stations are the
// viewpoints) and `embree_job -fscan --stations` (the same surfels, rays and
// stations on Embree) run in turn as whole processes: wall time, the trace,
// time per (point x station), peak RSS and RSS per point. -fscan traces
// every point from every station, N^2 M rays at N stations of M points: the
// time per point per station stays flat when the time grows linearly with
// the rays, the RSS per point when the memory grows linearly with the points.
// --full is the scale: 20 stations x 5,000,000 points. See README.md.

#include <malloc.h>

#include <cstdio>
#include <filesystem>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "bench_args.hpp"
#include "bench_common.hpp"
#include "cloud_replay.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "room_generator.hpp"

namespace {

using namespace occlusion;
using namespace occlusion::bench;
namespace fs = std::filesystem;

constexpr const char* kUsage =
    "usage: bench_stations [--points-per-station M] [--stations N,N,...] [--layout rooms|hall]\n"
    "                      [--triangles N] [--threads T] [--seed S] [--repeat N] [--cli PATH]\n"
    "                      [--no-embree] [--full]\n";

constexpr double kRoomGap = 0.5;  // between neighbouring rooms, metres

struct Options {
  std::size_t points_per_station = 100'000;
  std::vector<std::size_t> stations{1, 2, 5, 10, 20};
  std::string layout = "rooms";
  std::size_t triangles = 20'000;
  unsigned threads = 2;
  std::uint64_t seed = 1;
  int repeat = 1;
  std::string cli;
  bool embree = true;
};

std::vector<std::size_t> parse_list(const std::string& flag, const std::string& text) {
  std::vector<std::size_t> values;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    const std::size_t n = parse_unsigned(flag, item);
    if (n == 0 || n > 1000) throw UsageError(flag + ": station counts are 1..1000");
    values.push_back(n);
  }
  if (values.empty()) throw UsageError(flag + " needs at least one count");
  return values;
}

Options parse(int argc, char** argv) {
  Options o;
  bool full = false, points_given = false, stations_given = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--points-per-station") {
      o.points_per_station = parse_unsigned(arg, flag_value(argc, argv, i));
      points_given = true;
    } else if (arg == "--stations") {
      o.stations = parse_list(arg, flag_value(argc, argv, i));
      stations_given = true;
    } else if (arg == "--layout") {
      o.layout = flag_value(argc, argv, i);
      if (o.layout != "rooms" && o.layout != "hall") {
        throw UsageError("--layout must be rooms or hall, got '" + o.layout + "'");
      }
    } else if (arg == "--triangles") {
      o.triangles = parse_unsigned(arg, flag_value(argc, argv, i));
    } else if (arg == "--threads") {
      o.threads = parse_threads(arg, flag_value(argc, argv, i));
    } else if (arg == "--seed") {
      o.seed = parse_unsigned(arg, flag_value(argc, argv, i));
    } else if (arg == "--repeat") {
      o.repeat = static_cast<int>(parse_unsigned(arg, flag_value(argc, argv, i)));
      if (o.repeat < 1) throw UsageError("--repeat must be at least 1");
    } else if (arg == "--cli") {
      o.cli = flag_value(argc, argv, i);
    } else if (arg == "--no-embree") {
      o.embree = false;
    } else if (arg == "--full") {
      full = true;
    } else {
      throw UsageError("unknown argument '" + arg + "'");
    }
  }
  if (full) {
    if (!points_given) o.points_per_station = 5'000'000;
    if (!stations_given) o.stations = {20};
  }
  if (o.points_per_station == 0 || o.threads == 0) {
    throw UsageError("--points-per-station and --threads must be > 0");
  }
  return o;
}

// N rooms along x, each holding the same M samples and its station.
PointCloud building(const PointCloud& room, std::size_t rooms) {
  PointCloud cloud;
  const std::size_t m = room.size();
  cloud.positions.reserve(m * rooms);
  cloud.station_ids.reserve(m * rooms);
  for (std::size_t r = 0; r < rooms; ++r) {
    const Eigen::Vector3f offset(static_cast<float>(r * (kRoomSize.x() + kRoomGap)), 0.0f, 0.0f);
    for (const auto& p : room.positions) cloud.positions.push_back(p + offset);
    cloud.station_ids.insert(cloud.station_ids.end(), m, static_cast<std::int32_t>(r));
    Station station;
    station.name = "room_" + std::to_string(r + 1);
    station.frame.origin =
        Eigen::Vector3d(r * (kRoomSize.x() + kRoomGap) + kRoomSize.x() / 2, kRoomSize.y() / 2, 1.5);
    cloud.stations.push_back(station);
  }
  return cloud;
}

// `count` of the cloud's points spread evenly over its order (sample_mesh
// gives them face by face: a prefix would drop the last faces).
PointCloud evenly(const PointCloud& cloud, std::size_t count) {
  PointCloud kept;
  kept.positions.reserve(count);
  for (std::size_t k = 0; k < count; ++k) {
    kept.positions.push_back(cloud.positions[k * cloud.size() / count]);
  }
  return kept;
}

// One room of N x M samples, the N stations along its long axis, each point
// with its nearest station.
PointCloud hall(const PointCloud& samples, std::size_t stations) {
  PointCloud cloud = samples;
  for (std::size_t k = 0; k < stations; ++k) {
    Station station;
    station.name = "hall_" + std::to_string(k + 1);
    const double along = (static_cast<double>(k) + 0.5) / static_cast<double>(stations);
    station.frame.origin =
        Eigen::Vector3d(1.0 + along * (kRoomSize.x() - 2.0), kRoomSize.y() / 2, 1.5);
    cloud.stations.push_back(station);
  }
  cloud.station_ids.resize(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Eigen::Vector3d p = cloud.positions[i].cast<double>();
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < stations; ++k) {
      const double d = (p - cloud.stations[k].frame.origin).squaredNorm();
      if (d < nearest) {
        nearest = d;
        cloud.station_ids[i] = static_cast<std::int32_t>(k);
      }
    }
  }
  return cloud;
}

struct Row {
  std::size_t stations = 0, points = 0;
  CliRun ours, embree;
};

double timing(const CliRun& run, const char* key) {
  return run.json["timings"].get(key, 0.0).asDouble();
}

void print_rows(const std::vector<Row>& rows) {
  std::printf("\n%4s %11s %13s | %-50s | %-34s | %s\n", "N", "points", "rays",
              "ours: wall, trace s; ns/(pt x st) trace, wall; RSS", "embree: wall, trace s; RSS",
              "embree/ours trace, wall");
  for (const Row& row : rows) {
    const double rays = static_cast<double>(row.points) * static_cast<double>(row.stations);
    const ChildResult& o = row.ours.best;
    if (o.exit_code != 0) {
      std::printf("%4zu %11s FAILED (exit %d)\n%s", row.stations, grouped(row.points).c_str(),
                  o.exit_code, o.err.c_str());
      continue;
    }
    const double trace = timing(row.ours, "trace_seconds");
    std::printf("%4zu %11s %13s | %7.2f %7.2f; %6.1f %6.1f; %6.0f MB (%5.0f B/pt) |", row.stations,
                grouped(row.points).c_str(), grouped(static_cast<std::size_t>(rays)).c_str(),
                o.wall_seconds, trace, 1e9 * trace / rays, 1e9 * o.wall_seconds / rays,
                static_cast<double>(o.peak_rss_bytes) / 1e6,
                static_cast<double>(o.peak_rss_bytes) / static_cast<double>(row.points));
    const ChildResult& e = row.embree.best;
    if (row.embree.json.isNull() || e.exit_code != 0) {
      std::printf(" %-34s |\n", e.exit_code == -1 ? "not run" : "FAILED");
      continue;
    }
    const double embree_trace = timing(row.embree, "trace_seconds");
    std::printf(" %7.2f %7.2f; %6.0f MB            | %5.2f %5.2f\n", e.wall_seconds, embree_trace,
                static_cast<double>(e.peak_rss_bytes) / 1e6, embree_trace / trace,
                e.wall_seconds / o.wall_seconds);
  }
}

int run(const Options& o) {
  const fs::path bench_dir = fs::read_symlink("/proc/self/exe").parent_path();
  const std::string cli = o.cli.empty() ? (bench_dir.parent_path() / "occlusion").string() : o.cli;
  std::vector<Row> rows;
  for (const std::size_t n : o.stations) {
    Row row;
    row.stations = n;
    const std::string path =
        (bench_dir / ("bench_stations_" + std::to_string(n) + ".ply")).string();
    {
      // Generated, written and dropped before the programs run (child_process.hpp on ru_maxrss).
      const GeneratedRoom room = generate_room(o.triangles, o.seed);
      const std::size_t sampled =
          o.layout == "hall" ? n * o.points_per_station : o.points_per_station;
      const PointCloud samples = evenly(sample_point_cloud(room.mesh, sampled, o.seed), sampled);
      const PointCloud cloud = o.layout == "hall" ? hall(samples, n) : building(samples, n);
      row.points = cloud.size();
      write_cloud(path, cloud, {}, CloudFormat::kPlyBinary);
    }
    malloc_trim(0);
    const std::string threads = std::to_string(o.threads);
    const std::string out = (bench_dir / "bench_stations_out").string();
    std::fprintf(stderr, "bench_stations: %zu station(s), %s points: -fscan%s ...\n", n,
                 grouped(row.points).c_str(), o.embree ? " and embree_job -fscan, in turn" : "");
    const std::vector<std::string> ours = {cli,         "-fscan", path,    "--json",
                                           "--threads", threads,  "--out", out + "/ours"};
    std::vector<std::string> theirs;
    if (o.embree) {
      theirs = {(bench_dir / "embree_job").string(),
                "-fscan",
                path,
                "--stations",
                "--threads",
                threads,
                "--out",
                out + "/embree"};
    }
    auto [ours_run, embree_run] =
        run_clis_alternating(ours, (bench_dir / "bench_stations_cli").string(), theirs,
                             (bench_dir / "bench_stations_embree_job").string(), o.repeat);
    row.ours = std::move(ours_run);
    row.embree = std::move(embree_run);
    if (!row.ours.json.isNull()) {
      const Json::Value& j = row.ours.json;
      std::printf("N %zu: visible %.4f (embree %.4f), seen by several %.4f, by none %.4f; %s\n", n,
                  j["visible_fraction"].asDouble(),
                  row.embree.json.get("visible_fraction", -1.0).asDouble(),
                  j["seen_by_several_fraction"].asDouble(), j["seen_by_none_fraction"].asDouble(),
                  stage_timings(j).c_str());
    }
    rows.push_back(std::move(row));
    fs::remove(path);
  }
  print_rows(rows);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return occlusion::bench::run_tool("bench_stations", kUsage, argc, argv, parse, run);
}
