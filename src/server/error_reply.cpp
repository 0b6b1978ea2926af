#include "error_reply.hpp"

#include <new>
#include <stdexcept>

#include "occlusion/analysis/progress.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/io/input_error.hpp"
#include "occlusion/server/protocol_error.hpp"

namespace occlusion::server {

ErrorReply classify(std::exception_ptr error) {
  try {
    std::rethrow_exception(error);
  } catch (const ProtocolError& e) {
    return {e.code, e.what()};
  } catch (const UsageError& e) {
    return {"invalid_request", e.what()};
  } catch (const InputError& e) {
    return {"input_error", e.what()};
  } catch (const OutputError& e) {
    return {"output_error", e.what()};
  } catch (const Cancelled&) {
    return {"cancelled", "cancelled"};
  } catch (const std::bad_alloc&) {
    return {"internal", "out of memory"};
  } catch (const std::invalid_argument& e) {
    // The analyses' own argument checks, for values the job's validate() let through.
    return {"invalid_request", e.what()};
  } catch (const std::exception& e) {
    return {"internal", e.what()};
  } catch (...) {
    return {"internal", "unknown error"};
  }
}

}  // namespace occlusion::server
