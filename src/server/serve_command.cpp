// `occlusion serve`: the server's own face on the command line. Its options
// are declared keys like every job's, parsed by the same code.

#include <cstdio>
#include <memory>
#include <stdexcept>

#include "occlusion/app/errors.hpp"
#include "occlusion/app/key_sources.hpp"
#include "occlusion/server/server.hpp"

namespace occlusion::server {

namespace {

constexpr std::size_t kMiB = std::size_t{1} << 20;

const Keys<ServerOptions>& serve_keys() {
  using R = ServerOptions;
  static const Keys<R> keys = {
      key("host", &R::host).metavar("HOST").doc("address to bind (any but loopback is logged)"),
      key("port", &R::port).metavar("N").doc("port; 0 picks a free one"),
      key("data", &R::data_dir)
          .path()
          .metavar("DIR")
          .doc("the files clients may read and write; job outputs go to DIR/out, uploads to "
               "DIR/uploads"),
      key("web", &R::web_dir).path().metavar("DIR").doc("the built viewer (web/dist if not given)"),
      key("workers", &R::workers).range(1, 256).metavar("N").doc("threads running loads and jobs"),
      key("max_running_per_client", &R::max_running_per_client)
          .range(1, 256)
          .metavar("N")
          .doc("jobs of one connection running at once; the others wait their turn"),
      key("max_memory_mb", &R::max_memory_mb)
          .range(0, 1u << 24)
          .metavar("N")
          .doc("memory budget of one job in MiB (work over it is refused up front with the "
               "estimate); 0 = half the machine's memory"),
      key("max_work", &R::max_work)
          .range(0, 1e9)
          .unit("G ray steps")
          .metavar("N")
          .doc("work budget of one job: rays x octree depth, in billions (work over it is "
               "refused up front with the estimate and the keys to lower); 0 = none"),
      custom_key<R>(
          "cache_mb", ValueType::kInteger,
          [](R& r, const Json::Value& v) { r.cache_bytes = v.asUInt64() * kMiB; },
          [](const R& r) { return Json::Value(Json::UInt64(r.cache_bytes / kMiB)); })
          .range(0, 1 << 20)
          .metavar("N")
          .doc("memory for loaded scenes kept for reuse, in MiB"),
      custom_key<R>(
          "max_upload_mb", ValueType::kInteger,
          [](R& r, const Json::Value& v) { r.max_upload_bytes = v.asUInt64() * kMiB; },
          [](const R& r) { return Json::Value(Json::UInt64(r.max_upload_bytes / kMiB)); })
          .range(1, 4096)
          .metavar("N")
          .doc("largest file a browser may upload, in MiB"),
  };
  return keys;
}

void print_help() {
  std::printf(
      "usage: occlusion serve [options]\n"
      "\n"
      "Serve the browser viewer and the WebSocket protocol (docs/protocol.md) on one port:\n"
      "open http://HOST:PORT/ in a browser. Every job of the command line is reachable.\n"
      "Stops on Ctrl-C (SIGINT) or SIGTERM.\n\noptions:\n");
  for (const auto& k : serve_keys()) {
    const KeyInfo& info = k.info;
    std::printf("  %-22s %s (%s; default %s)\n", (cli_spelling(info) + " " + info.metavar).c_str(),
                info.doc.c_str(), describe_values(info).c_str(), default_text(info).c_str());
  }
}

}  // namespace

int run_serve_command(const std::vector<std::string>& args) {
  std::vector<std::string> rest;
  for (const auto& arg : args) {
    if (arg == "-h" || arg == "--help") {
      print_help();
      return 0;
    }
    rest.push_back(arg);
  }
  ServerOptions options;
  options.web_dir = "web/dist";
  options.stop_on_signals = true;
  apply_sources(serve_keys(), {source_from_arguments(rest, key_infos(serve_keys()), "serve", "")},
                options);
  std::unique_ptr<Server> server;
  try {
    server = std::make_unique<Server>(options);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--data: ") + e.what());
  }
  server->run();
  return 0;
}

}  // namespace occlusion::server
