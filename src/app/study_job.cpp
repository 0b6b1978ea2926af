#include "occlusion/app/study_job.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <set>

#include "evaluation_support.hpp"
#include "job_support.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/json_output.hpp"
#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "region_growing_support.hpp"
#include "study_support.hpp"

namespace occlusion::job {

std::vector<std::string> scene_names(const std::vector<StudyScene>& scenes) {
  const auto name = [](const std::string& scene, bool with_parent) {
    std::filesystem::path path(scene);
    if (path.filename().empty()) path = path.parent_path();
    const std::string stem = cloud_file_stem(path.string());
    return with_parent ? path.parent_path().filename().string() + "/" + stem : stem;
  };
  std::map<std::string, std::size_t> count;
  for (const auto& scene : scenes) ++count[name(scene.path, false)];
  std::vector<std::string> names;
  std::set<std::string> taken;
  for (const auto& scene : scenes) {
    names.push_back(name(scene.path, count[name(scene.path, false)] > 1));
    if (!taken.insert(names.back()).second) {
      throw UsageError("two scenes are both called '" + names.back() + "' (" + scene.path +
                       "); give each scene once, from folders with different names");
    }
  }
  return names;
}

}  // namespace occlusion::job

namespace occlusion {

namespace {

namespace fs = std::filesystem;

// "4:05" or "1:02:03".
std::string duration(double seconds) {
  const auto whole = static_cast<long long>(seconds + 0.5);
  char text[32];
  if (whole >= 3600) {
    std::snprintf(text, sizeof text, "%lld:%02lld:%02lld", whole / 3600, whole / 60 % 60,
                  whole % 60);
  } else {
    std::snprintf(text, sizeof text, "%lld:%02lld", whole / 60, whole % 60);
  }
  return text;
}

// A run's steps as stages of the whole shard: "[run 2/6, 0:42 elapsed, ~1:24
// left] office_1 pattern_4: scanning", with the fraction of the runs to make
// that is done. The estimate is the mean time of the runs made so far times
// the runs left (this one included); none before the first run ends.
Progress run_progress(const Progress& outer, const std::string& name, std::size_t position,
                      std::size_t runs, double elapsed) {
  std::string prefix = "[run " + std::to_string(position) + "/" + std::to_string(runs) + ", " +
                       duration(elapsed) + " elapsed";
  if (position > 1) {
    const double per_run = elapsed / static_cast<double>(position - 1);
    prefix += ", ~" + duration(per_run * static_cast<double>(runs - position + 1)) + " left";
  }
  prefix += "] " + name + ": ";
  Progress inner;
  inner.cancel = outer.cancel;
  inner.report = [=](const std::string& stage, double fraction) {
    outer(prefix + stage,
          (static_cast<double>(position - 1) + fraction) / static_cast<double>(runs));
  };
  return inner;
}

// The rows of `table` for this study's runs that were made with other
// parameters. When only their scenes' own settings differ (the study-wide
// parameters and the configurations are as study.parameters.json has them),
// those rows are dropped, to be made again, with a warning per scene;
// otherwise UsageError naming the keys that differ.
void check_fingerprints(CsvTable& table, const std::map<std::string, std::string>& expected,
                        const Json::Value& now, const std::string& out,
                        std::vector<std::string>& warnings) {
  std::set<std::string> configurations;
  std::map<std::string, std::size_t> scenes;  // scene -> its stale rows
  const std::size_t fingerprint = table.column("fingerprint");
  const auto stale = [&](const std::vector<std::string>& row) {
    const auto it = expected.find(job::run_key(table, row));
    return it != expected.end() && row[fingerprint] != it->second;
  };
  for (const auto& row : table.rows) {
    if (!stale(row)) continue;
    ++scenes[row[table.column("scene")]];
    configurations.insert(row[table.column("configuration")]);
  }
  if (scenes.empty()) return;
  const std::string path = job::parameters_path(out);
  std::string keys;
  if (const auto before = job::read_parameters(path)) {
    keys = job::describe_differences(job::row_parameters_of(*before), job::row_parameters_of(now));
    // The configurations' viewpoints are in the fingerprint too.
    for (const auto& name : configurations) {
      const Json::Value was = job::configuration_of(*before, name),
                        is = job::configuration_of(now, name);
      if (!job::differing_keys(was, is).empty() || was.isNull() != is.isNull())
        keys += std::string(keys.empty() ? "" : ", ") + "configuration '" + name + "'";
    }
    if (keys.empty()) {
      // All else is as it was: the scenes' own settings changed, and only
      // their rows are made again.
      for (const auto& [scene, rows] : scenes) {
        const std::string changes = job::describe_differences(
            job::scene_overrides_of(*before, scene), job::scene_overrides_of(now, scene));
        warnings.push_back(scene + ": its own settings changed (" +
                           (changes.empty() ? "in a way " + path + " does not record" : changes) +
                           "), so its " + std::to_string(rows) +
                           " rows in study.csv are made again");
      }
      table.rows.erase(std::remove_if(table.rows.begin(), table.rows.end(), stale),
                       table.rows.end());
      return;
    }
  } else {
    keys = "unknown (" + path + " is missing)";
  }
  std::size_t rows = 0;
  for (const auto& entry : scenes) rows += entry.second;
  throw UsageError(out + "/study.csv has " + std::to_string(rows) +
                   " rows made with other parameters; keys that differ: " + keys +
                   ". Resume with the same parameters, give another --out, or start again "
                   "with --fresh (which drops the rows in study.csv)");
}

// The shards' study.parameters.json (beside each CSV), which must agree.
Json::Value merged_parameters(const std::vector<std::string>& inputs,
                              std::vector<std::string>& warnings) {
  std::optional<Json::Value> first;
  std::string first_path;
  for (const auto& input : inputs) {
    const std::string path = job::parameters_path(fs::path(input).parent_path().string());
    const auto parameters = job::read_parameters(path);
    if (!parameters) {
      warnings.push_back(input + ": no " + path +
                         " beside it, so its parameters are not checked against the others'");
      continue;
    }
    if (!first) {
      first = parameters;
      first_path = path;
    } else {
      // Where the scenes and files are may differ from machine to machine.
      Json::Value a = job::row_parameters_of(*first), b = job::row_parameters_of(*parameters);
      a["configurations"] = (*first)["configurations"];
      b["configurations"] = (*parameters)["configurations"];
      a["scene_overrides"] = first->get("scene_overrides", Json::Value(Json::objectValue));
      b["scene_overrides"] = parameters->get("scene_overrides", Json::Value(Json::objectValue));
      if (!job::differing_keys(a, b).empty()) {
        throw UsageError("study merge: " + path + " and " + first_path + " differ: " +
                         job::describe_differences(a, b) + "; only shards of one study merge");
      }
    }
  }
  return first.value_or(Json::Value(Json::objectValue));
}

// The request to copy for each scene (scene_request): all but its scene list.
StudyRequest without_scenes(const StudyRequest& request) {
  StudyRequest shared = request;
  shared.scenes.clear();
  return shared;
}

// The openings of each scene that has its own (polygon_path), read before
// the first run, so that a bad file stops the study before it starts.
std::map<std::size_t, std::vector<PlanarPolygon>> scene_openings(const StudyRequest& request) {
  std::map<std::size_t, std::vector<PlanarPolygon>> openings;
  for (std::size_t s = 0; s < request.scenes.size(); ++s) {
    const Json::Value& overrides = request.scenes[s].overrides;
    if (overrides.isMember("polygon_path"))
      openings[s] = read_openings(overrides["polygon_path"].asString());
  }
  return openings;
}

void finish(StudyReport& report, const std::string& out, job::Clock::time_point start) {
  report.runs_failed = 0;
  for (const auto& row : report.table.rows) {
    if (job::failed_row(report.table, row)) ++report.runs_failed;
  }
  report.total_seconds = job::seconds_since(start);
  job::write_study_summary(report, out);
}

}  // namespace

CloudOcclusionRequest default_study_tracing() {
  CloudOcclusionRequest tracing;
  tracing.exterior = true;
  return tracing;
}

RegionGrowingOptions default_study_estimation() {
  RegionGrowingOptions options;
  options.max_cluster_size = std::numeric_limits<std::uint32_t>::max();
  return options;
}

StudyShard parse_shard(const std::string& text) {
  const std::size_t slash = text.find('/');
  const auto whole = [](const std::string& part) -> std::optional<std::size_t> {
    if (part.empty() || part.size() > 9 || part.find_first_not_of("0123456789") != part.npos) {
      return std::nullopt;
    }
    return static_cast<std::size_t>(std::stoul(part));
  };
  StudyShard shard;
  const auto index = whole(text.substr(0, slash));
  const auto count = slash == text.npos ? std::nullopt : whole(text.substr(slash + 1));
  if (!index || !count || *count == 0 || *index >= *count) {
    throw KeyError("shard", "must be i/n with 0 <= i < n (e.g. 3/10), got '" + text + "'");
  }
  shard.index = *index;
  shard.count = *count;
  return shard;
}

void validate(const StudyRequest& request) {
  if (request.scenes.empty()) {
    throw UsageError("no scenes given (--scene PATH or occlusion.study.scenes)");
  }
  if (request.configurations.empty()) {
    throw UsageError(
        "no viewpoint configurations given (--pattern N or occlusion.study.configurations)");
  }
  std::set<std::string> names, stems;
  for (const auto& configuration : request.configurations) {
    if (configuration.name.empty()) throw UsageError("a configuration has an empty name");
    if (!names.insert(configuration.name).second) {
      throw UsageError("two configurations are called '" + configuration.name + "'");
    }
    try {
      configuration.choice.validate();
    } catch (const UsageError& e) {
      throw UsageError("configuration '" + configuration.name + "': " + e.what());
    }
  }
  for (const auto& scene : job::scene_names(request.scenes)) {
    for (const auto& configuration : request.configurations) {
      if (!stems.insert(job::run_file_stem(scene, configuration.name)).second) {
        throw UsageError("configuration '" + configuration.name + "' of scene " + scene +
                         " would share its files in runs/ with another run: rename one");
      }
    }
  }
  if (request.out.empty()) throw KeyError("out", "is needed: the folder of the study's files");
  // Before the scenes' overrides are set: it checks them as their keys.
  check_keys(study_keys(), request);
  // The tracing and scan checks name the scene: the study-wide values with
  // any scene, then each scene's own.
  const auto check_scene = [](const StudyRequest& scene) {
    CloudOcclusionRequest tracing = scene.tracing;
    tracing.path = scene.scenes.front().path;
    validate(tracing);
    validate(job::study_scan_request(scene, tracing.path));
  };
  const StudyRequest shared = without_scenes(request);
  check_scene(scene_request(shared, request.scenes.front().path));
  for (const auto& scene : request.scenes) {
    if (scene.overrides.empty()) continue;
    try {
      check_scene(scene_request(shared, scene));
    } catch (const UsageError& e) {
      throw UsageError("scene " + scene.path + ": " + e.what() + " (its own setting)");
    }
  }
  if (request.occlusion_num_vp > 0) {
    ViewpointChoice::from_grid(request.occlusion_num_vp).validate();
  }
  job::validate_estimation(request.estimation);
  job::validate_segmenter(request);
  parse_shard(request.shard);
  // A sensor's scan needs every scene's mesh: a missing one stops the study
  // before its first run, not at that scene's.
  for (const auto& scene : request.scenes) job::check_scene_mesh(request, scene.path);
}

StudyReport run_study(const StudyRequest& request, const Progress& progress) {
  validate(request);
  const auto start = job::Clock::now();
  const StudyShard shard = parse_shard(request.shard);
  job::StudyContext context{
      request,
      resolve_mapping(request.class_mapping, request.mapping_path, request.ignored_classes),
      read_openings(request.tracing.polygon_path), (fs::path(request.out) / "runs").string(),
      job::row_parameters(request)};
  ensure_directory(context.runs_dir);
  const std::string csv_path = (fs::path(request.out) / "study.csv").string();
  StudyReport report;
  report.request = request;
  report.parameters = job::study_parameters(request);
  const std::vector<std::string> columns = job::study_columns(context.mapping);
  report.table = request.fresh ? CsvTable{columns, {}} : job::read_study_table(csv_path, columns);

  const std::vector<std::string> names = job::scene_names(request.scenes);
  const std::size_t configurations = request.configurations.size();
  const StudyRequest shared = without_scenes(request);
  // A scene's rows depend on its overrides: its own row parameters.
  std::vector<Json::Value> scene_parameters;
  for (const auto& scene : request.scenes) {
    scene_parameters.push_back(scene.overrides.empty()
                                   ? context.row_parameters
                                   : job::row_parameters(scene_request(shared, scene)));
  }
  const auto openings = scene_openings(request);
  std::map<std::string, std::string> fingerprints;  // run key -> the fingerprint it must have
  for (std::size_t s = 0; s < names.size(); ++s) {
    for (const auto& configuration : request.configurations) {
      fingerprints[names[s] + '\n' + configuration.name] =
          job::row_fingerprint(scene_parameters[s], configuration);
    }
  }
  const std::size_t rows_before = report.table.rows.size();
  check_fingerprints(report.table, fingerprints, report.parameters, request.out, report.warnings);
  // Failed rows are made again, unless asked to keep them.
  if (!request.skip_failed) {
    auto& rows = report.table.rows;
    rows.erase(std::remove_if(rows.begin(), rows.end(),
                              [&](const auto& row) {
                                return job::failed_row(report.table, row) &&
                                       fingerprints.count(job::run_key(report.table, row)) > 0;
                              }),
               rows.end());
  }
  std::set<std::string> done;
  for (const auto& row : report.table.rows) done.insert(job::run_key(report.table, row));
  // Before the first run, so that an interrupted study has it too.
  job::write_parameters(job::parameters_path(request.out), report.parameters);
  if (request.fresh || report.table.rows.size() < rows_before) write_csv(csv_path, report.table);

  // The runs to make now, in run order: (scene, configuration).
  report.runs_total = names.size() * configurations;
  std::vector<std::pair<std::size_t, std::size_t>> todo;
  for (std::size_t k = shard.index; k < report.runs_total; k += shard.count) {
    ++report.runs_in_shard;
    const std::size_t s = k / configurations, c = k % configurations;
    if (done.count(names[s] + '\n' + request.configurations[c].name) > 0) {
      ++report.runs_skipped;
    } else {
      todo.emplace_back(s, c);
    }
  }
  const auto runs_start = job::Clock::now();
  std::optional<job::LoadedCloud> scene;  // the scene of the previous run, loaded once
  // Its request (its overrides set) and what its runs share.
  std::optional<StudyRequest> scene_study;
  std::optional<job::StudyContext> scene_context;
  std::size_t loaded = names.size();
  for (std::size_t i = 0; i < todo.size(); ++i) {
    const auto [s, c] = todo[i];
    const NamedViewpointChoice& configuration = request.configurations[c];
    const double elapsed = job::seconds_since(runs_start);
    const Progress run_steps =
        run_progress(progress, names[s] + " " + configuration.name, i + 1, todo.size(), elapsed);
    if (loaded != s) {
      scene.reset();
      scene_context.reset();
      scene_study.emplace(scene_request(shared, request.scenes[s]));
      const auto own_openings = openings.find(s);
      scene_context.emplace(job::StudyContext{
          *scene_study, context.mapping,
          own_openings == openings.end() ? context.openings : own_openings->second,
          context.runs_dir, scene_parameters[s], context.worker});
      run_steps("loading the scene", 0.0);
      scene = job::load_cloud(request.scenes[s].path, request.tracing.skip_bad_lines, std::nullopt,
                              request.max_memory_mb);
      job::name_classes(scene->cloud, request.scenes[s].path, request.tracing.class_names_path);
      loaded = s;
      const StationFilterReport filtered = apply_station_filter(
          scene->cloud, station_filter(request.tracing), request.scenes[s].path);
      const std::size_t dropped = filtered.other_scans + filtered.too_near + filtered.too_far;
      if (dropped > 0) {
        report.warnings.push_back(
            request.scenes[s].path + ": scans, min_range and max_range dropped " +
            std::to_string(dropped) + " points (" + std::to_string(filtered.other_scans) +
            " of other scans, " + std::to_string(filtered.too_near) + " too near, " +
            std::to_string(filtered.too_far) + " too far)");
      }
      job::check_ground_truth(request.scenes[s].path, scene->cloud, context.mapping);
      if (scene->dropped_nan + scene->skipped_lines > 0) {
        report.warnings.push_back(request.scenes[s].path + ": reading dropped " +
                                  std::to_string(scene->dropped_nan + scene->skipped_lines) +
                                  " points (NaN or bad lines)");
      }
    }
    const job::StudyRunInput run{s * configurations + c, names[s], request.scenes[s].path,
                                 &scene->cloud, &configuration};
    const job::StudyRow row = job::run_study_once(*scene_context, run, run_steps, report.warnings);
    report.table.rows.push_back(job::study_cells(row, context.mapping));
    job::sort_by_run(report.table);
    // Whole rows only: the file is replaced, never appended to, so an
    // interruption (Ctrl-C, a scheduler's SIGTERM) leaves every finished row.
    write_csv(csv_path, report.table);
    ++report.runs_computed;
  }
  progress("summary", 1.0);
  finish(report, request.out, start);
  return report;
}

StudyReport run_study_merge(const std::vector<std::string>& inputs, const std::string& out,
                            const std::vector<std::string>& compare_with) {
  if (out.empty()) throw UsageError("study merge needs an output folder");
  const auto start = job::Clock::now();
  StudyReport report;
  report.job = "study_merge";
  report.request.out = out;
  report.request.compare_with = compare_with;
  report.inputs = inputs;
  std::vector<CsvTable> tables;
  for (const auto& input : inputs) tables.push_back(read_csv(input));
  report.table = job::merge_study_tables(tables, inputs, report.warnings);
  report.parameters = merged_parameters(inputs, report.warnings);
  ensure_directory(out);
  write_csv((fs::path(out) / "study.csv").string(), report.table);
  finish(report, out, start);
  return report;
}

namespace {

Json::Value estimate_json(const ClusteredEstimate& e) {
  Json::Value value(Json::objectValue);
  value["value"] = to_json(e.value);
  value["interval95"] = Json::Value();
  if (e.interval95) {
    value["interval95"].append(e.interval95->lo);
    value["interval95"].append(e.interval95->hi);
  }
  value["p_value"] = to_json(e.p_value);
  value["undefined_resamples"] = Json::UInt64(e.undefined_resamples);
  return value;
}

}  // namespace

Json::Value to_json(const StudyReport& report) {
  const StudyRequest& q = report.request;
  const CsvTable& table = report.table;
  Json::Value json(Json::objectValue);
  json["job"] = report.job;
  Json::Value correlations(Json::arrayValue);
  for (const auto& m : report.correlations) {
    Json::Value entry(Json::objectValue);
    entry["measure"] = m.measure;
    entry["against"] = "miou";
    entry["n"] = Json::UInt64(m.correlation.n);
    entry["pearson"] = to_json(m.correlation.pearson);
    entry["spearman"] = to_json(m.correlation.spearman);
    const auto& fit = m.correlation.fit;
    entry["slope"] = to_json(fit ? std::optional<double>(fit->slope) : std::nullopt);
    entry["intercept"] = to_json(fit ? std::optional<double>(fit->intercept) : std::nullopt);
    const ClusteredAssociation& a = m.association;
    entry["scenes"] = Json::UInt64(a.scenes);
    entry["inference"]["pearson"] = estimate_json(a.pearson);
    entry["inference"]["spearman"] = estimate_json(a.spearman);
    entry["inference"]["within_scene_slope"] = estimate_json(a.within_scene_slope);
    entry["inference"]["resamples"] = Json::UInt64(a.options.resamples);
    entry["inference"]["permutations"] = Json::UInt64(a.options.permutations);
    entry["inference"]["seed"] = Json::UInt64(a.options.seed);
    correlations.append(entry);
  }
  json["correlations"] = correlations;
  Json::Value comparisons(Json::arrayValue);
  for (const auto& c : report.comparisons) {
    Json::Value entry(Json::objectValue);
    entry["study"] = c.study;
    entry["measure"] = c.measure;
    entry["against"] = "miou";
    entry["runs"] = Json::UInt64(c.slopes.runs);
    entry["scenes"] = Json::UInt64(c.slopes.scenes);
    entry["slope_there"] = estimate_json(c.slopes.first);
    entry["slope_here"] = estimate_json(c.slopes.second);
    entry["difference"] = estimate_json(c.slopes.difference);
    entry["resamples"] = Json::UInt64(c.slopes.options.resamples);
    entry["seed"] = Json::UInt64(c.slopes.options.seed);
    comparisons.append(entry);
  }
  json["comparisons"] = comparisons;
  json["runs_total"] = Json::UInt64(report.runs_total);
  json["runs_in_shard"] = Json::UInt64(report.runs_in_shard);
  json["runs_skipped"] = Json::UInt64(report.runs_skipped);
  json["runs_computed"] = Json::UInt64(report.runs_computed);
  json["runs_failed"] = Json::UInt64(report.runs_failed);

  Json::Value rows(Json::arrayValue);
  for (const auto& row : table.rows) {
    Json::Value entry(Json::objectValue);
    for (std::size_t c = 0; c < table.columns.size(); ++c) {
      const auto value = job::cell_number(row[c]);
      const bool text = !value && !row[c].empty();
      entry[table.columns[c]] = text ? Json::Value(row[c]) : to_json(value);
    }
    rows.append(entry);
  }
  json["rows"] = rows;

  Json::Value parameters = report.parameters;
  if (report.job == "study") {
    // The fingerprinted parameters, then every declared key they leave out.
    const Json::Value declared = parameters_json(study_keys(), q);
    for (const auto& name : declared.getMemberNames()) {
      if (!parameters.isMember(name)) parameters[name] = declared[name];
    }
    parameters["segmenter"] = job::segmenter_name(q.segmenter);
  } else {
    parameters["inputs"] = to_json(report.inputs);
  }
  json["parameters"] = parameters;
  Json::Value timings(Json::objectValue);
  timings["total_seconds"] = report.total_seconds;
  json["timings"] = timings;
  job::add_outputs_and_warnings(report, json);
  return json;
}

}  // namespace occlusion
