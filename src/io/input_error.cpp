#include "occlusion/io/input_error.hpp"

#include <utility>

namespace occlusion {
namespace {

std::string located_message(const std::string& path, std::size_t line, const std::string& reason) {
  if (line == 0) return path + ": " + reason;
  return path + ":" + std::to_string(line) + ": " + reason;
}

}  // namespace

InputError::InputError(std::string path_, std::size_t line_, std::string reason_)
    : std::runtime_error(located_message(path_, line_, reason_)),
      path(std::move(path_)),
      line(line_),
      reason(std::move(reason_)) {}

OutputError::OutputError(std::string path_, std::string reason_)
    : std::runtime_error(located_message(path_, 0, reason_)),
      path(std::move(path_)),
      reason(std::move(reason_)) {}

}  // namespace occlusion
