#pragma once
// The study job's pieces (internal to app/): one run (study_run.cpp), its
// segmentation (study_segmenter.cpp), the CSV table (study_table.cpp) and the
// summary (study_summary.cpp). study_job.cpp puts them together.

#include <json/value.h>

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "occlusion/analysis/class_mapping.hpp"
#include "occlusion/app/evaluate_job.hpp"
#include "occlusion/app/scan_job.hpp"
#include "occlusion/app/study_job.hpp"
#include "occlusion/core/polygon.hpp"
#include "segmenter_worker.hpp"

namespace occlusion::job {

// What every run of one invocation shares.
struct StudyContext {
  const StudyRequest& request;
  ClassMapping mapping;
  std::vector<PlanarPolygon> openings;
  std::string runs_dir;        // OUT/runs: scanned clouds and predictions
  Json::Value row_parameters;  // row_parameters(request), for the fingerprints
  // A "worker: COMMAND" segmenter's process, kept from run to run and ended
  // with the study (segmenter_worker.hpp).
  std::shared_ptr<SegmenterWorker> worker = idle_segmenter_worker();
};

// Why one run failed on its own (the segmenter crashed, timed out or wrote a
// bad prediction): the study records a failed row and goes on.
struct RunFailure : std::runtime_error {
  RunFailure(const std::string& reason, std::string tail)
      : std::runtime_error(reason), output_tail(std::move(tail)) {}
  std::string output_tail;  // the end of the segmenter's stdout and stderr
};

// One run's figures, as a CSV row holds them.
struct StudyRow {
  std::size_t run = 0;
  std::string scene, configuration;
  std::vector<Eigen::Vector3d> viewpoints;
  std::size_t points = 0, scanned_points = 0;
  double visible_fraction = 0.0;
  double occlusion_level = 0.0;
  std::optional<double> exterior_occlusion_level, interior_exterior_ratio;
  std::string segmenter;
  SegmentationMetrics metrics;  // empty for a failed run
  std::string failure;          // empty: the run succeeded; else why not, and the stderr tail
  std::string fingerprint;      // row_fingerprint of the parameters it was made with
  double scan_seconds = 0.0, occlusion_seconds = 0.0, segmentation_seconds = 0.0,
         evaluation_seconds = 0.0;
};

struct StudyRunInput {
  std::size_t index = 0;  // k of the docs: scene-major
  std::string scene_name;
  std::string scene_path;
  const PointCloud* cloud = nullptr;
  const NamedViewpointChoice* configuration = nullptr;
};

// Scans, measures, segments and scores one run. Its scanned cloud and
// prediction are left in context.runs_dir.
StudyRow run_study_once(const StudyContext& context, const StudyRunInput& run,
                        const Progress& progress, std::vector<std::string>& warnings);

// A run's scan made by the scan_model's sensor: the scanned cloud in the
// scene's frame (its labels from the mesh's groups, its colours from the
// scene's nearest points) and, per scene point, whether a return lies
// within twice the scene's spacing of it (what the scan covered).
struct SensorScan {
  PointCloud scanned;
  std::vector<bool> covered;
};
SensorScan sensor_scan(const StudyRequest& request, const PointCloud& scene,
                       const std::string& scene_path, const ViewpointChoice::Resolved& viewpoints,
                       const Progress& progress);
// The scene's mesh: ROOM/ROOM.obj for a folder, X.obj for a file X.ply.
std::string scene_mesh_path(const std::string& scene_path);
// UsageError when the scan model needs the scene's mesh and it is missing.
void check_scene_mesh(const StudyRequest& request, const std::string& scene_path);

// The request as -fscan would take it for `scene`.
ScanRequest study_scan_request(const StudyRequest& request, const std::string& scene);
// File stem of a run's files in runs/: scene and configuration, made safe.
std::string run_file_stem(const std::string& scene, const std::string& configuration);

// The segmenter's name in the CSV and the report: the baseline's long name,
// or the command template as given.
std::string segmenter_name(const std::string& segmenter);
// The scanned cloud's labels as the segmenter predicts them, in evaluation ids
// (the baseline) or as the command wrote them. `prediction_path` receives the
// file the prediction is in, `output_tail` the end of the command's output.
// RunFailure for a command that fails, times out or writes nothing;
// InputError for a prediction that cannot be read.
Prediction segment_scanned_cloud(const StudyContext& context, const PointCloud& scanned,
                                 const std::string& scanned_path, const std::string& stem,
                                 const Progress& progress, std::string& prediction_path,
                                 std::string& output_tail, std::vector<std::string>& warnings);
// UsageError unless the segmenter is the baseline, a template with {input}
// and {output}, or "worker: COMMAND" (neither in it), and segmenter_output an
// extension -eval reads.
void validate_segmenter(const StudyRequest& request);

// Every parameter that changes a row's figures (not the scenes, the
// configurations, the shard, the threads or the output folder), by key; the
// openings and mapping files by a digest of their contents (polygon_file,
// mapping_file), so that the rows do not depend on where the files are.
// For a scene's rows: row_parameters(scene_request(request, scene)), so a
// scene without overrides has the study's.
Json::Value row_parameters(const StudyRequest& request);
// Each scene's name in the CSV: its file or folder name; where two scenes
// share it (S3DIS has an office_1 in every Area), with its parent folder's.
// UsageError when two scenes would still share a name.
std::vector<std::string> scene_names(const std::vector<StudyScene>& scenes);
// {scene name: its overrides} for the scenes that have any, an openings file
// by a digest of its contents (polygon_file) as row_parameters has it.
Json::Value scene_overrides(const StudyRequest& request);
// row_parameters with the scenes (with their overrides), scene_overrides,
// the configurations, polygon_path and mapping_path: study.json's list and
// study.parameters.json's content.
Json::Value study_parameters(const StudyRequest& request);
// study_parameters without the scenes, their overrides, the configurations
// and paths: the study-wide row parameters.
Json::Value row_parameters_of(const Json::Value& study_parameters);
// study_parameters' overrides of the scene called `scene`; {} when none (or a
// study.parameters.json written before scenes had overrides).
Json::Value scene_overrides_of(const Json::Value& study_parameters, const std::string& scene);
// The entry of study_parameters' configurations called `name`; null when none is.
Json::Value configuration_of(const Json::Value& study_parameters, const std::string& name);
// 16 hex digits hashing the row parameters and the configuration's viewpoints.
std::string row_fingerprint(const Json::Value& row_parameters,
                            const NamedViewpointChoice& configuration);
// Keys whose values differ between two parameter objects, or that only one has.
std::vector<std::string> differing_keys(const Json::Value& before, const Json::Value& now);
// "point_radius (was 0.06, now 0.05), ..." for those keys.
std::string describe_differences(const Json::Value& before, const Json::Value& now);
// OUT/study.parameters.json: the parameters of the rows in OUT/study.csv.
std::string parameters_path(const std::string& out);
// Nothing when the file does not exist; InputError when it is not JSON.
std::optional<Json::Value> read_parameters(const std::string& path);
void write_parameters(const std::string& path, const Json::Value& parameters);

// The CSV columns: the run's identity and figures, one iou_<class> per
// evaluation class of the mapping, then the timings (columns ending _seconds).
std::vector<std::string> study_columns(const ClassMapping& mapping);
std::vector<std::string> study_cells(const StudyRow& row, const ClassMapping& mapping);
// A cell as a number; nothing for an empty cell or text.
std::optional<double> cell_number(const std::string& cell);
// Whether a row's `status` is "failed".
bool failed_row(const CsvTable& table, const std::vector<std::string>& row);
// "scene\nconfiguration": what makes a run the same run in another CSV.
std::string run_key(const CsvTable& table, const std::vector<std::string>& row);
// The study's CSV, or an empty table with `columns` when there is none yet.
// UsageError when the file has other columns (another class mapping).
CsvTable read_study_table(const std::string& path, const std::vector<std::string>& columns);
// Stable, by the `run` column.
void sort_by_run(CsvTable& table);
// Rows of all tables, one per run key, the first kept; UsageError when the
// columns differ or are not a study's.
CsvTable merge_study_tables(const std::vector<CsvTable>& tables,
                            const std::vector<std::string>& names,
                            std::vector<std::string>& warnings);

// The correlations, study.svg, study.md and study.json of report.table, in `out`.
void write_study_summary(StudyReport& report, const std::string& out);

}  // namespace occlusion::job
