#pragma once
// One client connection: reads its messages, runs its requests (on this
// thread or a worker), keeps the cancel flag of each running request and the
// uploads it announced. Knows nothing of WebSocket++: replies go to an Outbox.

#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>

#include "command_table.hpp"
#include "messages.hpp"
#include "outbox.hpp"
#include "server_context.hpp"

namespace occlusion::server {

class Session : public std::enable_shared_from_this<Session> {
 public:
  Session(ServerContext& server, std::shared_ptr<Outbox> outbox);

  // Sends the hello message.
  void open();
  void on_text(std::string_view text);
  void on_binary(std::string message);
  // The connection is gone: cancels its requests, whose replies are dropped.
  void close();

  std::size_t running() const;
  // The largest binary message this connection may send next: the biggest
  // upload it announced and has not sent (refused ones included, whose bytes
  // are dropped), 0 when none. Beyond max_text_bytes only such a message may
  // go, so the transport refuses any other as soon as its frame passes the limit.
  std::uint64_t expected_binary_bytes() const;

 private:
  using Flag = std::shared_ptr<std::atomic<bool>>;
  using Run = std::function<Json::Value(CommandContext&)>;

  struct Upload {
    std::string name;
    std::uint64_t size = 0;
  };

  void dispatch(const Request& request);
  void announce_upload(const Request& request);
  void cancel(const Request& request);
  // Runs on a worker; the id must be registered already. `may_use_reserve`:
  // the command is short or can tell, by its work estimate, that it is not
  // (worker_pool.hpp).
  void submit(const std::string& command, std::uint32_t id, Json::Value params, Run run,
              const Flag& flag, bool may_use_reserve);
  // Runs `run` and sends its result or error. Never throws. On the reserve,
  // a job over the reserve's work budget goes back to the queue instead.
  void execute(const std::string& command, std::uint32_t id, const Json::Value& params,
               const Run& run, const Flag& flag, Lane lane);
  WorkerPool::OnPosition position_reporter(std::uint32_t id) const;
  void send_error(const Json::Value& id, const std::string& command, const std::string& code,
                  const std::string& message);
  // The error reply as text, with data-directory prefixes taken out of the message.
  std::string error_text(const Json::Value& id, const std::string& command, const std::string& code,
                         const std::string& message) const;

  // False if the id is in use.
  bool register_id(std::uint32_t id, const Flag& flag);
  void finish(std::uint32_t id);

  ServerContext& server_;
  std::shared_ptr<Outbox> outbox_;

  mutable std::mutex mutex_;
  std::map<std::uint32_t, Flag> running_;
  std::map<std::uint32_t, Upload> uploads_;
  // Their binary message is dropped; the announced size (0: none or over the
  // upload limit) is what the transport still lets through.
  std::map<std::uint32_t, std::uint64_t> refused_uploads_;
  bool closed_ = false;
};

// The hello message: protocol version, commands and whether each is
// available, limits.
std::string hello_message(const Limits& limits);

}  // namespace occlusion::server
