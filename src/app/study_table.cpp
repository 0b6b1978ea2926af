// The study's CSV: one row per run, read back on restart and by `study merge`.

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>

#include "occlusion/app/errors.hpp"
#include "report_format.hpp"
#include "study_support.hpp"

namespace occlusion::job {

namespace {

const std::vector<std::string> kRunColumns = {"run",
                                              "scene",
                                              "configuration",
                                              "status",
                                              "viewpoints",
                                              "viewpoint_positions",
                                              "points",
                                              "scanned_points",
                                              "visible_fraction",
                                              "occlusion_level",
                                              "exterior_occlusion_level",
                                              "interior_exterior_ratio",
                                              "segmenter",
                                              "mean_over",
                                              "miou",
                                              "overall_accuracy",
                                              "mean_class_accuracy"};
// After the classes: why a run failed, and what it was made with.
const std::vector<std::string> kRecordColumns = {"failure", "fingerprint"};
const std::vector<std::string> kTimingColumns = {"scan_seconds", "occlusion_seconds",
                                                 "segmentation_seconds", "evaluation_seconds"};

// Ten digits: the figures read back (resume, merge) to what was written, so a
// summary is the same whichever way its rows came.
std::string number(double value) {
  return format_number("%.10g", value);
}
std::string number(const std::optional<double>& value) {
  return format_number("%.10g", value, "");
}

std::string positions(const std::vector<Eigen::Vector3d>& points) {
  std::string text;
  for (const auto& p : points) {
    text += (text.empty() ? "" : ";") + format_number("%.6g", p.x()) + " " +
            format_number("%.6g", p.y()) + " " + format_number("%.6g", p.z());
  }
  return text;
}

// The timings differ from one run of the same computation to the next.
bool same_figures(const CsvTable& table, const std::vector<std::string>& a,
                  const std::vector<std::string>& b) {
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    const std::string& name = table.columns[c];
    const bool timing = name.size() > 8 && name.compare(name.size() - 8, 8, "_seconds") == 0;
    if (!timing && a[c] != b[c]) return false;
  }
  return true;
}

}  // namespace

std::vector<std::string> study_columns(const ClassMapping& mapping) {
  std::vector<std::string> columns = kRunColumns;
  for (const auto& c : mapping.evaluation_classes()) columns.push_back("iou_" + c.name);
  columns.insert(columns.end(), kRecordColumns.begin(), kRecordColumns.end());
  columns.insert(columns.end(), kTimingColumns.begin(), kTimingColumns.end());
  return columns;
}

std::vector<std::string> study_cells(const StudyRow& row, const ClassMapping& mapping) {
  const SegmentationMetrics& m = row.metrics;
  std::vector<std::string> cells = {std::to_string(row.run),
                                    row.scene,
                                    row.configuration,
                                    row.failure.empty() ? "ok" : "failed",
                                    std::to_string(row.viewpoints.size()),
                                    positions(row.viewpoints),
                                    std::to_string(row.points),
                                    std::to_string(row.scanned_points),
                                    number(row.visible_fraction),
                                    number(row.occlusion_level),
                                    number(row.exterior_occlusion_level),
                                    number(row.interior_exterior_ratio),
                                    row.segmenter,
                                    to_string(m.mean_over),
                                    number(m.miou),
                                    number(m.overall_accuracy),
                                    number(m.mean_class_accuracy)};
  for (const auto& c : mapping.evaluation_classes()) {
    const auto metrics = std::find_if(m.classes.begin(), m.classes.end(),
                                      [&](const ClassMetrics& k) { return k.id == c.id; });
    cells.push_back(metrics == m.classes.end() ? "" : number(metrics->iou));
  }
  cells.push_back(row.failure);
  cells.push_back(row.fingerprint);
  for (const double seconds : {row.scan_seconds, row.occlusion_seconds, row.segmentation_seconds,
                               row.evaluation_seconds}) {
    cells.push_back(format_number("%.3f", seconds));
  }
  return cells;
}

std::optional<double> cell_number(const std::string& cell) {
  if (cell.empty()) return std::nullopt;
  char* end = nullptr;
  const double value = std::strtod(cell.c_str(), &end);
  if (end != cell.c_str() + cell.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

bool failed_row(const CsvTable& table, const std::vector<std::string>& row) {
  return row.at(table.column("status")) == "failed";
}

std::string run_key(const CsvTable& table, const std::vector<std::string>& row) {
  return row.at(table.column("scene")) + '\n' + row.at(table.column("configuration"));
}

CsvTable read_study_table(const std::string& path, const std::vector<std::string>& columns) {
  if (!std::filesystem::exists(path)) return CsvTable{columns, {}};
  CsvTable table = read_csv(path);
  if (table.columns != columns) {
    throw UsageError(path +
                     ": its columns are not this study's (was it written with another class "
                     "mapping?); give another --out, or remove it to start again");
  }
  return table;
}

void sort_by_run(CsvTable& table) {
  const std::size_t run = table.column("run");
  std::stable_sort(table.rows.begin(), table.rows.end(), [run](const auto& a, const auto& b) {
    return cell_number(a[run]).value_or(0.0) < cell_number(b[run]).value_or(0.0);
  });
}

CsvTable merge_study_tables(const std::vector<CsvTable>& tables,
                            const std::vector<std::string>& names,
                            std::vector<std::string>& warnings) {
  if (tables.empty()) throw UsageError("study merge: no CSV given");
  CsvTable merged{tables.front().columns, {}};
  for (const char* needed : {"run", "scene", "configuration", "miou"}) {
    if (merged.column(needed) == merged.columns.size()) {
      throw UsageError(names.front() + ": not a study CSV (no column '" + needed + "')");
    }
  }
  std::map<std::string, std::size_t> seen;  // run key -> row in `merged`
  for (std::size_t t = 0; t < tables.size(); ++t) {
    if (tables[t].columns != merged.columns) {
      throw UsageError(names[t] + ": its columns differ from " + names.front() +
                       "'s (another class mapping?); only shards of one study merge");
    }
    for (const auto& row : tables[t].rows) {
      const std::string key = run_key(merged, row);
      const auto [where, added] = seen.emplace(key, merged.rows.size());
      if (added) {
        merged.rows.push_back(row);
      } else if (!same_figures(merged, merged.rows[where->second], row)) {
        warnings.push_back(names[t] + ": run (" + row[merged.column("scene")] + ", " +
                           row[merged.column("configuration")] +
                           ") has other figures than an earlier CSV's; the first is kept");
      }
    }
  }
  sort_by_run(merged);
  return merged;
}

}  // namespace occlusion::job
