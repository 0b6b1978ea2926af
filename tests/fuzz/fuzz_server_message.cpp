// The server's text messages, as Session::on_text handles them: parse, read
// the request, and on any error name the id in the error reply. Bad messages
// are a ProtocolError, never anything else.

#include "fuzz_support.hpp"
#include "messages.hpp"
#include "occlusion/server/protocol_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace occlusion::server;
  Json::Value message;
  occlusion::fuzz::expect_only<ProtocolError>([&] {
    message = parse_json(occlusion::fuzz::as_text(data, size));
    const Request request = read_request(message);
    write_json(request.params);
  });
  const std::string command =
      message.isObject() && message["command"].isString() ? message["command"].asString() : "";
  error_message(request_id_of(message), command, "invalid_request", "fuzz");
  return 0;
}
