#include "occlusion/server/blocking_client.hpp"

#include <boost/asio/post.hpp>
#include <websocketpp/client.hpp>
#include <websocketpp/config/asio_no_tls_client.hpp>

#include <condition_variable>
#include <deque>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "messages.hpp"
#include "occlusion/server/binary_frame.hpp"

namespace occlusion::server {

namespace {

using Endpoint = websocketpp::client<websocketpp::config::asio_client>;
using Handle = websocketpp::connection_hdl;

Json::Value parse_or_null(const std::string& text) {
  try {
    return parse_json(text);
  } catch (const std::exception&) {
    return Json::Value();
  }
}

std::uint32_t message_id(const ClientMessage& message) {
  if (message.binary) return frame_request_id(message.data);
  const Json::Value json = parse_or_null(message.data);
  return json.isObject() && json["id"].isUInt() ? json["id"].asUInt() : 0xFFFFFFFFu;
}

}  // namespace

std::uint32_t frame_request_id(const std::string& message) {
  try {
    return decode_frame_header(message).request_id;
  } catch (const std::exception&) {
    return 0;
  }
}

struct BlockingClient::Impl {
  Endpoint endpoint;
  Handle handle;
  std::thread thread;

  std::mutex mutex;
  std::condition_variable changed;
  std::deque<ClientMessage> inbox;
  bool open = false;
  bool closed = false;
  int close_code = 0;
  std::string failure;
  Json::Value hello;

  void push(ClientMessage message) {
    {
      const std::lock_guard<std::mutex> lock(mutex);
      inbox.push_back(std::move(message));
    }
    changed.notify_all();
  }

  void post_send(std::string payload, websocketpp::frame::opcode::value opcode) {
    boost::asio::post(endpoint.get_io_service(), [this, payload = std::move(payload), opcode]() {
      websocketpp::lib::error_code ignored;
      endpoint.send(handle, payload, opcode, ignored);
    });
  }
};

BlockingClient::BlockingClient(const std::string& host, std::uint16_t port, Duration timeout,
                               const std::string& origin)
    : impl_(std::make_unique<Impl>()) {
  Impl& impl = *impl_;
  impl.endpoint.clear_access_channels(websocketpp::log::alevel::all);
  impl.endpoint.clear_error_channels(websocketpp::log::elevel::all);
  impl.endpoint.init_asio();
  impl.endpoint.set_max_message_size(std::size_t{1} << 31);
  impl.endpoint.set_open_handler([&impl](Handle) {
    {
      const std::lock_guard<std::mutex> lock(impl.mutex);
      impl.open = true;
    }
    impl.changed.notify_all();
  });
  const auto on_end = [&impl](Handle h, bool failed) {
    {
      const std::lock_guard<std::mutex> lock(impl.mutex);
      impl.closed = true;
      websocketpp::lib::error_code error;
      const auto connection = impl.endpoint.get_con_from_hdl(h, error);
      if (!error) {
        impl.close_code = connection->get_remote_close_code();
        if (failed) impl.failure = connection->get_ec().message();
      }
    }
    impl.changed.notify_all();
  };
  impl.endpoint.set_close_handler([on_end](Handle h) { on_end(h, false); });
  impl.endpoint.set_fail_handler([on_end](Handle h) { on_end(h, true); });
  impl.endpoint.set_message_handler([&impl](Handle, const Endpoint::message_ptr& message) {
    ClientMessage received;
    received.binary = message->get_opcode() == websocketpp::frame::opcode::binary;
    received.data = std::move(message->get_raw_payload());
    impl.push(std::move(received));
  });

  websocketpp::lib::error_code error;
  const std::string uri = "ws://" + host + ":" + std::to_string(port) + "/ws";
  const Endpoint::connection_ptr connection = impl.endpoint.get_connection(uri, error);
  if (error) throw std::runtime_error("cannot connect to " + uri + ": " + error.message());
  if (!origin.empty()) connection->append_header("Origin", origin);
  impl.handle = connection->get_handle();
  impl.endpoint.connect(connection);
  impl.thread = std::thread([&impl] { impl.endpoint.run(); });

  std::unique_lock<std::mutex> lock(impl.mutex);
  if (!impl.changed.wait_for(lock, timeout, [&] { return impl.open || impl.closed; }) ||
      !impl.open) {
    const std::string why = impl.failure.empty() ? "timed out" : impl.failure;
    lock.unlock();
    close();
    throw std::runtime_error("cannot connect to " + uri + ": " + why);
  }
  lock.unlock();
  const auto first = receive(timeout);
  if (first && !first->binary) impl.hello = parse_or_null(first->data);
  if (!impl.hello.isObject() || impl.hello["type"].asString() != "hello") {
    close();
    throw std::runtime_error("no hello message from " + uri);
  }
}

BlockingClient::~BlockingClient() {
  close();
}

const Json::Value& BlockingClient::hello() const {
  return impl_->hello;
}

void BlockingClient::send_text(const std::string& text) {
  impl_->post_send(text, websocketpp::frame::opcode::text);
}

void BlockingClient::send_binary(std::string message) {
  impl_->post_send(std::move(message), websocketpp::frame::opcode::binary);
}

void BlockingClient::send_request(std::uint32_t id, const std::string& command,
                                  const Json::Value& params) {
  Json::Value request(Json::objectValue);
  request["id"] = id;
  request["command"] = command;
  request["params"] = params;
  send_text(write_json(request));
}

std::optional<ClientMessage> BlockingClient::receive(Duration timeout) {
  Impl& impl = *impl_;
  std::unique_lock<std::mutex> lock(impl.mutex);
  if (!impl.changed.wait_for(lock, timeout, [&] { return !impl.inbox.empty() || impl.closed; }) ||
      impl.inbox.empty()) {
    return std::nullopt;
  }
  ClientMessage message = std::move(impl.inbox.front());
  impl.inbox.pop_front();
  return message;
}

Reply BlockingClient::collect(std::uint32_t id, Duration timeout) {
  Impl& impl = *impl_;
  Reply reply;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  std::unique_lock<std::mutex> lock(impl.mutex);
  for (;;) {
    // Take this request's messages, in order, leaving the others queued.
    for (auto it = impl.inbox.begin(); it != impl.inbox.end();) {
      if (message_id(*it) != id) {
        ++it;
        continue;
      }
      ClientMessage message = std::move(*it);
      it = impl.inbox.erase(it);
      if (message.binary) {
        reply.frames.push_back(std::move(message.data));
        continue;
      }
      Json::Value json = parse_or_null(message.data);
      if (json["type"].asString() == "progress") {
        reply.progress.push_back(std::move(json));
      } else {
        reply.final = std::move(json);
        return reply;
      }
    }
    if (impl.closed) return reply;
    if (impl.changed.wait_until(lock, deadline) == std::cv_status::timeout) return reply;
  }
}

Reply BlockingClient::request(std::uint32_t id, const std::string& command,
                              const Json::Value& params, Duration timeout) {
  send_request(id, command, params);
  return collect(id, timeout);
}

bool BlockingClient::wait_closed(Duration timeout) {
  Impl& impl = *impl_;
  std::unique_lock<std::mutex> lock(impl.mutex);
  return impl.changed.wait_for(lock, timeout, [&] { return impl.closed; });
}

int BlockingClient::close_code() const {
  const std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->close_code;
}

void BlockingClient::close() {
  Impl& impl = *impl_;
  if (!impl.thread.joinable()) return;
  boost::asio::post(impl.endpoint.get_io_service(), [&impl] {
    websocketpp::lib::error_code ignored;
    impl.endpoint.close(impl.handle, websocketpp::close::status::normal, "bye", ignored);
  });
  // The closing handshake normally ends the loop at once; a dead server does not answer.
  {
    std::unique_lock<std::mutex> lock(impl.mutex);
    impl.changed.wait_for(lock, std::chrono::seconds(2), [&] { return impl.closed; });
  }
  impl.endpoint.stop();
  impl.thread.join();
}

}  // namespace occlusion::server
