#pragma once
// What a command sees while it runs: its params, the server's shared state,
// a Progress wired to rate-limited progress events and to the request's cancel
// flag, and a way to stream binary frames ahead of its result.

#include <json/value.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <vector>

#include "occlusion/core/progress.hpp"
#include "occlusion/server/binary_frame.hpp"
#include "outbox.hpp"
#include "server_context.hpp"

namespace occlusion::server {

class CommandContext {
 public:
  // `max_work`: the work budget this run gets (the server's, or the
  // reserve's, which is smaller), in G ray steps.
  CommandContext(ServerContext& server, Outbox& outbox, std::uint32_t id, const Json::Value& params,
                 const std::atomic<bool>* cancel, double max_work);
  CommandContext(const CommandContext&) = delete;
  CommandContext& operator=(const CommandContext&) = delete;

  ServerContext& server;
  const std::uint32_t id;
  const Json::Value& params;
  const double max_work;

  const Progress& progress() const { return progress_; }

  // Addresses the frame to this request and sends it; the result lists it.
  // Throws Cancelled when the request was cancelled meanwhile.
  void send(Frame frame);
  void send(const std::vector<Frame>& frames);
  const std::vector<FrameHeader>& sent() const { return sent_; }

 private:
  void report(const std::string& stage, double fraction);

  Outbox& outbox_;
  Progress progress_;
  std::vector<FrameHeader> sent_;
  std::mutex report_mutex_;  // in case an analysis reports from several threads
  bool reported_ = false;
  std::chrono::steady_clock::time_point last_report_;
};

}  // namespace occlusion::server
