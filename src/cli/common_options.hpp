#pragma once
// What the command line's human summaries share.

#include <optional>
#include <string>
#include <vector>

namespace Json {
class Value;
}

namespace occlusion::cli {

// A figure for the human summaries, `missing` when it is undefined.
std::string optional_figure(const std::optional<double>& value, const char* pattern,
                            const char* missing);

// Prints one JSON object on stdout.
void print_json(const Json::Value& json);
// Prints warnings on stderr.
void print_warnings(const std::vector<std::string>& warnings);

}  // namespace occlusion::cli
