#include "session.hpp"

#include <algorithm>
#include <optional>

#include "command_params.hpp"
#include "error_reply.hpp"
#include "occlusion/app/job_registry.hpp"
#include "occlusion/app/work_budget.hpp"
#include "occlusion/io/named_paths.hpp"
#include "occlusion/server/protocol_error.hpp"
#include "upload.hpp"

namespace occlusion::server {

namespace {

// Refused announcements remembered per connection, so a client that keeps
// sending them cannot grow the set without bound.
constexpr std::size_t kMaxRefusedUploads = 64;

}  // namespace

std::string hello_message(const Limits& limits) {
  Json::Value json(Json::objectValue);
  json["type"] = "hello";
  json["protocol"] = kProtocolVersion;
  json["server"] = "occlusion 0.1.0";
  Json::Value commands(Json::objectValue);
  for (const auto& command : command_table()) commands[command.name] = command.available();
  json["commands"] = commands;
  // Each job's keys as declared (type, default, range, unit, doc): the viewer
  // builds its settings from them instead of keeping its own copies.
  Json::Value jobs_json(Json::objectValue);
  for (const JobInfo& job : jobs()) {
    Json::Value entry(Json::objectValue);
    entry["section"] = job.section;
    entry["summary"] = job.summary;
    Json::Value keys(Json::arrayValue);
    for (const KeyInfo& info : job.keys) keys.append(to_json(info));
    entry["keys"] = keys;
    jobs_json[job.name] = entry;
  }
  json["jobs"] = jobs_json;
  Json::Value limit(Json::objectValue);
  limit["max_text_bytes"] = Json::UInt64(limits.max_text_bytes);
  limit["max_upload_bytes"] = Json::UInt64(limits.max_upload_bytes);
  limit["progress_per_second"] = 1.0 / limits.progress_interval_seconds;
  limit["max_memory_mb"] = Json::UInt64(limits.max_memory_mb);
  limit["max_work"] = limits.max_work;
  limit["max_running_per_client"] = Json::UInt64(limits.max_running_per_client);
  limit["max_queued_per_client"] = Json::UInt64(limits.max_queued_per_client);
  json["limits"] = limit;
  Json::Value suffixes(Json::arrayValue);
  for (const auto& suffix : upload_suffixes()) suffixes.append(suffix);
  json["upload_suffixes"] = suffixes;
  return write_json(json);
}

Session::Session(ServerContext& server, std::shared_ptr<Outbox> outbox)
    : server_(server), outbox_(std::move(outbox)) {}

void Session::open() {
  outbox_->send_text(hello_message(server_.limits));
}

void Session::on_text(std::string_view text) {
  if (text.size() > server_.limits.max_text_bytes) {
    send_error(Json::Value(), "", "message_too_large",
               "text messages are limited to " + std::to_string(server_.limits.max_text_bytes) +
                   " bytes; this one has " + std::to_string(text.size()));
    return;
  }
  Json::Value message;
  try {
    message = parse_json(text);
    dispatch(read_request(message));
  } catch (...) {
    const ErrorReply error = classify(std::current_exception());
    const std::string command = message.isObject() && message["command"].isString()
                                    ? message["command"].asString()
                                    : std::string();
    send_error(request_id_of(message), command, error.code, error.message);
  }
}

void Session::dispatch(const Request& request) {
  const Command* command = find_command(request.command);
  if (command == nullptr) {
    throw ProtocolError("unknown_command", "unknown command '" + request.command + "'");
  }
  if (!command->available()) {
    throw ProtocolError("not_available",
                        "'" + request.command + "' is not available in this build yet");
  }
  {
    // Ids name replies, so no two requests of a connection may share one at a time.
    const std::lock_guard<std::mutex> lock(mutex_);
    if (running_.count(request.id) > 0) {
      throw ProtocolError("duplicate_id", "id " + std::to_string(request.id) + " is still running");
    }
  }
  if (command->name == "cancel") return cancel(request);
  if (command->name == "upload") return announce_upload(request);
  if (command->where == Where::kNetwork) {
    execute(request.command, request.id, request.params, command->run, nullptr, Lane::kWorker);
    return;
  }
  const Flag flag = std::make_shared<std::atomic<bool>>(false);
  if (!register_id(request.id, flag)) {
    throw ProtocolError("duplicate_id", "id " + std::to_string(request.id) + " is still running");
  }
  // Loads, and jobs that estimate their work, may start on the reserve.
  const JobInfo* job = find_job(request.command);
  const bool estimates_work =
      job != nullptr && std::any_of(job->keys.begin(), job->keys.end(),
                                    [](const KeyInfo& info) { return info.name == "max_work"; });
  submit(request.command, request.id, request.params, command->run, flag,
         command->waited_on || estimates_work);
}

WorkerPool::OnPosition Session::position_reporter(std::uint32_t id) const {
  // Until a worker takes it, the request's progress is its place in the queue.
  return
      [outbox = outbox_, id](std::size_t ahead) { outbox->send_text(queued_message(id, ahead)); };
}

void Session::submit(const std::string& command, std::uint32_t id, Json::Value params, Run run,
                     const Flag& flag, bool may_use_reserve) {
  auto self = shared_from_this();
  // Jobs share the workers fairly between clients; loads, uploads and the
  // live station, which a client waits on to go on working, are not held back
  // behind its own jobs. All of them wait in this connection's share of the queue.
  const Command* entry = find_command(command);
  const bool is_job = entry == nullptr || !entry->waited_on;
  const bool queued = server_.pool.submit(
      this,
      [self, command, id, params = std::move(params), run = std::move(run), flag](Lane lane) {
        self->execute(command, id, params, run, flag, lane);
      },
      position_reporter(id), WorkerPool::Kind{is_job, may_use_reserve});
  if (!queued) {
    finish(id);
    send_error(Json::Value(id), command, "busy",
               "too many requests are waiting (" +
                   std::to_string(server_.limits.max_queued_per_client) + " of a connection, " +
                   std::to_string(server_.limits.max_queued_jobs) +
                   " in all); try again once some are answered");
  }
}

void Session::execute(const std::string& command, std::uint32_t id, const Json::Value& params,
                      const Run& run, const Flag& flag, Lane lane) {
  const Limits& limits = server_.limits;
  const bool on_reserve = lane == Lane::kReserve;
  const double max_work =
      on_reserve && (limits.max_work <= 0 || limits.reserve_max_work < limits.max_work)
          ? limits.reserve_max_work
          : limits.max_work;
  // A file of the data directory, or an upload, names files inside it only.
  const NamedPathScope inside_data([this](const std::string& file, const std::string& named) {
    return server_.root.resolve_named(file, named).string();
  });
  std::string final_reply;
  try {
    CommandContext context(server_, *outbox_, id, params, flag.get(), max_work);
    context.progress().check_cancel();
    Json::Value result = run(context);
    // A job that finished as it was cancelled still counts as cancelled.
    context.progress().check_cancel();
    final_reply = result_message(id, command, std::move(result), context.sent());
  } catch (const WorkBudgetError& error) {
    // Too long for the reserve but within the server's budget: a worker
    // runs it when one is free, ahead of the jobs that came after it.
    const bool within_budget =
        limits.max_work <= 0 || static_cast<double>(error.steps) <= limits.max_work * kWorkUnit;
    if (on_reserve && max_work != limits.max_work && within_budget) {
      auto self = shared_from_this();
      const bool requeued = server_.pool.requeue(
          this,
          [self, command, id, params, run, flag](Lane next) {
            self->execute(command, id, params, run, flag, next);
          },
          position_reporter(id));
      if (requeued) return;
    }
    const ErrorReply reply = classify(std::current_exception());
    final_reply = error_text(Json::Value(id), command, reply.code, reply.message);
  } catch (...) {
    const ErrorReply error = classify(std::current_exception());
    final_reply = error_text(Json::Value(id), command, error.code, error.message);
  }
  // The id is free before its final reply leaves: a client may reuse it as
  // soon as it reads that reply.
  if (flag) finish(id);
  outbox_->send_text(final_reply);
}

void Session::announce_upload(const Request& request) {
  std::uint64_t size = 0;
  const auto refuse = [&] {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (refused_uploads_.size() >= kMaxRefusedUploads) refused_uploads_.clear();
    refused_uploads_[request.id] = size <= server_.limits.max_upload_bytes ? size : 0;
  };
  try {
    allow_keys(request.params, {"name", "size"});
    const std::string name = required_string(request.params, "name");
    size = required_unsigned(request.params, "size");
    check_upload_name(name);
    if (size > server_.limits.max_upload_bytes) {
      throw ProtocolError(
          "message_too_large",
          "uploads are limited to " + std::to_string(server_.limits.max_upload_bytes) + " bytes");
    }
    server_.root.resolve("uploads/" + name, false);
    if (!register_id(request.id, std::make_shared<std::atomic<bool>>(false))) {
      throw ProtocolError("duplicate_id", "id " + std::to_string(request.id) + " is still running");
    }
    const std::lock_guard<std::mutex> lock(mutex_);
    uploads_[request.id] = Upload{name, size};
    refused_uploads_.erase(request.id);
  } catch (...) {
    refuse();
    throw;
  }
}

void Session::on_binary(std::string message) {
  Json::Value id;
  try {
    // The header's id is trusted before the rest of the message: a malformed
    // upload ends its own request, answered under its id, and frees the id.
    const std::optional<std::uint32_t> named = header_request_id(message);
    Upload upload;
    Flag flag;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      if (named && refused_uploads_.erase(*named) > 0) return;
      const auto it = named ? uploads_.find(*named) : uploads_.end();
      if (it != uploads_.end()) {
        upload = it->second;
        flag = running_.at(it->first);
        uploads_.erase(it);
      }
    }
    if (!flag) {
      const FrameHeader header = decode_frame_header(message);
      id = header.request_id;
      throw ProtocolError("unexpected_binary",
                          "no upload was announced with id " + std::to_string(header.request_id));
    }
    id = *named;
    try {
      const FrameHeader header = decode_frame_header(message);
      if (header.kind != FrameKind::kUpload || header.type != ElementType::kUint8 ||
          header.components != 1 || header.count != upload.size) {
        throw ProtocolError("unexpected_binary", "the upload frame must be kind 'upload', uint8, " +
                                                     std::to_string(upload.size) +
                                                     " bytes as announced");
      }
    } catch (...) {
      finish(*named);
      throw;
    }
    auto bytes = std::make_shared<std::string>(std::move(message));
    submit(
        "upload", *named, Json::Value(Json::objectValue),
        [name = upload.name, bytes](CommandContext& context) {
          return store_upload(context, name, std::string_view(*bytes).substr(kFrameHeaderSize));
        },
        flag, true);
  } catch (...) {
    const ErrorReply error = classify(std::current_exception());
    send_error(id, id.isNull() ? "" : "upload", error.code, error.message);
  }
}

void Session::cancel(const Request& request) {
  allow_keys(request.params, {"target"});
  const std::uint64_t target = required_unsigned(request.params, "target");
  bool found = false;
  bool was_pending_upload = false;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (const auto it = running_.find(static_cast<std::uint32_t>(target));
        target <= UINT32_MAX && it != running_.end()) {
      it->second->store(true);
      found = true;
      // An upload still waiting for its bytes has no worker to notice the flag.
      const auto upload = uploads_.find(it->first);
      was_pending_upload = upload != uploads_.end();
      if (was_pending_upload) {
        refused_uploads_[it->first] = upload->second.size;
        uploads_.erase(upload);
        running_.erase(it);
      }
    }
  }
  Json::Value result(Json::objectValue);
  result["target"] = Json::UInt64(target);
  result["found"] = found;
  outbox_->send_text(result_message(request.id, "cancel", result, {}));
  if (was_pending_upload) {
    send_error(Json::Value(static_cast<std::uint32_t>(target)), "upload", "cancelled", "cancelled");
  }
}

void Session::close() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    closed_ = true;
    for (auto& [id, flag] : running_) flag->store(true);
    uploads_.clear();
  }
  // Its waiting requests never start; running ones stop at their next check.
  server_.pool.drop(this);
}

std::size_t Session::running() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return running_.size();
}

std::uint64_t Session::expected_binary_bytes() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  std::uint64_t largest = 0;
  for (const auto& [id, upload] : uploads_) largest = std::max(largest, upload.size);
  for (const auto& [id, size] : refused_uploads_) largest = std::max(largest, size);
  return largest;
}

bool Session::register_id(std::uint32_t id, const Flag& flag) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (closed_) flag->store(true);
  return running_.emplace(id, flag).second;
}

void Session::finish(std::uint32_t id) {
  const std::lock_guard<std::mutex> lock(mutex_);
  running_.erase(id);
}

void Session::send_error(const Json::Value& id, const std::string& command, const std::string& code,
                         const std::string& message) {
  outbox_->send_text(error_text(id, command, code, message));
}

std::string Session::error_text(const Json::Value& id, const std::string& command,
                                const std::string& code, const std::string& message) const {
  // Readers name files by their full path; the client knows them by the data-relative one.
  std::string text = message;
  const std::string prefix = server_.root.path().string() + "/";
  for (std::size_t at = text.find(prefix); at != std::string::npos; at = text.find(prefix, at)) {
    text.erase(at, prefix.size());
  }
  return error_message(id, command, code, text);
}

}  // namespace occlusion::server
