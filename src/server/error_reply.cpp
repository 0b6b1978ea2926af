#include "error_reply.hpp"

#include <new>

#include "occlusion/app/errors.hpp"
#include "occlusion/server/protocol_error.hpp"

namespace occlusion::server {

namespace {

// The app layer's classification as protocol codes (docs/protocol.md).
const char* protocol_code(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::kUsage:
      return "invalid_request";
    case ErrorKind::kInput:
      return "input_error";
    case ErrorKind::kOutput:
      return "output_error";
    case ErrorKind::kCancelled:
      return "cancelled";
    case ErrorKind::kResource:
    case ErrorKind::kInternal:
      break;
  }
  return "internal";
}

}  // namespace

ErrorReply classify(std::exception_ptr error) {
  try {
    std::rethrow_exception(error);
  } catch (const ProtocolError& e) {
    return {e.code, e.what()};
  } catch (const std::bad_alloc&) {
    return {"internal", "out of memory"};
  } catch (const std::exception& e) {
    const ErrorKind kind = occlusion::classify(e);
    return {protocol_code(kind), kind == ErrorKind::kCancelled ? "cancelled" : e.what()};
  } catch (...) {
    return {"internal", "unknown error"};
  }
}

}  // namespace occlusion::server
