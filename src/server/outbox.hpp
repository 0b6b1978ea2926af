#pragma once
// Where a connection's messages go. The WebSocket implementation queues them
// onto the network thread, so any thread may call these; tests can record them.

#include <string>

namespace occlusion::server {

class Outbox {
 public:
  virtual ~Outbox() = default;
  virtual void send_text(std::string message) = 0;
  virtual void send_binary(std::string message) = 0;
};

}  // namespace occlusion::server
