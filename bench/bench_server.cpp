// bench_server: the WebSocket server under load, over loopback only.
//
//   bench_server [--points N] [--clients LIST] [--seconds S] [--workers W]
//
// Starts `occlusion serve` in-process on 127.0.0.1 (an ephemeral port) over a
// scratch data directory holding one generated cloud of N points (default
// 1,000,000, binary PLY with colours and labels), then measures:
//   - requests per second of small commands (ping, list_files), with 1, 4 and
//     16 clients each sending one request after the other for S seconds;
//   - the time to stream the cloud: `load` from request to result, cold (file
//     read, encoded, cached) and warm (from the cache: pure streaming), best of 3;
//   - the time to upload the same file as a browser would (announce + one binary
//     message) until the server has read, stored and streamed it back;
//   - the live station (`station_view`): the first request, which builds the
//     disc model and its octree, then the median over 20 positions walking
//     across the room of the server's trace time and of the round trip (the
//     per-point frame included): the viewer's latency per dragged position.

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "bench_args.hpp"
#include "bench_common.hpp"
#include "occlusion/core/random.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/server/binary_frame.hpp"
#include "occlusion/server/blocking_client.hpp"
#include "occlusion/server/server.hpp"

namespace {

namespace fs = std::filesystem;
using occlusion::bench::grouped;
using occlusion::bench::seconds_since;
using occlusion::server::BlockingClient;
using Clock = std::chrono::steady_clock;
using Millis = std::chrono::milliseconds;

struct Options {
  std::size_t points = 1'000'000;
  std::vector<unsigned> clients = {1, 4, 16};
  double seconds = 2.0;
  unsigned workers = 2;
};

Options parse(int argc, char** argv) {
  using occlusion::bench::flag_value;
  using occlusion::bench::parse_unsigned;
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--points") {
      options.points = parse_unsigned(flag, flag_value(argc, argv, i));
    } else if (flag == "--seconds") {
      options.seconds = static_cast<double>(parse_unsigned(flag, flag_value(argc, argv, i)));
    } else if (flag == "--workers") {
      options.workers = static_cast<unsigned>(parse_unsigned(flag, flag_value(argc, argv, i)));
    } else if (flag == "--clients") {
      options.clients.clear();
      std::istringstream list(flag_value(argc, argv, i));
      for (std::string item; std::getline(list, item, ',');) {
        options.clients.push_back(static_cast<unsigned>(parse_unsigned(flag, item)));
      }
    } else {
      throw occlusion::bench::UsageError(
          "usage: bench_server [--points N] [--clients 1,4,16] [--seconds S] [--workers W]");
    }
  }
  return options;
}

// Points on the six faces of a 10 x 8 x 3 m room, coloured and labelled.
occlusion::PointCloud room_cloud(std::size_t n) {
  occlusion::PointCloud cloud;
  occlusion::Rng random(42);
  cloud.positions.reserve(n);
  cloud.colours.reserve(n);
  cloud.labels.reserve(n);
  cloud.class_names = occlusion::s3dis_class_names();
  for (std::size_t i = 0; i < n; ++i) {
    const int face = static_cast<int>(i % 6);
    const float u = static_cast<float>(random.uniform()), v = static_cast<float>(random.uniform());
    Eigen::Vector3f p;
    switch (face) {
      case 0:
        p = {10 * u, 8 * v, 0};
        break;
      case 1:
        p = {10 * u, 8 * v, 3};
        break;
      case 2:
        p = {10 * u, 0, 3 * v};
        break;
      case 3:
        p = {10 * u, 8, 3 * v};
        break;
      case 4:
        p = {0, 8 * u, 3 * v};
        break;
      default:
        p = {10, 8 * u, 3 * v};
        break;
    }
    cloud.positions.push_back(p);
    cloud.colours.push_back({static_cast<std::uint8_t>(40 * face), 128, 200});
    cloud.labels.push_back(face < 2 ? face : 2);
  }
  return cloud;
}

// Small-command round trips per second with `clients` clients in parallel.
double requests_per_second(std::uint16_t port, unsigned clients, const std::string& command,
                           double seconds) {
  std::atomic<std::uint64_t> done{0};
  std::atomic<bool> failed{false};
  std::vector<std::thread> threads;
  const auto start = Clock::now();
  for (unsigned c = 0; c < clients; ++c) {
    threads.emplace_back([&] {
      BlockingClient client("127.0.0.1", port);
      for (std::uint32_t id = 0; seconds_since(start) < seconds; ++id) {
        if (!client.request(id, command, Json::Value(Json::objectValue), Millis(10000)).ok()) {
          failed = true;
          return;
        }
        ++done;
      }
    });
  }
  for (auto& thread : threads) thread.join();
  if (failed) std::fprintf(stderr, "bench_server: a %s request failed\n", command.c_str());
  return static_cast<double>(done.load()) / seconds_since(start);
}

struct Streamed {
  double seconds = 0.0;
  std::size_t bytes = 0;
  bool cached = false;
};

Streamed load(BlockingClient& client, std::uint32_t id, const std::string& path) {
  Json::Value params(Json::objectValue);
  params["path"] = path;
  const auto start = Clock::now();
  const occlusion::server::Reply reply = client.request(id, "load", params, Millis(120000));
  Streamed streamed;
  streamed.seconds = seconds_since(start);
  if (!reply.ok()) throw std::runtime_error("load failed: " + reply.final.toStyledString());
  for (const auto& frame : reply.frames) streamed.bytes += frame.size();
  streamed.cached = reply.final["result"]["cached"].asBool();
  return streamed;
}

struct LiveTimes {
  double first = 0.0;         // round trip of the request that built the model
  double trace_median = 0.0;  // the server's trace time, median of the later ones
  double round_trip_median = 0.0;
  std::size_t visible = 0;  // points seen from the last position
};

LiveTimes live_station(BlockingClient& client, std::uint32_t first_id) {
  const auto request = [&](std::uint32_t id, double x) {
    Json::Value params(Json::objectValue);
    params["path"] = "cloud.ply";
    Json::Value position(Json::arrayValue);
    for (double value : {x, 4.0, 1.5}) position.append(value);
    params["position"] = position;
    const auto start = Clock::now();
    const occlusion::server::Reply reply =
        client.request(id, "station_view", params, Millis(300000));
    const double seconds = seconds_since(start);
    if (!reply.ok())
      throw std::runtime_error("station_view failed: " + reply.final.toStyledString());
    return std::make_pair(seconds, reply.final["result"]);
  };
  LiveTimes times;
  times.first = request(first_id, 5.0).first;
  std::vector<double> traces, trips;
  for (std::uint32_t k = 0; k < 20; ++k) {
    const auto [seconds, result] = request(first_id + 1 + k, 1.0 + 0.4 * k);
    trips.push_back(seconds);
    traces.push_back(result["trace_seconds"].asDouble());
    times.visible = result["visible_points"].asUInt64();
  }
  const auto median = [](std::vector<double> values) {
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    return values[values.size() / 2];
  };
  times.trace_median = median(traces);
  times.round_trip_median = median(trips);
  return times;
}

double upload(BlockingClient& client, std::uint32_t id, const std::string& bytes) {
  Json::Value params(Json::objectValue);
  params["name"] = "bench_upload.ply";
  params["size"] = Json::UInt64(bytes.size());
  occlusion::server::FrameHeader header;
  header.kind = occlusion::server::FrameKind::kUpload;
  header.request_id = id;
  header.count = bytes.size();
  std::string message = occlusion::server::encode_frame(header, bytes.data(), bytes.size()).message;
  const auto start = Clock::now();
  client.send_request(id, "upload", params);
  client.send_binary(std::move(message));
  const occlusion::server::Reply reply = client.collect(id, Millis(120000));
  if (!reply.ok()) throw std::runtime_error("upload failed: " + reply.final.toStyledString());
  return seconds_since(start);
}

}  // namespace

int main(int argc, char** argv) try {
  const Options options = parse(argc, argv);
  const fs::path data =
      fs::temp_directory_path() / ("occlusion-bench-server-" + std::to_string(::getpid()));
  fs::create_directories(data);
  struct Cleanup {
    fs::path path;
    ~Cleanup() {
      std::error_code ignored;
      fs::remove_all(path, ignored);
    }
  } cleanup{data};

  const occlusion::PointCloud cloud = room_cloud(options.points);
  occlusion::write_cloud((data / "cloud.ply").string(), cloud);
  std::ifstream file(data / "cloud.ply", std::ios::binary);
  const std::string ply((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());

  occlusion::server::ServerOptions server_options;
  server_options.port = 0;
  server_options.data_dir = data.string();
  server_options.workers = options.workers;
  server_options.log = [](const std::string&) {};
  occlusion::server::Server server(server_options);
  std::thread loop([&server] { server.run(); });
  const std::uint16_t port = server.port();

  std::printf("bench_server: 127.0.0.1:%u, %u workers, %u hardware threads\n", port,
              options.workers, std::thread::hardware_concurrency());
  for (const char* command : {"ping", "list_files"}) {
    for (unsigned clients : options.clients) {
      std::printf("%-10s %2u client(s): %9.0f requests/s\n", command, clients,
                  requests_per_second(port, clients, command, options.seconds));
    }
  }

  BlockingClient client("127.0.0.1", port);
  const Streamed cold = load(client, 1, "cloud.ply");
  double warm = std::numeric_limits<double>::infinity();
  Streamed last;
  for (std::uint32_t k = 0; k < 3; ++k) {
    last = load(client, 2 + k, "cloud.ply");
    warm = std::min(warm, last.seconds);
  }
  const double megabytes = static_cast<double>(last.bytes) / 1e6;
  std::printf(
      "stream %s points (%.1f MB of frames): cold load %.3f s, cached %.3f s (%.0f MB/s)%s\n",
      grouped(options.points).c_str(), megabytes, cold.seconds, warm, megabytes / warm,
      last.cached ? "" : " [not cached!]");
  std::printf("upload %s-byte PLY, read, store and stream back: %.3f s\n",
              grouped(ply.size()).c_str(), upload(client, 10, ply));
  const LiveTimes live = live_station(client, 20);
  std::printf(
      "live station on %s points: first (builds the disc model) %.3f s; per position: trace "
      "%.1f ms, round trip %.1f ms (median of 20; %s points seen from the last)\n",
      grouped(options.points).c_str(), live.first, 1e3 * live.trace_median,
      1e3 * live.round_trip_median, grouped(live.visible).c_str());

  client.close();
  server.stop();
  loop.join();
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "bench_server: %s\n", e.what());
  return 1;
}
