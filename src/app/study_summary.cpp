// What the study's rows say together: correlations, the plot, the report.

#include <algorithm>
#include <filesystem>
#include <map>
#include <ostream>
#include <sstream>

#include "job_support.hpp"
#include "occlusion/analysis/baseline_segmenter.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/io/atomic_file.hpp"
#include "occlusion/io/svg_plot.hpp"
#include "report_format.hpp"
#include "study_support.hpp"

namespace occlusion::job {

namespace {

// Fixed, so that a study's intervals and p-values are the same on every run
// and every machine.
const InferenceOptions kInference{2000, 2000, 1};

struct Measure {
  const char* column;
  const char* label;
};

// The occlusion measures, each correlated with mIoU.
const Measure kMeasures[] = {
    {"occlusion_level", "occlusion level (-poc)"},
    {"exterior_occlusion_level", "exterior occlusion level (-poc, walls, floor, ceiling)"},
    {"visible_fraction", "visible fraction (-fscan)"},
};

// Per row: whether an earlier row of the same scene placed the same set of
// viewpoints (pattern_1 and a one-point grid both stand at the centre). Such
// a run measures nothing new, and counting it twice would shrink the
// intervals: it stays in the table and leaves the statistics, with a warning.
std::vector<bool> repeated_runs(const CsvTable& table, std::vector<std::string>* warnings) {
  const std::size_t scene = table.column("scene"), configuration = table.column("configuration");
  const std::size_t positions = table.column("viewpoint_positions");
  std::map<std::string, std::string> first;  // scene + viewpoint set -> configuration
  std::vector<bool> repeated(table.rows.size(), false);
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const auto& row = table.rows[r];
    if (failed_row(table, row)) continue;
    std::vector<std::string> points;
    std::istringstream text(row[positions]);
    for (std::string point; std::getline(text, point, ';');) points.push_back(point);
    std::sort(points.begin(), points.end());
    std::string key = row[scene] + '\n';
    for (const auto& point : points) key += point + ';';
    const auto [it, added] = first.emplace(key, row[configuration]);
    if (added) continue;
    repeated[r] = true;
    if (warnings != nullptr) {
      warnings->push_back(row[scene] + ": configuration '" + row[configuration] +
                          "' places the same viewpoints as '" + it->second +
                          "'; the correlations count that measurement once");
    }
  }
  return repeated;
}

// The pairs (measure, mIoU) of the rows that have both and are not a
// repeated run, and (when asked) each pair's scene as a number.
void pairs(const CsvTable& table, const std::string& column, std::vector<double>& x,
           std::vector<double>& y, std::vector<std::size_t>* scenes = nullptr) {
  const std::size_t c = table.column(column), miou = table.column("miou");
  const std::size_t scene = table.column("scene");
  const std::vector<bool> repeated = repeated_runs(table, nullptr);
  std::map<std::string, std::size_t> scene_numbers;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const auto& row = table.rows[r];
    const auto a = cell_number(row[c]), b = cell_number(row[miou]);
    if (a && b && !repeated[r]) {
      x.push_back(*a);
      y.push_back(*b);
      if (scenes != nullptr) {
        scenes->push_back(scene_numbers.emplace(row[scene], scene_numbers.size()).first->second);
      }
    }
  }
}

// Each run key's (measure, mIoU), for the rows pairs() takes.
std::map<std::string, std::pair<double, double>> measured_runs(const CsvTable& table,
                                                               const std::string& column) {
  const std::size_t c = table.column(column), miou = table.column("miou");
  const std::vector<bool> repeated = repeated_runs(table, nullptr);
  std::map<std::string, std::pair<double, double>> runs;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const auto& row = table.rows[r];
    const auto a = cell_number(row[c]), b = cell_number(row[miou]);
    if (a && b && !repeated[r]) runs[run_key(table, row)] = {*a, *b};
  }
  return runs;
}

// This study's rows against another study's (its folder's study.csv), one
// comparison per measure: the runs both have, in this table's order, scenes
// numbered as pairs() numbers them.
std::vector<StudyComparison> compare_with_study(const CsvTable& here, const std::string& folder,
                                                std::vector<std::string>& warnings) {
  const std::string csv = (std::filesystem::path(folder) / "study.csv").string();
  if (!std::filesystem::is_regular_file(csv)) {
    throw KeyError("compare_with", folder + " has no study.csv (a study's out folder)");
  }
  const CsvTable there = read_study_table(csv, here.columns);
  std::vector<StudyComparison> comparisons;
  for (const auto& measure : kMeasures) {
    const auto theirs = measured_runs(there, measure.column);
    const auto ours = measured_runs(here, measure.column);
    std::vector<double> x_there, y_there, x_here, y_here;
    std::vector<std::size_t> scenes;
    std::map<std::string, std::size_t> scene_numbers;
    for (const auto& row : here.rows) {
      const std::string key = run_key(here, row);
      const auto mine = ours.find(key), other = theirs.find(key);
      if (mine == ours.end() || other == theirs.end()) continue;
      x_there.push_back(other->second.first);
      y_there.push_back(other->second.second);
      x_here.push_back(mine->second.first);
      y_here.push_back(mine->second.second);
      const std::string& scene = row[here.column("scene")];
      scenes.push_back(scene_numbers.emplace(scene, scene_numbers.size()).first->second);
    }
    if (x_here.empty() && std::string(measure.column) == "exterior_occlusion_level") continue;
    const std::size_t unpaired = ours.size() - x_here.size();
    if (unpaired > 0) {
      warnings.push_back(std::to_string(unpaired) + " runs with " + measure.column +
                         " have no counterpart in " + csv + ": the comparison leaves them out");
    }
    comparisons.push_back({folder, measure.column,
                           paired_slopes(x_there, y_there, x_here, y_here, scenes, kInference)});
  }
  return comparisons;
}

std::string fixed(const std::optional<double>& value) {
  return format_number("%.4f", value, "–");
}
std::string fixed(const std::string& cell) {
  return fixed(cell_number(cell));
}

std::vector<std::string> segmenters(const CsvTable& table) {
  std::vector<std::string> names;
  for (const auto& row : table.rows) {
    const std::string& name = row[table.column("segmenter")];
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
  return names;
}

bool constant(const std::vector<double>& values) {
  return std::all_of(values.begin(), values.end(), [&](double v) { return v == values.front(); });
}

std::string joined(const Json::Value& list) {
  std::string text;
  for (const auto& item : list) text += (text.empty() ? "" : ", ") + item.asString();
  return text;
}

// A panel's title: the measure as this study took it (the parameters say
// from where, and which classes block the exterior rays).
std::string panel_title(const Measure& measure, const Json::Value& parameters) {
  const std::string column = measure.column;
  if (column == "visible_fraction" || !parameters.isMember("occlusion_num_vp"))
    return measure.label;
  const unsigned grid = parameters["occlusion_num_vp"].asUInt();
  const std::string from = grid == 0 ? "from each configuration's viewpoints"
                                     : "from " + std::to_string(grid) + " grid viewpoints";
  if (column == "exterior_occlusion_level") {
    return "exterior occlusion level (-poc " + from +
           "; blocking: " + joined(parameters["exterior_classes"]) + ")";
  }
  return "occlusion level (-poc " + from + ")";
}

// Whether a scene of the study sets `key` for itself.
bool some_scene_sets(const Json::Value& parameters, const char* key) {
  const Json::Value& overrides = parameters["scene_overrides"];
  if (!overrides.isObject()) return false;
  for (const auto& scene : overrides) {
    if (scene.isMember(key)) return true;
  }
  return false;
}

// The plot's title: what was measured, with which settings.
std::string plot_title(const StudyReport& report) {
  const Json::Value& p = report.parameters;
  std::string title = "mIoU against occlusion, one point per run (" +
                      std::to_string(report.table.rows.size() - report.runs_failed) + " runs";
  if (p.isMember("point_radius")) {
    title += "; " + p["segmenter"].asString() + ", mIoU over " + p["mean_over"].asString() +
             " classes, point radius " +
             (p["point_radius"].isNumeric() ? format_number("%g", p["point_radius"].asDouble())
                                            : p["point_radius"].asString()) +
             (some_scene_sets(p, "point_radius") ? " (some scenes their own)" : "") + ", " +
             std::to_string(p["num_rays_per_vp"].asUInt64()) + " rays per viewpoint";
  }
  return title + ")";
}

// "-0.123 [-0.2, -0.05]", the interval left out where there is none.
std::string with_interval(const ClusteredEstimate& e, const char* pattern) {
  if (!e.value) return "–";
  std::string text = format_number(pattern, *e.value);
  if (e.interval95) {
    text += " [" + format_number(pattern, e.interval95->lo) + ", " +
            format_number(pattern, e.interval95->hi) + "]";
  }
  return text;
}

std::string plot(const StudyReport& report) {
  std::vector<ScatterPanel> panels;
  for (const auto& measure : kMeasures) {
    ScatterPanel panel;
    panel.title = panel_title(measure, report.parameters);
    panel.x_label = measure.column;
    panel.y_label = "mIoU";
    pairs(report.table, measure.column, panel.x, panel.y, &panel.group);
    // mIoU's whole range, so that a small spread looks small (a merged CSV
    // edited by hand may hold other values: then the axis fits them).
    if (std::all_of(panel.y.begin(), panel.y.end(),
                    [](double v) { return v >= 0.0 && v <= 1.0; })) {
      panel.y_range = std::make_pair(0.0, 1.0);
    }
    for (const auto& c : report.correlations) {
      if (c.measure != measure.column) continue;
      if (c.correlation.fit) {
        panel.line = PlotLine{c.correlation.fit->slope, c.correlation.fit->intercept};
      }
      const ClusteredAssociation& a = c.association;
      const auto p_text = [](const ClusteredEstimate& e) {
        return e.p_value ? ", p = " + format_number("%.3g", *e.p_value) : std::string();
      };
      panel.notes = {"Pearson r = " + with_interval(a.pearson, "%.2f") + p_text(a.pearson),
                     "within-scene slope = " + with_interval(a.within_scene_slope, "%.3g") +
                         p_text(a.within_scene_slope),
                     std::to_string(a.runs) + " runs in " + std::to_string(a.scenes) +
                         (a.scenes == 1 ? " scene" : " scenes") + "; colour: scene"};
    }
    // A measure the study did not take (exterior off) has no panel, unless
    // the table is empty and the plot would otherwise have none.
    if (!panel.x.empty() || (panels.empty() && report.table.rows.empty())) {
      panels.push_back(panel);
    }
  }
  return scatter_plot_svg(panels, plot_title(report));
}

// The study's answer in one sentence, with its uncertainty: the within-scene
// slope of mIoU on the occlusion level (-poc), or the first measure taken.
std::string answer(const StudyReport& report) {
  const MeasureCorrelation* m = nullptr;
  for (const auto& c : report.correlations) {
    if (m == nullptr || c.measure == "occlusion_level") m = &c;
  }
  if (m == nullptr || m->correlation.n == 0) {
    return "**Answer:** none yet: no run has both an occlusion measure and an mIoU.";
  }
  const ClusteredAssociation& a = m->association;
  const ClusteredEstimate& slope = a.within_scene_slope;
  const std::string counts = std::to_string(a.runs) + " runs in " + std::to_string(a.scenes) +
                             (a.scenes == 1 ? " scene" : " scenes");
  const std::string p =
      slope.p_value ? "within-scene permutation p = " + format_number("%.3g", *slope.p_value) + "; "
                    : "";
  if (!slope.value) {
    // Undefined because mIoU never changes, or because the measure changes in no scene.
    std::vector<double> x, miou;
    pairs(report.table, m->measure, x, miou);
    if (miou.size() >= 2 && constant(miou)) {
      return "**Answer:** this study cannot say: mIoU is the same (" +
             format_number("%.4g", miou.front()) +
             ") in every run, so there is nothing to relate to " + m->measure + " (" + counts +
             ").";
    }
    return "**Answer:** this study cannot say: no scene was scanned from configurations whose " +
           m->measure + " differs, so there is no within-scene effect to estimate (" + counts +
           ").";
  }
  const std::string change = "within a scene, mIoU changes by " +
                             format_number("%.3g", *slope.value) + " per unit of " + m->measure;
  if (!slope.interval95) {
    return "**Answer (descriptive only):** " + change + " (" + p + counts + "), but " +
           std::to_string(a.scenes) + (a.scenes == 1 ? " scene is" : " scenes are") +
           " too few for an interval (at least " + std::to_string(kMinScenesForInterval) +
           "): this describes these scenes and answers nothing beyond them.";
  }
  const Interval& i = *slope.interval95;
  const std::string interval = "95 % interval " + format_number("%.3g", i.lo) + " to " +
                               format_number("%.3g", i.hi) + ", scene-clustered bootstrap; ";
  if (i.lo > 0.0 || i.hi < 0.0) {
    const bool hurts = i.hi < 0.0;
    return std::string("**Answer:** more ") +
           (m->measure == "visible_fraction" ? "visibility" : "occlusion") + ", " +
           (hurts ? "lower" : "higher") + " mIoU: " + change + " (" + interval + p + counts + ").";
  }
  return "**Answer:** no effect of " + m->measure + " on mIoU can be told from noise: " + change +
         " (" + interval + "it includes 0; " + p + counts + ").";
}

void write_markdown(std::ostream& out, const StudyReport& report, const std::string& svg_name) {
  const CsvTable& table = report.table;
  out << "# Occlusion study\n\n" << answer(report) << "\n\n";
  for (const auto& name : segmenters(table)) {
    out << "Segmenter: **" << markdown_cell(name) << "**";
    if (name == kBaselineSegmenterName) {
      out << " — a geometric baseline, not a network: floor, ceiling and walls from the "
             "region-growing planes, everything else clutter (docs/study.md)";
    }
    out << ".\n\n";
  }
  out << table.rows.size() << " runs";
  if (report.job == "study") {
    out << " (" << report.runs_failed << " failed; " << report.runs_computed << " computed now, "
        << report.runs_skipped << " already in study.csv; shard " << report.request.shard << " of "
        << report.runs_total << " runs in all)";
  } else {
    out << " (" << report.runs_failed << " failed), merged from " << report.inputs.size()
        << " CSV files";
  }
  out << ".";
  if (report.parameters.isMember("mean_over")) {
    out << " mIoU averages over the `" << report.parameters["mean_over"].asString()
        << "` classes (mean_over, docs/metrics.md).";
  }
  const Json::Value& overrides = report.parameters["scene_overrides"];
  if (overrides.isObject() && !overrides.empty()) {
    out << "\n\nScenes with settings of their own (overriding the study's for that scene; "
           "docs/study.md):\n\n| scene | its own settings |\n|---|---|\n";
    for (const auto& scene : overrides.getMemberNames()) {
      std::string settings;
      for (const auto& key : overrides[scene].getMemberNames()) {
        const Json::Value& value = overrides[scene][key];
        settings +=
            (settings.empty() ? "" : ", ") + key + " " +
            (value.isString() ? value.asString() : format_number("%.10g", value.asDouble()));
      }
      out << "| " << markdown_cell(scene) << " | " << markdown_cell(settings) << " |\n";
    }
    out << "\nOther scenes use the study's settings.";
  }
  out << "\n\n## Correlation with mIoU\n\n"
      << "| measure | runs | scenes | Pearson r [95 %] | p | Spearman ρ [95 %] | p | "
         "within-scene slope [95 %] | p | fitted line |\n"
      << "|---|---:|---:|---|---:|---|---:|---|---:|---|\n";
  for (const auto& m : report.correlations) {
    const Correlation& c = m.correlation;
    const ClusteredAssociation& a = m.association;
    const std::string line = c.fit ? "mIoU = " + format_number("%.4g", c.fit->slope) + " × x + " +
                                         format_number("%.4g", c.fit->intercept)
                                   : "–";
    out << "| " << m.measure << " | " << c.n << " | " << a.scenes << " | "
        << with_interval(a.pearson, "%.3f") << " | "
        << format_number("%.3g", a.pearson.p_value, "–") << " | "
        << with_interval(a.spearman, "%.3f") << " | "
        << format_number("%.3g", a.spearman.p_value, "–") << " | "
        << with_interval(a.within_scene_slope, "%.3g") << " | "
        << format_number("%.3g", a.within_scene_slope.p_value, "–") << " | " << line << " |\n";
  }
  if (!report.comparisons.empty()) {
    out << "\n## Against other studies of the same runs\n\n"
        << "| measure | other study | paired runs | scenes | slope there [95 %] | slope here "
           "[95 %] | here − there [95 %] |\n|---|---|---:|---:|---|---|---|\n";
    for (const auto& c : report.comparisons) {
      out << "| " << c.measure << " | " << markdown_cell(c.study) << " | " << c.slopes.runs << " | "
          << c.slopes.scenes << " | " << with_interval(c.slopes.first, "%.3g") << " | "
          << with_interval(c.slopes.second, "%.3g") << " | "
          << with_interval(c.slopes.difference, "%.3g") << " |\n";
    }
    out << "\nRuns are paired by scene and configuration; each bootstrap draw takes the same "
           "scenes for both studies, so the difference's interval keeps the pairing.\n";
  }
  out << "\nA correlation needs at least 3 runs and a measure that varies; – marks one that is "
         "undefined. Intervals: 95 % percentile intervals of a bootstrap that draws whole scenes ("
      << kInference.resamples << " draws, seed " << kInference.seed << "), given from "
      << kMinScenesForInterval << " scenes on. p: two-sided, from " << kInference.permutations
      << " shuffles of the measure within each scene. The within-scene slope is the change in "
         "mIoU per unit of the measure among runs of the same scene (docs/study.md).\n\n"
      << "![mIoU against occlusion](" << svg_name << ")\n\n## Runs\n\n"
      << "| scene | configuration | status | viewpoints | visible fraction | occlusion level | "
         "exterior occlusion level | mIoU | overall accuracy |\n"
      << "|---|---|---|---:|---:|---:|---:|---:|---:|\n";
  const auto cell = [&](const std::vector<std::string>& row, const char* column) {
    return row[table.column(column)];
  };
  for (const auto& row : table.rows) {
    out << "| " << markdown_cell(cell(row, "scene")) << " | "
        << markdown_cell(cell(row, "configuration")) << " | " << cell(row, "status") << " | "
        << cell(row, "viewpoints") << " | " << fixed(cell(row, "visible_fraction")) << " | "
        << fixed(cell(row, "occlusion_level")) << " | "
        << fixed(cell(row, "exterior_occlusion_level")) << " | " << fixed(cell(row, "miou"))
        << " | " << fixed(cell(row, "overall_accuracy")) << " |\n";
  }
  if (report.runs_failed > 0) {
    out << "\n## Failed runs\n\nThey have no mIoU and stay out of the correlations; a resume "
           "makes them again.\n\n| scene | configuration | why |\n|---|---|---|\n";
    for (const auto& row : table.rows) {
      if (!failed_row(table, row)) continue;
      out << "| " << markdown_cell(cell(row, "scene")) << " | "
          << markdown_cell(cell(row, "configuration")) << " | "
          << markdown_cell(cell(row, "failure")) << " |\n";
    }
  }
  std::vector<std::size_t> classes;
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    if (table.columns[c].rfind("iou_", 0) != 0) continue;
    const bool any = std::any_of(table.rows.begin(), table.rows.end(),
                                 [c](const auto& row) { return !row[c].empty(); });
    if (any) classes.push_back(c);
  }
  if (classes.empty()) return;
  out << "\n## IoU per class\n\n| scene | configuration |";
  for (const std::size_t c : classes)
    out << ' ' << markdown_cell(table.columns[c].substr(4)) << " |";
  out << "\n|---|---|";
  for (std::size_t k = 0; k < classes.size(); ++k) out << "---:|";
  out << '\n';
  for (const auto& row : table.rows) {
    out << "| " << markdown_cell(cell(row, "scene")) << " | "
        << markdown_cell(cell(row, "configuration")) << " |";
    for (const std::size_t c : classes) out << ' ' << fixed(row[c]) << " |";
    out << '\n';
  }
}

}  // namespace

void write_study_summary(StudyReport& report, const std::string& out) {
  report.correlations.clear();
  repeated_runs(report.table, &report.warnings);
  for (const auto& measure : kMeasures) {
    std::vector<double> x, y;
    std::vector<std::size_t> scenes;
    pairs(report.table, measure.column, x, y, &scenes);
    if (x.empty() && std::string(measure.column) == "exterior_occlusion_level") continue;
    Correlation correlation = correlate(x, y);
    ClusteredAssociation association = clustered_association(x, y, scenes, kInference);
    // Rounding can leave a constant's variance a hair above 0 and make a
    // number of it: a constant has no correlation.
    for (const auto* values : {&x, &y}) {
      if (values->size() < 2 || !constant(*values)) continue;
      correlation.pearson.reset();
      correlation.spearman.reset();
      correlation.fit.reset();
      for (auto* e :
           {&association.pearson, &association.spearman, &association.within_scene_slope}) {
        *e = ClusteredEstimate{};
      }
      report.warnings.push_back(std::string(values == &x ? measure.column : "miou") +
                                " is the same (" + format_number("%.10g", values->front()) +
                                ") in all " + std::to_string(values->size()) + " runs, so its " +
                                "correlation with " + (values == &x ? "miou" : measure.column) +
                                " is undefined");
    }
    report.correlations.push_back({measure.column, correlation, association});
  }
  report.comparisons.clear();
  for (const auto& folder : report.request.compare_with) {
    for (auto& comparison : compare_with_study(report.table, folder, report.warnings))
      report.comparisons.push_back(std::move(comparison));
  }
  ensure_directory(out);
  const auto path = [&](const char* name) { return (std::filesystem::path(out) / name).string(); };
  const std::string svg = plot(report);
  // study.csv is the resumable table, written row by row as runs finish; the
  // summary files appear together.
  OutputSet outputs;
  write_file_atomically(outputs.add(path("study.svg")),
                        [&](std::ostream& stream) { stream << svg; });
  write_file_atomically(outputs.add(path("study.md")),
                        [&](std::ostream& stream) { write_markdown(stream, report, "study.svg"); });
  report.outputs = {path("study.json"), path("study.csv"), path("study.svg"), path("study.md")};
  write_json_report(outputs.add(path("study.json")), to_json(report));
  outputs.commit();
}

}  // namespace occlusion::job
