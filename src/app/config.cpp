#include "occlusion/app/config.hpp"

#include <json/reader.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "occlusion/app/errors.hpp"
#include "occlusion/app/job_registry.hpp"

namespace occlusion {

namespace {

[[noreturn]] void fail(const Config& config, const std::string& message) {
  throw UsageError(config.path + ": " + message);
}

std::string resolve(const Config& config, const std::string& path) {
  const std::filesystem::path p(path);
  if (p.is_absolute() || config.directory.empty()) return path;
  return (std::filesystem::path(config.directory) / p).lexically_normal().string();
}

KeySource section_source(const Config& config, const std::string& section) {
  const JobInfo* job = find_job_by_section(section);
  if (job == nullptr) fail(config, "unknown key 'occlusion." + section + "'");
  return source_from_json(
      config.root["occlusion"][section], job->keys, Face::kConfig, config.path + ": ", section,
      [&config](const std::string& path, bool) { return resolve(config, path); });
}

void check(const Config& config) {
  if (!config.root.isObject()) fail(config, "the top level must be an object");
  for (const auto& top_key : config.root.getMemberNames()) {
    if (top_key != "occlusion") fail(config, "unknown key '" + top_key + "'");
  }
  if (!config.root.isMember("occlusion")) fail(config, "missing key 'occlusion'");
  const Json::Value& occlusion = config.root["occlusion"];
  if (!occlusion.isObject()) fail(config, "'occlusion' must be an object");
  for (const auto& section : occlusion.getMemberNames()) section_source(config, section);
}

}  // namespace

Config load_config(const std::string& path) {
  Config config;
  config.path = path;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UsageError(path + ": cannot open config file");
  std::ostringstream text;
  text << in.rdbuf();
  const std::string body = text.str();

  Json::CharReaderBuilder builder;
  builder["collectComments"] = false;
  builder["rejectDupKeys"] = true;
  builder["stackLimit"] = 64;  // a config is a few levels deep; deeper is a mistake or an attack
  const std::unique_ptr<Json::CharReader> reader(builder.newCharReader());
  std::string errors;
  try {
    if (!reader->parse(body.data(), body.data() + body.size(), &config.root, &errors)) {
      throw UsageError(path + ": not valid JSON: " + errors);
    }
  } catch (const Json::Exception& e) {
    throw UsageError(path + ": not valid JSON: " + e.what());
  }
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

KeySource config_source(const Config& config, const JobInfo& job) {
  if (!config.root["occlusion"].isMember(job.section)) {
    KeySource empty;
    empty.face = Face::kConfig;
    empty.prefix = config.path + ": ";
    empty.section = job.section;
    return empty;
  }
  return section_source(config, job.section);
}

}  // namespace occlusion
