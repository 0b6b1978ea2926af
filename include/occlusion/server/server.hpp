#pragma once
// `occlusion serve`: one process that serves the viewer over HTTP and the
// JSON/binary protocol of docs/protocol.md over a WebSocket, on one port.
// WebSocket++ and Boost.Asio stay inside src/server/*.cpp.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace occlusion::server {

struct ServerOptions {
  std::string host = "127.0.0.1";  // a non-loopback host is logged as such
  std::uint16_t port = 8080;       // 0: any free port (see Server::port)
  std::string data_dir = ".";      // every client path is relative to it
  std::string web_dir;             // the built viewer; empty or without index.html: a help page
  unsigned workers = 2;            // threads running loads and jobs
  std::size_t cache_bytes = std::size_t{1} << 30;
  std::size_t max_upload_bytes = std::size_t{256} << 20;
  std::size_t max_text_bytes = std::size_t{1} << 20;
  std::size_t max_queued_jobs = 64;
  std::size_t max_queued_per_client = 16;  // a connection's requests waiting at once
  std::size_t max_running_per_client = 1;  // a connection's jobs running at once
  // A job estimated to need more memory is refused; 0: half the machine's memory.
  std::uint64_t max_memory_mb = 0;
  // A job estimated to trace more G ray steps (app/work_budget.hpp) is
  // refused; 0: no budget. The default, 100 (1e8 rays from each of 9
  // viewpoints over an 80,000-point cloud is 15), is hours of tracing.
  double max_work = 100;
  double progress_interval_seconds = 0.1;
  bool stop_on_signals = false;  // SIGINT and SIGTERM stop run() (the CLI sets it)
  // One line per notable event; default: stderr.
  std::function<void(const std::string&)> log;
};

// `occlusion serve [options]`: parses the options, serves until a signal.
// Returns the exit code; throws UsageError for bad options.
int run_serve_command(const std::vector<std::string>& args);

class Server {
 public:
  // Binds and listens. Throws std::invalid_argument for bad options (a missing
  // data directory) and std::runtime_error when the address cannot be bound.
  explicit Server(ServerOptions options);
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  // The bound port (the chosen one when options.port was 0).
  std::uint16_t port() const;
  // Serves until stop(), on the calling thread.
  void run();
  // Closes every connection and makes run() return. Any thread; idempotent.
  void stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// True for 127.0.0.0/8, ::1 and "localhost".
bool is_loopback_host(const std::string& host);

// Whether a WebSocket whose Origin header is `origin` (empty: not a browser)
// may connect to a server listening on `listen_host` and reached as
// `host_header`. WebSockets are not bound by the browser's same-origin policy,
// so any page the user visits could talk to a server on localhost. Allowed: no
// Origin, a viewer on a loopback dev server, and the served page itself when
// it was reached by an address or by the listening host's own name; refused:
// any other page, and a page whose name was rebound (DNS rebinding) to this
// server's address.
bool origin_allowed(const std::string& origin, const std::string& host_header,
                    const std::string& listen_host);

}  // namespace occlusion::server
