#include "job_options.hpp"

#include <limits>

#include "arguments.hpp"
#include "common_options.hpp"
#include "occlusion/app/errors.hpp"

namespace occlusion::cli {

namespace {

unsigned parse_count(const std::string& option, const std::string& text) {
  const std::uint64_t value = parse_unsigned(option, text);
  if (value > std::numeric_limits<unsigned>::max()) throw UsageError(option + " is too large");
  return static_cast<unsigned>(value);
}

}  // namespace

void add_estimation_options(OptionTable& table, RegionGrowingOptions& e) {
  table.value({"--normal-k"}, [&e](const std::string& option, const std::string& v) {
    e.normal_k = parse_count(option, v);
  });
  table.value({"--min-cluster-size"}, [&e](const std::string& option, const std::string& v) {
    e.min_cluster_size = parse_unsigned(option, v);
  });
  table.value({"--max-cluster-size"}, [&e](const std::string& option, const std::string& v) {
    e.max_cluster_size = parse_unsigned(option, v);
  });
  table.value({"--neighbours"}, [&e](const std::string& option, const std::string& v) {
    e.neighbours = parse_count(option, v);
  });
  table.value({"--smoothness-degrees"}, [&e](const std::string& option, const std::string& v) {
    e.smoothness_degrees = parse_number(option, v);
  });
  table.value({"--curvature-threshold"}, [&e](const std::string& option, const std::string& v) {
    e.curvature_threshold = parse_number(option, v);
  });
  table.value({"--ransac-distance"}, [&e](const std::string& option, const std::string& v) {
    e.ransac_distance = parse_number(option, v);
  });
  table.value({"--ransac-iterations"}, [&e](const std::string& option, const std::string& v) {
    e.ransac_iterations = parse_count(option, v);
  });
  table.value({"--recover-edges"}, [&e](const std::string& option, const std::string& v) {
    e.recover_edges = parse_bool(option, v);
  });
}

void add_tracing_options(OptionTable& table, CloudOcclusionRequest& request) {
  add_seed_option(table, request.seed);
  add_threads_option(table, request.threads);
  table.value({"--num-rays-per-vp"}, [&](const std::string& option, const std::string& v) {
    request.num_rays_per_vp = parse_unsigned(option, v);
  });
  table.value({"--point-radius"}, [&](const std::string& option, const std::string& v) {
    request.point_radius = parse_number(option, v);
  });
  table.value({"--polygon-path"},
              [&](const std::string&, const std::string& v) { request.polygon_path = v; });
  table.value({"--octree-resolution"}, [&](const std::string& option, const std::string& v) {
    request.octree_resolution = parse_number(option, v);
  });
  table.value({"--enable-acceleration"}, [&](const std::string& option, const std::string& v) {
    request.enable_acceleration = parse_bool(option, v);
  });
  table.value({"--sampling"},
              [&](const std::string&, const std::string& v) { request.sampling = v; });
  table.value({"--light-radius"}, [&](const std::string& option, const std::string& v) {
    request.light_radius = parse_number(option, v);
  });
  table.flag({"--exterior"}, [&] { request.exterior = true; });
  table.value({"--exterior-classes"}, [&](const std::string&, const std::string& v) {
    request.exterior_classes = split_list(v);
    request.exterior = true;
  });
  table.flag({"--skip-bad-lines"}, [&] { request.skip_bad_lines = true; });
}

}  // namespace occlusion::cli
