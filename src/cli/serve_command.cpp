#include <cstdio>
#include <memory>
#include <stdexcept>

#include "arguments.hpp"
#include "commands.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/server/server.hpp"
#include "option_table.hpp"

namespace occlusion::cli {

namespace {

void print_help() {
  std::printf(
      "usage: occlusion serve [options]\n"
      "\n"
      "Serve the browser viewer and the WebSocket protocol (docs/protocol.md) on one port:\n"
      "open http://HOST:PORT/ in a browser. Every job of the command line is reachable.\n"
      "\n"
      "options:\n"
      "  --host HOST           address to bind (default 127.0.0.1; any other is logged)\n"
      "  --port N              port (default 8080; 0 picks a free one)\n"
      "  --data DIR            the files clients may read and write (default .);\n"
      "                        job outputs go to DIR/out, uploads to DIR/uploads\n"
      "  --web DIR             the built viewer (default web/dist)\n"
      "  --workers N           threads running loads and jobs (default 2)\n"
      "  --cache-mb N          memory for loaded scenes kept for reuse (default 1024)\n"
      "  --max-upload-mb N     largest file a browser may upload (default 256)\n"
      "\n"
      "Stops on Ctrl-C (SIGINT) or SIGTERM.\n");
}

}  // namespace

int run_serve_command(const std::vector<std::string>& args) {
  server::ServerOptions options;
  options.web_dir = "web/dist";
  options.stop_on_signals = true;
  bool help = false;

  OptionTable table("serve");
  table.flag({"-h", "--help"}, [&] { help = true; });
  table.value({"--host"}, [&](const std::string&, const std::string& v) { options.host = v; });
  table.value({"--port"}, [&](const std::string& o, const std::string& v) {
    const auto port = parse_unsigned(o, v);
    if (port > 65535) throw UsageError("--port must be 0..65535");
    options.port = static_cast<std::uint16_t>(port);
  });
  table.value({"--data"}, [&](const std::string&, const std::string& v) { options.data_dir = v; });
  table.value({"--web"}, [&](const std::string&, const std::string& v) { options.web_dir = v; });
  table.value({"--workers"}, [&](const std::string& o, const std::string& v) {
    const auto workers = parse_unsigned(o, v);
    if (workers < 1 || workers > 256) throw UsageError("--workers must be 1..256");
    options.workers = static_cast<unsigned>(workers);
  });
  table.value({"--cache-mb"}, [&](const std::string& o, const std::string& v) {
    options.cache_bytes = static_cast<std::size_t>(parse_unsigned(o, v)) << 20;
  });
  table.value({"--max-upload-mb"}, [&](const std::string& o, const std::string& v) {
    const auto megabytes = parse_unsigned(o, v);
    if (megabytes < 1 || megabytes > 4096) throw UsageError("--max-upload-mb must be 1..4096");
    options.max_upload_bytes = static_cast<std::size_t>(megabytes) << 20;
  });
  table.parse(args, [](const std::string& arg) {
    throw UsageError("serve takes no positional argument, got '" + arg + "'");
  });
  if (help) {
    print_help();
    return 0;
  }

  std::unique_ptr<server::Server> server;
  try {
    server = std::make_unique<server::Server>(options);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--data: ") + e.what());
  }
  server->run();
  return 0;
}

}  // namespace occlusion::cli
