#pragma once
// Options every job shares: output mode, config file, viewpoints, seed, threads.

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "occlusion/analysis/progress.hpp"
#include "occlusion/app/viewpoint_choice.hpp"
#include "option_table.hpp"

namespace Json {
class Value;
}

namespace occlusion::cli {

struct OutputOptions {
  bool json = false;
  bool quiet = false;
  bool help = false;
};

// --json, -q/--quiet, -h/--help, and --config FILE (skipped here: the config is
// loaded first by config_path(), so that every other option overrides it).
void add_output_options(OptionTable& table, OutputOptions& output);

// The value of --config, if any.
std::optional<std::string> config_path(const std::vector<std::string>& args);

// --viewpoint X,Y,Z (repeatable), --pattern N and, with allow_grid, --num-vp N.
// Giving two kinds is a usage error; giving none leaves the choice as it was.
struct ViewpointOptions {
  std::vector<Eigen::Vector3d> points;
  std::optional<int> pattern;
  std::optional<std::size_t> grid_count;
  void apply_to(ViewpointChoice& choice) const;
};
void add_viewpoint_options(OptionTable& table, ViewpointOptions& viewpoints, bool allow_grid);

void add_seed_option(OptionTable& table, std::uint64_t& seed);

// The handler for a command's one positional argument (its input): sets `path`
// (overriding the config's) and rejects a second one.
std::function<void(const std::string&)> single_input(std::string& path, const std::string& command);
void add_threads_option(OptionTable& table, unsigned& threads);

// For a repeatable option that fills a config list: the first value given on
// the command line replaces the config's list, the next ones add to it.
// `replaced` lives with the caller: option aliases hold separate copies of a handler.
void add_to_list(std::vector<std::string>& list, bool& replaced, const std::string& value);

// A figure for the human summaries, `missing` when it is undefined.
std::string optional_figure(const std::optional<double>& value, const char* pattern,
                            const char* missing);

// Prints one JSON object on stdout.
void print_json(const Json::Value& json);
// Prints warnings on stderr.
void print_warnings(const std::vector<std::string>& warnings);

}  // namespace occlusion::cli
