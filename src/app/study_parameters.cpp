// The study's parameters: what study.json lists, what a row's fingerprint
// hashes, and the file (study.parameters.json) a resume and a merge compare.

#include <json/writer.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "job_support.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/json_output.hpp"
#include "occlusion/app/study_job.hpp"
#include "occlusion/io/input_error.hpp"
#include "occlusion/io/strict_json.hpp"
#include "region_growing_support.hpp"
#include "study_support.hpp"

namespace occlusion::job {

namespace {

// One line, keys sorted (jsoncpp's objects are ordered maps): the same
// parameters give the same text on every machine.
// 17 digits tell every double apart; 15 show 0.06 as 0.06, for people.
std::string canonical(const Json::Value& json, int digits = 17) {
  Json::StreamWriterBuilder builder;
  builder["indentation"] = "";
  builder["precision"] = digits;
  return Json::writeString(builder, json);
}

// By text, not Json::Value's ==: a count read back from a file is an Int
// where the request's was a UInt.
bool same(const Json::Value& a, const Json::Value& b) {
  return canonical(a) == canonical(b);
}

// FNV-1a, 64 bits: stable across compilers and machines, unlike std::hash.
std::uint64_t fnv1a(const std::string& text) {
  std::uint64_t hash = 1469598103934665603ULL;
  for (const unsigned char c : text) {
    hash ^= c;
    hash *= 1099511628211ULL;
  }
  return hash;
}

std::string hex(std::uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}

// What a file holds, not where it is: shards on machines that mount the data
// elsewhere, and the server (which resolves paths), make the same rows.
// Empty for no file; a file that cannot be read is reported where it is read.
std::string content_digest(const std::string& path) {
  if (path.empty()) return "";
  std::ifstream in(path, std::ios::binary);
  if (!in) return "unreadable";
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return hex(fnv1a(text));
}

}  // namespace

// Every declared key that can change a row's figures (from the declarations,
// so a new key joins the fingerprint by being declared); not which scenes and
// configurations, where files go or how the work is spread. Files count by
// their contents.
Json::Value row_parameters(const StudyRequest& q) {
  Json::Value p = parameters_json(study_keys(), q);
  for (const char* key :
       {"scenes", "configurations", "patterns", "shard", "out", "threads", "skip_failed", "fresh",
        "segmenter_timeout", "polygon_path", "mapping_path", "max_memory_mb", "compare_with"}) {
    p.removeMember(key);
  }
  // Keys declared after studies were first run, whose default leaves every row
  // as it was: they join the fingerprint only when set, so a study run before
  // they existed still resumes.
  static const Json::Value defaults = parameters_json(study_keys(), StudyRequest{});
  for (const char* key : {"scans", "min_range", "max_range", "class_mapping", "class_names",
                          "frame", "up", "scoring", "scan_model"}) {
    if (p.isMember(key) && same(p[key], defaults[key])) p.removeMember(key);
  }
  // An ideal scan uses no sensor: its rows stay when only the laser changes.
  if (q.scan_model == kIdealScan) {
    for (const auto& k : study_sensor_keys()) p.removeMember(k.info.name);
  }
  p["segmenter"] = segmenter_name(q.segmenter);
  p["polygon_file"] = content_digest(q.tracing.polygon_path);
  p["mapping_file"] = content_digest(q.mapping_path);
  return p;
}

Json::Value scene_overrides(const StudyRequest& q) {
  Json::Value all(Json::objectValue);
  const std::vector<std::string> names = scene_names(q.scenes);
  for (std::size_t s = 0; s < q.scenes.size(); ++s) {
    Json::Value overrides = q.scenes[s].overrides;
    if (overrides.empty()) continue;
    if (overrides.isMember("polygon_path")) {
      overrides["polygon_file"] = content_digest(overrides["polygon_path"].asString());
      overrides.removeMember("polygon_path");
    }
    all[names[s]] = overrides;
  }
  return all;
}

Json::Value study_parameters(const StudyRequest& q) {
  Json::Value p = row_parameters(q);
  p["polygon_path"] = q.tracing.polygon_path;
  p["mapping_path"] = q.mapping_path;
  p["scenes"] = parameters_json(study_keys(), q)["scenes"];
  p["scene_overrides"] = scene_overrides(q);
  Json::Value configurations(Json::arrayValue);
  for (const auto& configuration : q.configurations) {
    Json::Value entry = configuration.choice.to_json();
    entry["name"] = configuration.name;
    configurations.append(entry);
  }
  p["configurations"] = configurations;
  return p;
}

Json::Value row_parameters_of(const Json::Value& study_parameters) {
  Json::Value p = study_parameters;
  for (const char* key :
       {"scenes", "scene_overrides", "configurations", "polygon_path", "mapping_path"}) {
    p.removeMember(key);
  }
  return p;
}

Json::Value scene_overrides_of(const Json::Value& study_parameters, const std::string& scene) {
  const Json::Value& all = study_parameters["scene_overrides"];
  return all.isObject() && all.isMember(scene) ? all[scene] : Json::Value(Json::objectValue);
}

Json::Value configuration_of(const Json::Value& study_parameters, const std::string& name) {
  for (const auto& entry : study_parameters["configurations"]) {
    if (entry["name"] == name) return entry;
  }
  return Json::Value();
}

std::string row_fingerprint(const Json::Value& row_parameters,
                            const NamedViewpointChoice& configuration) {
  return hex(fnv1a(canonical(row_parameters) + '\n' + canonical(configuration.choice.to_json())));
}

std::vector<std::string> differing_keys(const Json::Value& before, const Json::Value& now) {
  std::vector<std::string> keys;
  for (const auto& key : now.getMemberNames()) {
    if (!before.isMember(key) || !same(before[key], now[key])) keys.push_back(key);
  }
  for (const auto& key : before.getMemberNames()) {
    if (!now.isMember(key)) keys.push_back(key);
  }
  return keys;
}

std::string describe_differences(const Json::Value& before, const Json::Value& now) {
  std::string text;
  for (const auto& key : differing_keys(before, now)) {
    text += (text.empty() ? "" : ", ") + key + " (was " +
            (before.isMember(key) ? canonical(before[key], 15) : "absent") + ", now " +
            (now.isMember(key) ? canonical(now[key], 15) : "absent") + ")";
  }
  return text;
}

std::string parameters_path(const std::string& out) {
  return (std::filesystem::path(out) / "study.parameters.json").string();
}

std::optional<Json::Value> read_parameters(const std::string& path) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  Json::Value json;
  std::string errors;
  if (!parse_strict_json(text, StrictJson{}, json, errors) || !json.isObject()) {
    throw InputError(path, 0,
                     "not a study's parameters (" + errors + "); remove it, or give another --out");
  }
  return json;
}

void write_parameters(const std::string& path, const Json::Value& parameters) {
  write_json_report(path, parameters);
}

}  // namespace occlusion::job
