// The JSON config file, through load_config (the file) and config_from_json
// (the same checks on JSON a server request carries). Bad config is a
// UsageError, never anything else.

#include <json/reader.h>

#include <memory>

#include "fuzz_support.hpp"
#include "occlusion/app/config.hpp"
#include "occlusion/app/errors.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace occlusion;
  const std::string path = fuzz::write_input(fuzz::as_text(data, size), "config.json");
  fuzz::expect_only<UsageError>([&] { load_config(path); });

  Json::CharReaderBuilder builder;
  const std::unique_ptr<Json::CharReader> reader(builder.newCharReader());
  Json::Value root;
  std::string errors;
  bool parsed = false;
  try {
    const char* text = reinterpret_cast<const char*>(data);
    parsed = reader->parse(text, text + size, &root, &errors);
  } catch (const Json::Exception&) {
    // JsonCpp's own limits (nesting depth): not what this target tests.
  }
  if (parsed) {
    fuzz::expect_only<UsageError>([&] { config_from_json(root, "/data", "params"); });
  }
  return 0;
}
