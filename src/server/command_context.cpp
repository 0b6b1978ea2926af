#include "command_context.hpp"

#include "messages.hpp"

namespace occlusion::server {

CommandContext::CommandContext(ServerContext& server_context, Outbox& outbox,
                               std::uint32_t request_id, const Json::Value& request_params,
                               const std::atomic<bool>* cancel, double work_budget)
    : server(server_context),
      id(request_id),
      params(request_params),
      max_work(work_budget),
      outbox_(outbox) {
  progress_.cancel = cancel;
  progress_.report = [this](const std::string& stage, double fraction) { report(stage, fraction); };
}

void CommandContext::report(const std::string& stage, double fraction) {
  // Analyses report per block of work, which can be thousands of times a
  // second; the browser needs a few updates a second at most.
  const std::lock_guard<std::mutex> lock(report_mutex_);
  const auto now = std::chrono::steady_clock::now();
  const auto interval = std::chrono::duration<double>(server.limits.progress_interval_seconds);
  if (reported_ && now - last_report_ < interval) return;
  reported_ = true;
  last_report_ = now;
  outbox_.send_text(progress_message(id, stage, fraction));
}

void CommandContext::send(Frame frame) {
  progress_.check_cancel();
  set_request_id(frame.message, id);
  sent_.push_back(frame.header);
  sent_.back().request_id = id;
  outbox_.send_binary(std::move(frame.message));
}

void CommandContext::send(const std::vector<Frame>& frames) {
  for (const auto& frame : frames) send(frame);
}

}  // namespace occlusion::server
