#include "common_options.hpp"

#include <json/value.h>

#include <cstdio>
#include <iostream>

#include "occlusion/app/json_output.hpp"

namespace occlusion::cli {

std::string optional_figure(const std::optional<double>& value, const char* pattern,
                            const char* missing) {
  if (!value) return missing;
  char text[48];
  std::snprintf(text, sizeof text, pattern, *value);
  return text;
}

void print_json(const Json::Value& json) {
  std::cout << format_json(json) << std::endl;
}

void print_warnings(const std::vector<std::string>& warnings) {
  for (const auto& warning : warnings) {
    std::fprintf(stderr, "occlusion: warning: %s\n", warning.c_str());
  }
}

}  // namespace occlusion::cli
