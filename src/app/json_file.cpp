#include "occlusion/app/json_file.hpp"

#include <json/reader.h>

#include <memory>

#include "occlusion/app/errors.hpp"
#include "occlusion/io/file_bytes.hpp"
#include "occlusion/io/input_error.hpp"

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
  Json::CharReaderBuilder builder;
  builder["collectComments"] = false;
  builder["rejectDupKeys"] = true;
  // These files are a few levels deep; deeper is a mistake or an attack.
  builder["stackLimit"] = 64;
  const std::unique_ptr<Json::CharReader> reader(builder.newCharReader());
  Json::Value root;
  std::string errors;
  bool parsed = false;
  try {
    parsed = reader->parse(body.data(), body.data() + body.size(), &root, &errors);
  } catch (const Json::Exception& e) {  // JsonCpp throws on the stack limit
    errors = e.what();
  }
  if (!parsed) {
    while (!errors.empty() && (errors.back() == '\n' || errors.back() == ' ')) errors.pop_back();
    throw UsageError(source + ": not valid JSON: " + errors);
  }
  return root;
}

}  // namespace occlusion
