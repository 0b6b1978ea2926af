#include "occlusion/app/study_job.hpp"

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
#include "region_growing_support.hpp"
#include "study_support.hpp"

namespace occlusion {

namespace {

namespace fs = std::filesystem;

// A scene's name in the CSV: its file or folder name; where two scenes share
// it (S3DIS has an office_1 in every Area), with its parent folder's.
std::vector<std::string> scene_names(const std::vector<std::string>& scenes) {
  const auto name = [](const std::string& scene, bool with_parent) {
    fs::path path(scene);
    if (path.filename().empty()) path = path.parent_path();
    const std::string stem = path.stem().string();
    return with_parent ? path.parent_path().filename().string() + "/" + stem : stem;
  };
  std::map<std::string, std::size_t> count;
  for (const auto& scene : scenes) ++count[name(scene, false)];
  std::vector<std::string> names;
  std::set<std::string> taken;
  for (const auto& scene : scenes) {
    names.push_back(name(scene, count[name(scene, false)] > 1));
    if (!taken.insert(names.back()).second) {
      throw UsageError("two scenes are both called '" + names.back() + "' (" + scene +
                       "); give each scene once, from folders with different names");
    }
  }
  return names;
}

// A run's steps as stages of the whole shard: "[2/6] office_1 pattern_4:
// scanning", with the fraction of the shard's runs done.
Progress run_progress(const Progress& outer, const std::string& prefix, std::size_t position,
                      std::size_t runs) {
  Progress inner;
  inner.cancel = outer.cancel;
  inner.report = [=](const std::string& stage, double fraction) {
    outer(prefix + stage,
          (static_cast<double>(position - 1) + fraction) / static_cast<double>(runs));
  };
  return inner;
}

void finish(StudyReport& report, const std::string& out, job::Clock::time_point start) {
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
  for (const auto& scene : scene_names(request.scenes)) {
    for (const auto& configuration : request.configurations) {
      if (!stems.insert(job::run_file_stem(scene, configuration.name)).second) {
        throw UsageError("configuration '" + configuration.name + "' of scene " + scene +
                         " would share its files in runs/ with another run: rename one");
      }
    }
  }
  if (request.out.empty()) throw KeyError("out", "is needed: the folder of the study's files");
  // The tracing and scan checks name the scene: any scene will do here.
  CloudOcclusionRequest tracing = request.tracing;
  tracing.path = request.scenes.front();
  validate(tracing);
  validate(job::study_scan_request(request, request.scenes.front()));
  if (request.occlusion_num_vp > 0) {
    ViewpointChoice::from_grid(request.occlusion_num_vp).validate();
  }
  check_keys(study_keys(), request);
  job::validate_estimation(request.estimation);
  job::validate_segmenter(request);
  parse_shard(request.shard);
}

StudyReport run_study(const StudyRequest& request, const Progress& progress) {
  validate(request);
  const auto start = job::Clock::now();
  const StudyShard shard = parse_shard(request.shard);
  job::StudyContext context{request, resolve_mapping(request.mapping_path, request.ignored_classes),
                            read_openings(request.tracing.polygon_path),
                            (fs::path(request.out) / "runs").string()};
  ensure_directory(context.runs_dir);
  const std::string csv_path = (fs::path(request.out) / "study.csv").string();
  StudyReport report;
  report.request = request;
  report.table = job::read_study_table(csv_path, job::study_columns(context.mapping));
  std::set<std::string> done;
  for (const auto& row : report.table.rows) done.insert(job::run_key(report.table, row));

  const std::vector<std::string> names = scene_names(request.scenes);
  const std::size_t configurations = request.configurations.size();
  report.runs_total = names.size() * configurations;
  for (std::size_t k = shard.index; k < report.runs_total; k += shard.count) ++report.runs_in_shard;
  std::size_t position = 0;  // among this shard's runs, for progress
  for (std::size_t s = 0; s < names.size(); ++s) {
    std::optional<job::LoadedCloud> scene;  // loaded once, for its first run to be made
    for (std::size_t c = 0; c < configurations; ++c) {
      const std::size_t k = s * configurations + c;
      if (k % shard.count != shard.index) continue;
      ++position;
      const NamedViewpointChoice& configuration = request.configurations[c];
      if (done.count(names[s] + '\n' + configuration.name) > 0) {
        ++report.runs_skipped;
        continue;
      }
      if (!scene) {
        progress("loading " + names[s],
                 static_cast<double>(position - 1) / static_cast<double>(report.runs_in_shard));
        scene = job::load_cloud(request.scenes[s], request.tracing.skip_bad_lines);
        job::check_ground_truth(request.scenes[s], scene->cloud, context.mapping);
        if (scene->dropped_nan + scene->skipped_lines > 0) {
          report.warnings.push_back(request.scenes[s] + ": reading dropped " +
                                    std::to_string(scene->dropped_nan + scene->skipped_lines) +
                                    " points (NaN or bad lines)");
        }
      }
      const job::StudyRunInput run{k, names[s], request.scenes[s], &scene->cloud, &configuration};
      const std::string prefix = "[" + std::to_string(position) + "/" +
                                 std::to_string(report.runs_in_shard) + "] " + names[s] + " " +
                                 configuration.name + ": ";
      const job::StudyRow row = job::run_study_once(
          context, run, run_progress(progress, prefix, position, report.runs_in_shard),
          report.warnings);
      report.table.rows.push_back(job::study_cells(row, context.mapping));
      job::sort_by_run(report.table);
      write_csv(csv_path, report.table);
      ++report.runs_computed;
    }
  }
  progress("summary", 1.0);
  finish(report, request.out, start);
  return report;
}

StudyReport run_study_merge(const std::vector<std::string>& inputs, const std::string& out) {
  if (out.empty()) throw UsageError("study merge needs an output folder");
  const auto start = job::Clock::now();
  StudyReport report;
  report.job = "study_merge";
  report.request.out = out;
  report.inputs = inputs;
  std::vector<CsvTable> tables;
  for (const auto& input : inputs) tables.push_back(read_csv(input));
  report.table = job::merge_study_tables(tables, inputs, report.warnings);
  ensure_directory(out);
  write_csv((fs::path(out) / "study.csv").string(), report.table);
  finish(report, out, start);
  return report;
}

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
    correlations.append(entry);
  }
  json["correlations"] = correlations;
  json["runs_total"] = Json::UInt64(report.runs_total);
  json["runs_in_shard"] = Json::UInt64(report.runs_in_shard);
  json["runs_skipped"] = Json::UInt64(report.runs_skipped);
  json["runs_computed"] = Json::UInt64(report.runs_computed);

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

  Json::Value parameters(Json::objectValue);
  if (report.job == "study") {
    parameters = parameters_json(study_keys(), q);
    parameters["segmenter"] = job::segmenter_name(q.segmenter);
  } else {
    parameters["inputs"] = to_json(report.inputs);
  }
  json["parameters"] = parameters;
  Json::Value timings(Json::objectValue);
  timings["total_seconds"] = report.total_seconds;
  json["timings"] = timings;
  json["outputs"] = to_json(report.outputs);
  json["warnings"] = to_json(report.warnings);
  return json;
}

}  // namespace occlusion
