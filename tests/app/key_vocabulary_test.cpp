// The one vocabulary, tested from the registry itself: for every job and
// every declared key, the command line, a config file and a server request
// give the same value; an out-of-range value and an unknown key are refused
// by all three, each naming the key as that face spells it.

#include <gtest/gtest.h>
#include <json/writer.h>

#include <cmath>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "occlusion/app/config.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/job_registry.hpp"
#include "occlusion/app/key_sources.hpp"

namespace occlusion {
namespace {

bool is_list(ValueType type) {
  return type == ValueType::kStringList || type == ValueType::kPathList ||
         type == ValueType::kIntegerList || type == ValueType::kNumberList ||
         type == ValueType::kPointList || type == ValueType::kViewpointSets ||
         type == ValueType::kPathEntries;
}

// A valid value of the key, other than its default where the type allows.
Json::Value sample_value(const KeyInfo& info) {
  switch (info.type) {
    case ValueType::kNumber: {
      const double lo = info.min.value_or(0.0);
      const double hi = info.max.value_or(lo + 10.0);
      return lo + (hi - lo) / 7.0;  // strictly inside, so exclusive bounds hold too
    }
    case ValueType::kInteger: {
      const double lo = info.min.value_or(0.0);
      const double hi = std::min(info.max.value_or(1e9), 1e9);
      return Json::UInt64(static_cast<std::uint64_t>(lo + std::floor((hi - lo) / 2.0)));
    }
    case ValueType::kBool:
      return !info.default_value.asBool();
    case ValueType::kString:
      if (!info.choices.empty()) {
        for (const auto& choice : info.choices) {
          if (choice != info.default_value.asString()) return choice;
        }
      }
      return info.name == "shard" ? "1/3" : "some_value";
    case ValueType::kPath:
      return "/tmp/occlusion-vocabulary/" + info.name;
    case ValueType::kStringList: {
      Json::Value list(Json::arrayValue);
      list.append("alpha");
      list.append("beta");
      return list;
    }
    case ValueType::kPathList: {
      Json::Value list(Json::arrayValue);
      list.append("/tmp/occlusion-vocabulary/a");
      list.append("/tmp/occlusion-vocabulary/b");
      return list;
    }
    case ValueType::kIntegerList: {
      Json::Value list(Json::arrayValue);
      list.append(Json::UInt64(static_cast<std::uint64_t>(info.min.value_or(0.0))));
      list.append(Json::UInt64(static_cast<std::uint64_t>(info.max.value_or(3.0))));
      return list;
    }
    case ValueType::kNumberList: {
      Json::Value list(Json::arrayValue);
      list.append(info.min.value_or(0.0) + 1.5);
      list.append(info.min.value_or(0.0) + 2.5);
      return list;
    }
    case ValueType::kPointList: {
      Json::Value list(Json::arrayValue);
      Json::Value point(Json::arrayValue);
      point.append(1.5);
      point.append(-2.0);
      point.append(0.25);
      list.append(point);
      return list;
    }
    case ValueType::kViewpointSets: {
      Json::Value list(Json::arrayValue);
      Json::Value set(Json::objectValue);
      set["name"] = "three";
      set["pattern"] = 3;
      list.append(set);
      return list;
    }
    case ValueType::kPathEntries: {  // a bare path, and an entry setting its first key
      Json::Value list(Json::arrayValue);
      list.append("/tmp/occlusion-vocabulary/a");
      Json::Value entry(Json::objectValue);
      entry["path"] = "/tmp/occlusion-vocabulary/b";
      const KeyInfo& own = info.entry_keys.at(0);
      entry[own.name] = sample_value(own);
      list.append(entry);
      return list;
    }
  }
  return Json::Value();
}

// A value of the right type outside the declared range or choices, if any.
std::optional<Json::Value> out_of_range(const KeyInfo& info) {
  if (!info.choices.empty()) return Json::Value("no_such_choice");
  const bool numeric = info.type == ValueType::kNumber || info.type == ValueType::kInteger;
  if (!numeric) return std::nullopt;
  if (info.max && *info.max < 1e15) {
    const double above = *info.max + 1.0;
    if (info.type == ValueType::kInteger) return Json::UInt64(static_cast<std::uint64_t>(above));
    return above;
  }
  if (info.min && (*info.min > 0.0 || info.min_exclusive)) {
    if (info.type == ValueType::kInteger) {
      return Json::UInt64(static_cast<std::uint64_t>(*info.min) - 1);
    }
    return *info.min - (info.min_exclusive ? 0.0 : 1.0);
  }
  if (info.type == ValueType::kNumber && info.min) return *info.min - 1.0;
  return std::nullopt;
}

std::string number_text(const Json::Value& v) {
  if (v.isUInt64()) return std::to_string(v.asUInt64());
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", v.asDouble());
  return text;
}

std::string item_text(const Json::Value& v) {
  if (v.isString()) return v.asString();
  if (v.isObject()) {  // an entry of a path list: its JSON text, as a shell would pass it
    Json::StreamWriterBuilder writer;
    writer["indentation"] = "";
    return Json::writeString(writer, v);
  }
  if (v.isBool()) return v.asBool() ? "true" : "false";
  if (v.isArray()) {  // a point
    std::string text;
    for (const auto& c : v) text += (text.empty() ? "" : ",") + number_text(c);
    return text;
  }
  return number_text(v);
}

// The command-line arguments that give `value` to the key.
std::vector<std::string> cli_arguments(const JobInfo& job, const KeyInfo& info,
                                       const Json::Value& value) {
  const std::string option = cli_spelling(info);
  std::vector<std::string> args;
  if (info.name == job.positional) {
    if (is_list(info.type)) {
      for (const auto& item : value) args.push_back(item_text(item));
    } else {
      args.push_back(item_text(value));
    }
    return args;
  }
  if (info.type == ValueType::kBool) return {option + "=" + item_text(value)};
  if (info.type == ValueType::kViewpointSets) {  // JSON text, as a shell would pass it
    Json::StreamWriterBuilder writer;
    writer["indentation"] = "";
    return {option, Json::writeString(writer, value)};
  }
  if (is_list(info.type) && info.repeatable) {
    for (const auto& item : value) {
      args.push_back(option);
      args.push_back(item_text(item));
    }
    return args;
  }
  if (is_list(info.type)) {
    std::string joined;
    for (const auto& item : value) joined += (joined.empty() ? "" : ",") + item_text(item);
    return {option, joined};
  }
  return {option, item_text(value)};
}

Json::Value config_file(const JobInfo& job, const std::string& key, const Json::Value& value) {
  Json::Value root;
  root["occlusion"][job.section][key] = value;
  return root;
}

// What a source holds for the key (the value the setter receives).
Json::Value held(const KeySource& source, const std::string& key) {
  const KeyValue* value = source.find(key);
  return value == nullptr ? Json::Value() : value->value;
}

KeySource from_server(const JobInfo& job, const std::string& key, const Json::Value& value) {
  Json::Value params(Json::objectValue);
  params[key] = value;
  return source_from_json(params, job.keys, Face::kServer, "params: ", job.section);
}

std::string thrown_message(const std::function<void()>& call) {
  try {
    call();
  } catch (const UsageError& e) {
    return e.what();
  }
  return "(nothing thrown)";
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(KeyVocabulary, EveryKeyMeansTheSameOnEveryFace) {
  std::size_t checked = 0;
  for (const JobInfo& job : jobs()) {
    for (const KeyInfo& info : job.keys) {
      SCOPED_TRACE(job.name + "." + info.name);
      const Json::Value value = sample_value(info);
      const KeySource cli = source_from_arguments(cli_arguments(job, info, value), job.keys,
                                                  job.cli_names.front(), job.positional);
      const Config config = config_from_json(config_file(job, info.name, value), "", "test.json");
      const KeySource file = config_source(config, job);
      const KeySource server = from_server(job, info.name, value);
      EXPECT_EQ(held(cli, info.name), value);
      EXPECT_EQ(held(file, info.name), value);
      EXPECT_EQ(held(server, info.name), value);
      ++checked;
    }
  }
  EXPECT_GT(checked, 80u);
}

TEST(KeyVocabulary, OutOfRangeIsRefusedByEveryFaceNamingTheKeyItsWay) {
  std::size_t checked = 0;
  for (const JobInfo& job : jobs()) {
    for (const KeyInfo& info : job.keys) {
      const auto bad = out_of_range(info);
      if (!bad || info.name == job.positional) continue;
      SCOPED_TRACE(job.name + "." + info.name + " = " + bad->toStyledString());
      const std::string cli = thrown_message([&] {
        source_from_arguments(cli_arguments(job, info, *bad), job.keys, job.cli_names.front(),
                              job.positional);
      });
      EXPECT_TRUE(contains(cli, cli_spelling(info) + " must be")) << cli;
      const std::string file = thrown_message(
          [&] { config_from_json(config_file(job, info.name, *bad), "", "test.json"); });
      EXPECT_TRUE(
          contains(file, "test.json: 'occlusion." + job.section + "." + info.name + "' must be"))
          << file;
      const std::string server = thrown_message([&] { from_server(job, info.name, *bad); });
      EXPECT_TRUE(contains(server, "params: '" + info.name + "' must be")) << server;
      ++checked;
    }
  }
  EXPECT_GT(checked, 50u);
}

TEST(KeyVocabulary, UnknownKeysAreRefusedByEveryFace) {
  for (const JobInfo& job : jobs()) {
    SCOPED_TRACE(job.name);
    EXPECT_TRUE(contains(thrown_message([&] {
                           source_from_arguments({"--no-such-key", "1"}, job.keys,
                                                 job.cli_names.front(), job.positional);
                         }),
                         "unknown option '--no-such-key'"));
    EXPECT_TRUE(contains(
        thrown_message([&] { config_from_json(config_file(job, "no_such_key", 1), "", "t.json"); }),
        "unknown key 'occlusion." + job.section + ".no_such_key'"));
    EXPECT_TRUE(contains(thrown_message([&] { from_server(job, "no_such_key", 1); }),
                         "unknown key 'no_such_key'"));
  }
}

// A key one job uses but another does not is refused by the other, not
// ignored: -fscan has no rays, -moc no point radius.
TEST(KeyVocabulary, KeysAJobDoesNotUseAreRefused) {
  const JobInfo& scan = *find_job("scan");
  EXPECT_TRUE(contains(thrown_message([&] { from_server(scan, "num_rays_per_vp", 100); }),
                       "unknown key 'num_rays_per_vp'"));
  EXPECT_TRUE(contains(thrown_message([&] {
                         config_from_json(config_file(scan, "light_radius", 0.5), "", "c.json");
                       }),
                       "unknown key 'occlusion.scan.light_radius'"));
  EXPECT_TRUE(
      contains(thrown_message([&] {
                 source_from_arguments({"--sampling", "uniform"}, scan.keys, "-fscan", "path");
               }),
               "unknown option '--sampling' for -fscan"));
  const JobInfo& mesh = *find_job("mesh_occlusion");
  EXPECT_TRUE(contains(thrown_message([&] { from_server(mesh, "point_radius", 0.1); }),
                       "unknown key 'point_radius'"));
}

// The drifts that issue 11 found, each pinned.
TEST(KeyVocabulary, ThreadsAreCappedOnEveryFace) {
  const JobInfo& poc = *find_job("cloud_occlusion");
  EXPECT_TRUE(contains(thrown_message([&] {
                         source_from_arguments({"--threads", "5000"}, poc.keys, "-poc", "path");
                       }),
                       "--threads must be an integer 0..1024"));
  EXPECT_TRUE(contains(
      thrown_message([&] { config_from_json(config_file(poc, "threads", 5000), "", "c.json"); }),
      "'occlusion.point_cloud.threads' must be an integer 0..1024"));
  EXPECT_TRUE(contains(thrown_message([&] { from_server(poc, "threads", 5000); }),
                       "'threads' must be an integer 0..1024"));
  const JobInfo& rgoc = *find_job("region_growing_occlusion");
  EXPECT_TRUE(
      contains(thrown_message([&] { from_server(rgoc, "threads", 40000); }), "'threads' must be"));
}

TEST(KeyVocabulary, ConfigAndServerErrorsDoNotNameCommandLineFlags) {
  const JobInfo& mesh = *find_job("mesh_occlusion");
  const std::string pattern =
      thrown_message([&] { config_from_json(config_file(mesh, "pattern", 9), "", "c.json"); });
  EXPECT_TRUE(contains(pattern, "'occlusion.mesh.pattern' must be an integer 1..7")) << pattern;
  EXPECT_FALSE(contains(pattern, "--"));
  const JobInfo& poc = *find_job("cloud_occlusion");
  const std::string radius = thrown_message([&] { from_server(poc, "point_radius", -1); });
  EXPECT_TRUE(contains(radius, "'point_radius' must be a number in (0, 1000000]")) << radius;
  EXPECT_FALSE(contains(radius, "--"));
}

// Checks that depend on two keys run after the request is filled; their
// messages are re-spelled for the face the key came from.
TEST(KeyVocabulary, CrossKeyErrorsNameTheKeyAsTheUserWroteIt) {
  const JobInfo& rgoc = *find_job("region_growing_occlusion");
  const auto run_with = [&](const KeySource& source) {
    return thrown_message([&] { rgoc.run({source}, {}); });
  };
  const std::string cli = run_with(
      source_from_arguments({"cloud.ply", "--min-cluster-size", "50", "--max-cluster-size", "10"},
                            rgoc.keys, "-rgoc", "path"));
  EXPECT_TRUE(contains(cli, "--max-cluster-size must be at least min_cluster_size")) << cli;
  Json::Value params;
  params["path"] = "cloud.ply";
  params["min_cluster_size"] = 50;
  params["max_cluster_size"] = 10;
  const std::string server =
      run_with(source_from_json(params, rgoc.keys, Face::kServer, "params: ", rgoc.section));
  EXPECT_TRUE(contains(server, "params: 'max_cluster_size' must be at least")) << server;
}

TEST(KeyVocabulary, OneViewpointKindPerSourceAndLaterSourcesOverride) {
  const JobInfo& moc = *find_job("mesh_occlusion");
  EXPECT_TRUE(contains(thrown_message([&] {
                         expanded(source_from_arguments({"--pattern", "3", "--num-vp", "4"},
                                                        moc.keys, "-moc", "path"),
                                  moc.keys);
                       }),
                       "give one of --viewpoint, --pattern or --num-vp"));
  // The config's pattern, then the command line's viewpoint: the viewpoint wins.
  const Config config = config_from_json(config_file(moc, "pattern", 4), "", "c.json");
  std::vector<KeySource> sources = {
      config_source(config, moc),
      source_from_arguments({"--viewpoint", "1,2,3"}, moc.keys, "-moc", "path")};
  EXPECT_EQ(expanded(sources[0], moc.keys).size(), 1u);
  EXPECT_EQ(expanded(sources[1], moc.keys).front().key, "viewpoints");
}

TEST(KeyVocabulary, BooleansAreFlagsOrTakeAValueEverywhere) {
  const JobInfo& poc = *find_job("cloud_occlusion");
  const auto exterior = [&](std::vector<std::string> args) {
    return held(source_from_arguments(args, poc.keys, "-poc", "path"), "exterior");
  };
  EXPECT_EQ(exterior({"--exterior"}), Json::Value(true));
  EXPECT_EQ(exterior({"--exterior", "false"}), Json::Value(false));
  EXPECT_EQ(exterior({"--exterior=no"}), Json::Value(false));
  // A bare flag before the input does not swallow it.
  const KeySource source =
      source_from_arguments({"--exterior", "cloud.ply"}, poc.keys, "-poc", "path");
  EXPECT_EQ(held(source, "exterior"), Json::Value(true));
  EXPECT_EQ(held(source, "path"), Json::Value("cloud.ply"));
  const auto acceleration = [&](std::vector<std::string> args) {
    return held(source_from_arguments(args, poc.keys, "-poc", "path"), "enable_acceleration");
  };
  EXPECT_EQ(acceleration({"--enable-acceleration"}), Json::Value(true));
  EXPECT_EQ(acceleration({"--enable-acceleration", "false"}), Json::Value(false));
  // exterior_classes implies exterior wherever it is given.
  Json::Value params;
  params["exterior_classes"].append("wall");
  const auto values = expanded(
      source_from_json(params, poc.keys, Face::kServer, "params: ", poc.section), poc.keys);
  bool implied = false;
  for (const auto& v : values) implied = implied || (v.key == "exterior" && v.value.asBool());
  EXPECT_TRUE(implied);
}

TEST(KeyVocabulary, StudyPatternsAreNamedAsTheCommandLineNamesThem) {
  const JobInfo& study = *find_job("study");
  Json::Value params;
  params["patterns"].append(3);
  params["out"] = "/tmp/occlusion-vocabulary-study";
  // Run far enough to fill the request; it fails on the missing scenes.
  const std::string message = thrown_message([&] {
    study.run({source_from_json(params, study.keys, Face::kServer, "params: ", study.section)}, {});
  });
  EXPECT_TRUE(contains(message, "no scenes given")) << message;
  const KeySource cli =
      source_from_arguments({"--pattern", "3", "--pattern", "7"}, study.keys, "study", "");
  Json::Value expected(Json::arrayValue);
  expected.append(Json::UInt64(3));
  expected.append(Json::UInt64(7));
  EXPECT_EQ(held(cli, "patterns"), expected);
}

TEST(KeyVocabulary, StudyConfigurationsOnTheCommandLineAreJsonTextAndBadTextIsRefused) {
  const JobInfo& study = *find_job("study");
  const KeySource cli = source_from_arguments(
      {"--configurations",
       R"([{"name": "low", "viewpoints": [[1, 2, 0.5]]}, {"name": "g", "num_vp": 4}])"},
      study.keys, "study", "");
  const Json::Value held_sets = held(cli, "configurations");
  ASSERT_EQ(held_sets.size(), 2u);
  EXPECT_EQ(held_sets[0]["name"].asString(), "low");
  EXPECT_EQ(held_sets[1]["num_vp"].asUInt64(), 4u);
  const std::string message = thrown_message([&] {
    source_from_arguments({"--configurations", "[{\"name\": "}, study.keys, "study", "");
  });
  EXPECT_TRUE(contains(message, "--configurations: not valid JSON")) << message;
}

TEST(KeyVocabulary, HelpListsEveryKeyWithItsDefault) {
  for (const JobInfo& job : jobs()) {
    const std::string help = job_help(job);
    for (const KeyInfo& info : job.keys) {
      if (info.name == job.positional) continue;
      EXPECT_TRUE(contains(help, cli_spelling(info))) << job.name << " " << info.name;
    }
  }
  EXPECT_TRUE(contains(job_help(*find_job("cloud_occlusion")), "default 30000"));
}

TEST(KeyVocabulary, EveryJobHasOneEntryAndUniqueNames) {
  std::set<std::string> names, sections, cli_names;
  for (const JobInfo& job : jobs()) {
    EXPECT_TRUE(names.insert(job.name).second) << job.name;
    EXPECT_TRUE(sections.insert(job.section).second) << job.section;
    for (const auto& cli : job.cli_names) EXPECT_TRUE(cli_names.insert(cli).second) << cli;
    std::set<std::string> keys;
    for (const KeyInfo& info : job.keys) {
      EXPECT_TRUE(keys.insert(info.name).second)
          << job.name << " declares " << info.name << " twice";
      EXPECT_FALSE(info.doc.empty()) << job.name << "." << info.name << " has no doc";
    }
  }
}

}  // namespace
}  // namespace occlusion
