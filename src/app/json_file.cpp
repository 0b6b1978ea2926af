#include "occlusion/app/json_file.hpp"

#include "occlusion/app/errors.hpp"
#include "occlusion/io/file_bytes.hpp"
#include "occlusion/io/input_error.hpp"
#include "occlusion/io/strict_json.hpp"

namespace occlusion {

Json::Value read_json_file(const std::string& path, const std::string& what) {
  std::string body;
  try {
    body = read_file_bytes(path);
  } catch (const InputError& e) {
    throw UsageError(path + ": cannot read " + what + ": " + e.reason);
  }
  return parse_json_text(body, path);
}

Json::Value parse_json_text(const std::string& body, const std::string& source) {
  Json::Value root;
  std::string errors;
  // These files are a few levels deep; deeper is a mistake or an attack.
  if (!parse_strict_json(body, StrictJson{64, false}, root, errors)) {
    throw UsageError(source + ": not valid JSON: " + errors);
  }
  return root;
}

}  // namespace occlusion
