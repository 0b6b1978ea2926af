#pragma once
// What the command line's human summaries share.

#include <optional>
#include <string>
#include <vector>

namespace Json {
class Value;
}

namespace occlusion {
struct StationFilterReport;
}

namespace occlusion::cli {

// A figure for the human summaries, `missing` when it is undefined.
std::string optional_figure(const std::optional<double>& value, const char* pattern,
                            const char* missing);

// Prints one JSON object on stdout.
void print_json(const Json::Value& json);
// Where a cloud job's viewpoints came from, and what scans / min_range /
// max_range dropped (when they dropped anything), on stdout.
void print_viewpoints_and_filter(const std::string& viewpoint_source,
                                 const StationFilterReport& filter);
// Prints warnings on stderr.
void print_warnings(const std::vector<std::string>& warnings);

}  // namespace occlusion::cli
