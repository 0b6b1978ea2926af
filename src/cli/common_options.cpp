#include "common_options.hpp"

#include <json/value.h>

#include <cstdio>
#include <iostream>

#include "occlusion/app/json_output.hpp"
#include "occlusion/app/station_filter.hpp"

namespace occlusion::cli {

void print_viewpoints_and_filter(const std::string& viewpoint_source,
                                 const StationFilterReport& filter) {
  std::printf("  viewpoints: %s\n", viewpoint_source.c_str());
  if (filter.other_scans + filter.too_near + filter.too_far == 0) return;
  std::printf(
      "  dropped at load: %zu points of other scans, %zu nearer than min_range, %zu farther "
      "than max_range\n",
      filter.other_scans, filter.too_near, filter.too_far);
}

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
