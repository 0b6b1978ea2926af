#include "occlusion/server/server.hpp"

// WebSocket++ is confined to this file (and the client): its headers are heavy
// and warn under our flags.
#include <boost/asio/ip/address.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/signal_set.hpp>
#include <boost/asio/steady_timer.hpp>
#include <websocketpp/config/asio_no_tls.hpp>
#include <websocketpp/server.hpp>

#include <atomic>
#include <cstdio>
#include <map>
#include <stdexcept>

#include "occlusion/app/memory_budget.hpp"
#include "occlusion/io/output_recovery.hpp"
#include "occlusion/server/static_files.hpp"
#include "outbox.hpp"
#include "server_context.hpp"
#include "session.hpp"

namespace occlusion::server {

namespace {

using Endpoint = websocketpp::server<websocketpp::config::asio>;
using Handle = websocketpp::connection_hdl;
namespace asio = boost::asio;

// Replies queued for one connection beyond which it is closed (1008).
constexpr std::size_t kMaxBufferedBytes = std::size_t{1} << 30;
// What the transport lets through beyond a message's protocol limit: a
// message a little too long gets a JSON error (message_too_large), one far
// too long a close (1009) before it is buffered.
constexpr std::size_t kTransportSlack = std::size_t{64} << 10;

// Sends from any thread by queueing onto the network thread, the only one that
// touches WebSocket++ connections. A connection gone meanwhile drops the message.
class ConnectionOutbox : public Outbox {
 public:
  ConnectionOutbox(Endpoint& endpoint, Handle handle) : endpoint_(endpoint), handle_(handle) {}

  void send_text(std::string message) override {
    post(std::move(message), websocketpp::frame::opcode::text);
  }
  void send_binary(std::string message) override {
    post(std::move(message), websocketpp::frame::opcode::binary);
  }

 private:
  void post(std::string message, websocketpp::frame::opcode::value opcode) {
    asio::post(endpoint_.get_io_service(), [&endpoint = endpoint_, handle = handle_,
                                            message = std::move(message), opcode]() mutable {
      websocketpp::lib::error_code error;
      const Endpoint::connection_ptr connection = endpoint.get_con_from_hdl(handle, error);
      if (error) return;
      // A client that requests faster than it reads would make the
      // server hold its replies without bound; it is let go instead.
      if (connection->get_buffered_amount() > kMaxBufferedBytes) {
        connection->close(websocketpp::close::status::policy_violation,
                          "replies are not being read", error);
        return;
      }
      // Hand the buffer over rather than copy it: frames reach 100 MB.
      const auto outgoing = connection->get_message(opcode, 0);
      outgoing->get_raw_payload().swap(message);
      connection->send(outgoing);
    });
  }

  Endpoint& endpoint_;
  Handle handle_;
};

}  // namespace

bool is_loopback_host(const std::string& host) {
  if (host == "localhost") return true;
  boost::system::error_code error;
  const auto address = asio::ip::make_address(host, error);
  return !error && address.is_loopback();
}

namespace {

// The host of "host", "host:port", "[v6]" or "[v6]:port".
std::string host_of(const std::string& authority) {
  if (!authority.empty() && authority[0] == '[') {
    const std::size_t close = authority.find(']');
    return close == std::string::npos ? std::string() : authority.substr(1, close - 1);
  }
  return authority.substr(0, authority.find(':'));
}

bool is_ip_literal(const std::string& host) {
  boost::system::error_code error;
  asio::ip::make_address(host, error);
  return !error;
}

}  // namespace

bool origin_allowed(const std::string& origin, const std::string& host_header,
                    const std::string& listen_host) {
  if (origin.empty()) return true;
  const std::size_t scheme = origin.find("://");
  if (scheme == std::string::npos) return false;
  const std::string authority = origin.substr(scheme + 3);
  if (is_loopback_host(host_of(authority))) return true;
  if (authority != host_header) return false;
  // The page's own origin, but a name can be rebound: evil.example resolving
  // to 127.0.0.1 makes a foreign page "same-origin" with this server. Only a
  // name the server is reached by without DNS (an address, or the host it
  // listens on) is the served page's own.
  const std::string host = host_of(authority);
  return is_ip_literal(host) || host == listen_host;
}

struct Server::Impl {
  explicit Impl(ServerOptions server_options);
  ~Impl();

  void on_open(Handle handle);
  void on_close(Handle handle);
  void on_message(Handle handle, const Endpoint::message_ptr& message);
  // Sets the connection's message limit to the text limit, or to the upload
  // its session awaits.
  void allow_expected_binary(Handle handle, const Session& session);
  void on_http(Handle handle);
  bool on_validate(Handle handle);
  void log(const std::string& line) const;
  void shutdown();

  ServerOptions options;
  Endpoint endpoint;  // before the context: workers post to it until they are joined
  ServerContext context;
  StaticFiles web;
  std::map<Handle, std::shared_ptr<Session>, std::owner_less<Handle>> sessions;
  std::unique_ptr<asio::signal_set> signals;
  std::unique_ptr<asio::steady_timer> stop_timer;
  std::atomic<bool> stopping{false};
  std::uint16_t port = 0;
};

namespace {

// Half the physical memory: room for two jobs and the scene cache. 4 GB when
// the system does not say.
std::uint64_t half_of_memory_mb() {
  const std::uint64_t machine = machine_memory_mb();
  return machine == 0 ? 4096 : machine / 2;
}

Limits limits_of(const ServerOptions& options) {
  Limits limits;
  limits.max_text_bytes = options.max_text_bytes;
  limits.max_upload_bytes = options.max_upload_bytes;
  limits.max_queued_jobs = options.max_queued_jobs;
  limits.max_queued_per_client = options.max_queued_per_client;
  limits.max_running_per_client = options.max_running_per_client;
  limits.max_memory_mb = options.max_memory_mb != 0 ? options.max_memory_mb : half_of_memory_mb();
  limits.max_work = options.max_work;
  limits.progress_interval_seconds = options.progress_interval_seconds;
  return limits;
}

}  // namespace

Server::Impl::Impl(ServerOptions server_options)
    : options(std::move(server_options)),
      context(DataRoot(options.data_dir), options.cache_bytes, options.workers, limits_of(options)),
      web(options.web_dir) {
  // Our own log says what matters; WebSocket++'s per-frame access log does not.
  endpoint.clear_access_channels(websocketpp::log::alevel::all);
  endpoint.clear_error_channels(websocketpp::log::elevel::all);
  endpoint.set_error_channels(websocketpp::log::elevel::fatal);
  endpoint.init_asio();
  endpoint.set_reuse_addr(true);
  // Beyond this a message is refused by WebSocket++ itself (close code 1009)
  // as soon as a frame header says so, before its bytes are held; only an
  // announced upload raises a connection's limit (allow_expected_binary).
  endpoint.set_max_message_size(options.max_text_bytes + kTransportSlack);

  endpoint.set_open_handler([this](Handle h) { on_open(h); });
  endpoint.set_close_handler([this](Handle h) { on_close(h); });
  endpoint.set_fail_handler([this](Handle h) { on_close(h); });
  endpoint.set_message_handler(
      [this](Handle h, const Endpoint::message_ptr& m) { on_message(h, m); });
  endpoint.set_http_handler([this](Handle h) { on_http(h); });
  endpoint.set_validate_handler([this](Handle h) { return on_validate(h); });

  websocketpp::lib::error_code error;
  endpoint.listen(options.host, std::to_string(options.port), error);
  if (error) {
    throw std::runtime_error("cannot listen on " + options.host + ":" +
                             std::to_string(options.port) + ": " + error.message());
  }
  endpoint.start_accept(error);
  if (error) throw std::runtime_error("cannot accept connections: " + error.message());
  websocketpp::lib::asio::error_code asio_error;
  port = endpoint.get_local_endpoint(asio_error).port();
  if (asio_error) throw std::runtime_error("cannot read the bound port: " + asio_error.message());

  if (!is_loopback_host(options.host)) {
    log("warning: listening on " + options.host +
        ", not a loopback address: whoever reaches this port can read and write the data "
        "directory " +
        context.root.path().string());
  }
  // Job outputs a killed server left half committed are finished, and its
  // temporaries removed, before any client reads them.
  const RecoveredOutputs recovered = recover_outputs((context.root.path() / "out").string());
  if (recovered.completed_sets + recovered.removed_temporaries > 0) {
    log("out/: finished " + std::to_string(recovered.completed_sets) +
        " output set(s) a killed run left half written, removed " +
        std::to_string(recovered.removed_temporaries) + " temporary file(s)");
  }
  if (!web.has_viewer()) {
    log("no viewer in --web '" + options.web_dir +
        "' (no index.html): '/' explains how to build it");
  }
  if (options.stop_on_signals) {
    signals = std::make_unique<asio::signal_set>(endpoint.get_io_service(), SIGINT, SIGTERM);
    signals->async_wait([this](const boost::system::error_code& e, int) {
      if (e) return;
      log("stopping on signal");
      shutdown();
    });
  }
}

Server::Impl::~Impl() {
  for (auto& [handle, session] : sessions) session->close();
  context.pool.stop();
}

void Server::Impl::log(const std::string& line) const {
  if (options.log) {
    options.log(line);
  } else {
    std::fprintf(stderr, "occlusion serve: %s\n", line.c_str());
  }
}

bool Server::Impl::on_validate(Handle handle) {
  const Endpoint::connection_ptr connection = endpoint.get_con_from_hdl(handle);
  const std::string origin = connection->get_request_header("Origin");
  if (origin_allowed(origin, connection->get_request_header("Host"), options.host)) return true;
  log("refused a WebSocket from origin " + origin);
  connection->set_status(websocketpp::http::status_code::forbidden);
  return false;
}

void Server::Impl::on_open(Handle handle) {
  auto session =
      std::make_shared<Session>(context, std::make_shared<ConnectionOutbox>(endpoint, handle));
  sessions[handle] = session;
  session->open();
}

void Server::Impl::on_close(Handle handle) {
  const auto it = sessions.find(handle);
  if (it == sessions.end()) return;
  it->second->close();
  sessions.erase(it);
}

void Server::Impl::on_message(Handle handle, const Endpoint::message_ptr& message) {
  const auto it = sessions.find(handle);
  if (it == sessions.end()) return;
  if (message->get_opcode() == websocketpp::frame::opcode::text) {
    it->second->on_text(message->get_payload());
  } else {
    it->second->on_binary(std::move(message->get_raw_payload()));
  }
  // Runs before the next frame's header is read, even one already received.
  allow_expected_binary(handle, *it->second);
}

void Server::Impl::allow_expected_binary(Handle handle, const Session& session) {
  websocketpp::lib::error_code error;
  const Endpoint::connection_ptr connection = endpoint.get_con_from_hdl(handle, error);
  if (error) return;
  const std::uint64_t upload = session.expected_binary_bytes();
  connection->set_max_message_size(
      upload == 0 ? options.max_text_bytes + kTransportSlack
                  : std::max<std::uint64_t>(upload + kFrameHeaderSize + kTransportSlack,
                                            options.max_text_bytes + kTransportSlack));
}

void Server::Impl::on_http(Handle handle) {
  const Endpoint::connection_ptr connection = endpoint.get_con_from_hdl(handle);
  const std::string method = connection->get_request().get_method();
  HttpResponse response;
  if (method != "GET" && method != "HEAD") {
    response = {405, "text/plain; charset=utf-8", "method not allowed\n"};
  } else {
    response = web.get(connection->get_resource());
  }
  connection->set_status(static_cast<websocketpp::http::status_code::value>(response.status));
  connection->replace_header("Content-Type", response.content_type);
  connection->replace_header("X-Content-Type-Options", "nosniff");
  connection->set_body(method == "HEAD" ? std::string() : response.body);
}

Server::Server(ServerOptions options) : impl_(std::make_unique<Impl>(std::move(options))) {}

Server::~Server() {
  stop();
  impl_.reset();
}

std::uint16_t Server::port() const {
  return impl_->port;
}

void Server::run() {
  impl_->log("listening on http://" + impl_->options.host + ":" + std::to_string(impl_->port) +
             "/ (data: " + impl_->context.root.path().string() + ")");
  for (;;) {
    try {
      impl_->endpoint.run();
      return;
    } catch (const std::exception& e) {
      // A handler's bug must not end the server; the loop picks up where it was.
      impl_->log(std::string("internal error: ") + e.what());
      if (impl_->stopping) return;
    }
  }
}

void Server::stop() {
  impl_->shutdown();
}

void Server::Impl::shutdown() {
  if (stopping.exchange(true)) return;
  asio::post(endpoint.get_io_service(), [this] {
    websocketpp::lib::error_code ignored;
    endpoint.stop_listening(ignored);
    for (auto& [handle, session] : sessions) {
      session->close();
      endpoint.close(handle, websocketpp::close::status::going_away, "server stopping", ignored);
    }
    // Closing handshakes get a moment; a client that does not answer is not waited for.
    stop_timer = std::make_unique<asio::steady_timer>(endpoint.get_io_service(),
                                                      std::chrono::milliseconds(200));
    stop_timer->async_wait([this](const boost::system::error_code&) { endpoint.stop(); });
  });
}

}  // namespace occlusion::server
