#include "occlusion/app/config.hpp"

#include <json/value.h>

#include <algorithm>
#include <filesystem>
#include <initializer_list>
#include <limits>
#include <map>

#include "occlusion/app/errors.hpp"
#include "occlusion/app/json_file.hpp"

namespace occlusion {

namespace {

enum class KeyType {
  kString,
  kNumber,
  kUnsigned,
  kBool,
  kPointList,
  kStringList,
  kViewpointSets,  // [{"name": ..., "pattern" | "num_vp" | "viewpoints": ...}, ...]
};

using Schema = std::map<std::string, KeyType>;

Schema joined(std::initializer_list<Schema> parts) {
  Schema all;
  for (const auto& part : parts) all.insert(part.begin(), part.end());
  return all;
}

// Groups of keys that several sections share, so that a key means the same
// thing (and has the same type) wherever it appears.
const Schema kViewpointKeys = {{"pattern", KeyType::kUnsigned},
                               {"viewpoints", KeyType::kPointList},
                               {"num_vp", KeyType::kUnsigned}};
// How a point cloud is traced (-poc and -fscan), also per run of the study.
const Schema kCloudTracingKeys = {{"num_rays_per_vp", KeyType::kUnsigned},
                                  {"point_radius", KeyType::kNumber},
                                  {"polygon_path", KeyType::kString},
                                  {"octree_resolution", KeyType::kNumber},
                                  {"enable_acceleration", KeyType::kBool},
                                  {"sampling", KeyType::kString},
                                  {"light_radius", KeyType::kNumber},
                                  {"exterior", KeyType::kBool},
                                  {"exterior_classes", KeyType::kStringList},
                                  {"self_tolerance", KeyType::kNumber},
                                  {"format", KeyType::kString},
                                  {"skip_bad_lines", KeyType::kBool},
                                  {"seed", KeyType::kUnsigned},
                                  {"threads", KeyType::kUnsigned}};
// Region growing (-rgoc, extract_polygons, the study's baseline segmenter).
const Schema kEstimationKeys = {
    {"normal_k", KeyType::kUnsigned},         {"min_cluster_size", KeyType::kUnsigned},
    {"max_cluster_size", KeyType::kUnsigned}, {"neighbours", KeyType::kUnsigned},
    {"smoothness_degrees", KeyType::kNumber}, {"curvature_threshold", KeyType::kNumber},
    {"ransac_distance", KeyType::kNumber},    {"ransac_iterations", KeyType::kUnsigned},
    {"recover_edges", KeyType::kBool}};
// How a segmentation is scored (-eval, the study).
const Schema kScoringKeys = {{"mapping_path", KeyType::kString},
                             {"ignored_classes", KeyType::kStringList},
                             {"max_distance", KeyType::kNumber}};

// Sections and their keys. point_cloud is the seed's section for -poc; it is
// checked here so that a config written for every job loads for any job.
const std::map<std::string, Schema>& sections() {
  static const std::map<std::string, Schema> kSections = {
      {"mesh", joined({kViewpointKeys,
                       {{"path", KeyType::kString},
                        {"octree_resolution", KeyType::kNumber},
                        {"enable_acceleration", KeyType::kBool},
                        {"samples_per_unit_area", KeyType::kNumber},
                        {"seed", KeyType::kUnsigned},
                        {"threads", KeyType::kUnsigned},
                        {"out", KeyType::kString}}})},
      // -poc and -fscan both read this section (the seed's "point_cloud").
      {"point_cloud", joined({kViewpointKeys,
                              kCloudTracingKeys,
                              {{"path", KeyType::kString},
                               {"escape_directions", KeyType::kBool},
                               {"out", KeyType::kString}}})},
      {"reconstruct",
       {{"path", KeyType::kString},
        {"format", KeyType::kString},
        {"skip_bad_lines", KeyType::kBool},
        {"out", KeyType::kString}}},
      {"region_growing", joined({kViewpointKeys,
                                 kEstimationKeys,
                                 {{"path", KeyType::kString},
                                  {"samples_per_unit_area", KeyType::kNumber},
                                  {"octree_resolution", KeyType::kNumber},
                                  {"enable_acceleration", KeyType::kBool},
                                  {"seed", KeyType::kUnsigned},
                                  {"threads", KeyType::kUnsigned},
                                  {"skip_bad_lines", KeyType::kBool},
                                  {"out", KeyType::kString}}})},
      {"evaluate", joined({kScoringKeys,
                           {{"ground_truth", KeyType::kStringList},
                            {"predictions", KeyType::kStringList},
                            {"skip_bad_lines", KeyType::kBool},
                            {"threads", KeyType::kUnsigned},
                            {"out", KeyType::kString}}})},
      {"study", joined({kCloudTracingKeys,
                        kEstimationKeys,
                        kScoringKeys,
                        {{"scenes", KeyType::kStringList},
                         {"configurations", KeyType::kViewpointSets},
                         {"occlusion_num_vp", KeyType::kUnsigned},
                         {"segmenter", KeyType::kString},
                         {"segmenter_output", KeyType::kString},
                         {"shard", KeyType::kString},
                         {"out", KeyType::kString}}})},
  };
  return kSections;
}

const char* type_name(KeyType type) {
  switch (type) {
    case KeyType::kString:
      return "a string";
    case KeyType::kNumber:
      return "a number";
    case KeyType::kUnsigned:
      return "a non-negative integer";
    case KeyType::kBool:
      return "true or false";
    case KeyType::kPointList:
      return "a list of [x, y, z] points";
    case KeyType::kStringList:
      return "a list of strings";
    case KeyType::kViewpointSets:
      return "a list of {\"name\", and \"pattern\", \"num_vp\" or \"viewpoints\"} objects";
  }
  return "?";
}

bool has_type(const Json::Value& value, KeyType type) {
  switch (type) {
    case KeyType::kString:
      return value.isString();
    case KeyType::kNumber:
      return value.isNumeric() && !value.isBool();
    case KeyType::kUnsigned:
      return (value.isUInt64() || (value.isInt64() && value.asInt64() >= 0)) && !value.isBool() &&
             value.isIntegral();
    case KeyType::kBool:
      return value.isBool();
    case KeyType::kPointList:
      if (!value.isArray()) return false;
      for (const auto& point : value) {
        if (!point.isArray() || point.size() != 3) return false;
        for (const auto& coordinate : point) {
          if (!coordinate.isNumeric() || coordinate.isBool()) return false;
        }
      }
      return true;
    case KeyType::kStringList:
      if (!value.isArray()) return false;
      for (const auto& item : value) {
        if (!item.isString()) return false;
      }
      return true;
    case KeyType::kViewpointSets:
      return value.isArray();  // the items: check_viewpoint_sets, which names the item
  }
  return false;
}

[[noreturn]] void fail(const Config& config, const std::string& message) {
  throw UsageError(config.path + ": " + message);
}

void check_object(const Config& config, const Json::Value& value, const std::string& where) {
  if (!value.isObject()) fail(config, "'" + where + "' must be an object");
}

const Schema kViewpointSetKeys = joined({kViewpointKeys, {{"name", KeyType::kString}}});

void check_viewpoint_sets(const Config& config, const Json::Value& list, const std::string& where) {
  for (Json::ArrayIndex i = 0; i < list.size(); ++i) {
    const std::string item = where + "[" + std::to_string(i) + "]";
    const Json::Value& set = list[i];
    check_object(config, set, item);
    for (const auto& key : set.getMemberNames()) {
      const auto entry = kViewpointSetKeys.find(key);
      if (entry == kViewpointSetKeys.end()) fail(config, "unknown key '" + item + "." + key + "'");
      if (!has_type(set[key], entry->second)) {
        fail(config, "'" + item + "." + key + "' must be " + type_name(entry->second));
      }
    }
    if (!set.isMember("name")) fail(config, "'" + item + "' needs a \"name\"");
    const int kinds = static_cast<int>(set.isMember("pattern")) +
                      static_cast<int>(set.isMember("num_vp")) +
                      static_cast<int>(set.isMember("viewpoints"));
    if (kinds != 1) {
      fail(config, "'" + item + "' needs exactly one of \"pattern\", \"num_vp\" or \"viewpoints\"");
    }
  }
}

void check(const Config& config) {
  check_object(config, config.root, "(top level)");
  for (const auto& top_key : config.root.getMemberNames()) {
    if (top_key != "occlusion") fail(config, "unknown key '" + top_key + "'");
  }
  if (!config.root.isMember("occlusion")) fail(config, "missing key 'occlusion'");
  const Json::Value& occlusion = config.root["occlusion"];
  check_object(config, occlusion, "occlusion");
  for (const auto& section_name : occlusion.getMemberNames()) {
    const auto section = sections().find(section_name);
    const std::string where = "occlusion." + section_name;
    if (section == sections().end()) fail(config, "unknown key '" + where + "'");
    const Json::Value& body = occlusion[section_name];
    check_object(config, body, where);
    for (const auto& key : body.getMemberNames()) {
      const auto entry = section->second.find(key);
      if (entry == section->second.end()) {
        fail(config, "unknown key '" + where + "." + key + "'");
      }
      if (!has_type(body[key], entry->second)) {
        fail(config, "'" + where + "." + key + "' must be " + type_name(entry->second));
      }
      if (entry->second == KeyType::kViewpointSets) {
        check_viewpoint_sets(config, body[key], where + "." + key);
      }
    }
  }
}

// {"pattern": 7} or {"num_vp": 9} or {"viewpoints": [[x, y, z], ...]}, at most one (checked).
void read_choice(const Json::Value& body, ViewpointChoice& out) {
  if (body.isMember("viewpoints")) {
    std::vector<Eigen::Vector3d> points;
    for (const auto& point : body["viewpoints"]) {
      points.emplace_back(point[0].asDouble(), point[1].asDouble(), point[2].asDouble());
    }
    out = ViewpointChoice::from_points(points);
  }
  if (body.isMember("pattern")) {
    out = ViewpointChoice::from_pattern(
        static_cast<int>(std::min<Json::UInt64>(body["pattern"].asUInt64(), 1000)));
  }
  if (body.isMember("num_vp")) {
    out = ViewpointChoice::from_grid(static_cast<std::size_t>(body["num_vp"].asUInt64()));
  }
}

std::string resolve(const Config& config, const std::string& path) {
  const std::filesystem::path p(path);
  if (p.is_absolute() || config.directory.empty()) return path;
  return (std::filesystem::path(config.directory) / p).lexically_normal().string();
}

}  // namespace

Config load_config(const std::string& path) {
  Config config;
  config.path = path;
  config.root = read_json_file(path, "config file");
  config.directory = std::filesystem::path(path).parent_path().string();
  check(config);
  return config;
}

Config config_from_json(const Json::Value& root, const std::string& directory,
                        const std::string& name) {
  Config config;
  config.root = root;
  config.directory = directory;
  config.path = name;
  check(config);
  return config;
}

ConfigSection::ConfigSection(const Config& config, const std::string& name)
    : config_(config), name_(name), body_(config.root["occlusion"][name]) {}

bool ConfigSection::has(const std::string& key) const {
  return body_.isObject() && body_.isMember(key);
}

void ConfigSection::read(const std::string& key, std::string& out) const {
  if (has(key)) out = body_[key].asString();
}

void ConfigSection::read_path(const std::string& key, std::string& out) const {
  if (!has(key)) return;
  const std::string path = body_[key].asString();
  out = path.empty() ? path : resolve(config_, path);
}

void ConfigSection::read(const std::string& key, double& out) const {
  if (has(key)) out = body_[key].asDouble();
}

void ConfigSection::read(const std::string& key, bool& out) const {
  if (has(key)) out = body_[key].asBool();
}

void ConfigSection::read(const std::string& key, std::uint64_t& out) const {
  if (has(key)) out = body_[key].asUInt64();
}

void ConfigSection::read(const std::string& key, unsigned& out) const {
  if (!has(key)) return;
  const Json::UInt64 value = body_[key].asUInt64();
  if (value > std::numeric_limits<unsigned>::max()) {
    fail(config_, "'occlusion." + name_ + "." + key + "' is too large");
  }
  out = static_cast<unsigned>(value);
}

void ConfigSection::read(const std::string& key, std::vector<std::string>& out) const {
  if (!has(key)) return;
  out.clear();
  for (const auto& item : body_[key]) out.push_back(item.asString());
}

void ConfigSection::read_paths(const std::string& key, std::vector<std::string>& out) const {
  if (!has(key)) return;
  read(key, out);
  for (auto& path : out) path = resolve(config_, path);
}

void ConfigSection::read_viewpoints(ViewpointChoice& out) const {
  const int kinds =
      (has("viewpoints") ? 1 : 0) + (has("pattern") ? 1 : 0) + (has("num_vp") ? 1 : 0);
  if (kinds > 1) {
    fail(config_, "occlusion." + name_ + ": give one of 'viewpoints', 'pattern' or 'num_vp'");
  }
  if (kinds == 1) read_choice(body_, out);
}

void ConfigSection::read(const std::string& key, std::vector<NamedViewpointChoice>& out) const {
  if (!has(key)) return;
  out.clear();
  for (const auto& set : body_[key]) {
    NamedViewpointChoice named;
    named.name = set["name"].asString();
    read_choice(set, named.choice);
    out.push_back(named);
  }
}

}  // namespace occlusion
