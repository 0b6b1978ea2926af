#include "occlusion/app/errors.hpp"

#include <new>

#include "occlusion/core/progress.hpp"
#include "occlusion/io/input_error.hpp"

namespace occlusion {

ErrorKind classify(const std::exception& error) {
  if (dynamic_cast<const UsageError*>(&error) != nullptr) return ErrorKind::kUsage;
  if (dynamic_cast<const InputError*>(&error) != nullptr) return ErrorKind::kInput;
  if (dynamic_cast<const OutputError*>(&error) != nullptr) return ErrorKind::kOutput;
  if (dynamic_cast<const Cancelled*>(&error) != nullptr) return ErrorKind::kCancelled;
  if (dynamic_cast<const std::bad_alloc*>(&error) != nullptr) return ErrorKind::kResource;
  // The analyses' own argument checks, for values a job's checks let through.
  if (dynamic_cast<const std::invalid_argument*>(&error) != nullptr) return ErrorKind::kUsage;
  return ErrorKind::kInternal;
}

const char* error_kind_name(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::kUsage:
      return "usage_error";
    case ErrorKind::kInput:
      return "input_error";
    case ErrorKind::kOutput:
      return "output_error";
    case ErrorKind::kCancelled:
      return "cancelled";
    case ErrorKind::kResource:
      return "resource_error";
    case ErrorKind::kInternal:
      return "internal";
  }
  return "internal";
}

}  // namespace occlusion
