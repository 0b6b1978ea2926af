#include "common_options.hpp"

#include <json/value.h>

#include <cstdio>
#include <iostream>

#include "arguments.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/json_output.hpp"

namespace occlusion::cli {

void add_output_options(OptionTable& table, OutputOptions& output) {
  table.flag({"--json"}, [&output] { output.json = true; });
  table.flag({"-q", "--quiet"}, [&output] { output.quiet = true; });
  table.flag({"-h", "--help"}, [&output] { output.help = true; });
  table.value({"--config"}, [](const std::string&, const std::string&) {});
}

std::optional<std::string> config_path(const std::vector<std::string>& args) {
  std::optional<std::string> path;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] != "--config") continue;
    if (i + 1 >= args.size()) throw UsageError("--config needs a value");
    if (path) throw UsageError("--config given twice");
    path = args[i + 1];
  }
  return path;
}

void ViewpointOptions::apply_to(ViewpointChoice& choice) const {
  const int kinds = (points.empty() ? 0 : 1) + (pattern ? 1 : 0) + (grid_count ? 1 : 0);
  if (kinds > 1) throw UsageError("give one of --viewpoint, --pattern or --num-vp");
  if (!points.empty()) choice = ViewpointChoice::from_points(points);
  if (pattern) choice = ViewpointChoice::from_pattern(*pattern);
  if (grid_count) choice = ViewpointChoice::from_grid(*grid_count);
}

void add_viewpoint_options(OptionTable& table, ViewpointOptions& viewpoints, bool allow_grid) {
  table.value({"--viewpoint"}, [&viewpoints](const std::string& option, const std::string& v) {
    viewpoints.points.push_back(parse_point(option, v));
  });
  table.value({"--pattern"}, [&viewpoints](const std::string& option, const std::string& v) {
    const auto pattern = parse_unsigned(option, v);
    if (pattern < 1 || pattern > 7) {
      throw UsageError("--pattern must be 1..7, got " + std::to_string(pattern));
    }
    viewpoints.pattern = static_cast<int>(pattern);
  });
  if (allow_grid) {
    table.value({"--num-vp"}, [&viewpoints](const std::string& option, const std::string& v) {
      viewpoints.grid_count = parse_unsigned(option, v);
    });
  }
}

void add_seed_option(OptionTable& table, std::uint64_t& seed) {
  table.value({"--seed"}, [&seed](const std::string& option, const std::string& v) {
    seed = parse_unsigned(option, v);
  });
}

std::function<void(const std::string&)> single_input(std::string& path,
                                                     const std::string& command) {
  return [&path, command, given = false](const std::string& positional) mutable {
    if (given) {
      throw UsageError("unexpected argument '" + positional + "': " + command + " takes one input");
    }
    path = positional;
    given = true;
  };
}

void add_threads_option(OptionTable& table, unsigned& threads) {
  table.value({"--threads"}, [&threads](const std::string& option, const std::string& v) {
    const auto count = parse_unsigned(option, v);
    if (count > 1024) throw UsageError("--threads must be at most 1024");
    threads = static_cast<unsigned>(count);
  });
}

void add_to_list(std::vector<std::string>& list, bool& replaced, const std::string& value) {
  if (!replaced) list.clear();
  replaced = true;
  list.push_back(value);
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
