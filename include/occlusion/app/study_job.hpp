#pragma once
// The `study` job: how much does occlusion hurt semantic segmentation? For
// each labelled scene x viewpoint configuration (a run):
//   1. scan the scene from the configuration's viewpoints (as -fscan),
//   2. measure the scanned cloud's occlusion (as -poc, and its exterior variant),
//   3. segment the scanned cloud (the built-in baseline, or a command the user
//      supplies, e.g. a network's inference script),
//   4. score the segmentation against the scanned cloud's own labels (as -eval),
// and append one row to OUT/study.csv. Then the correlation of each occlusion
// measure with mIoU goes to OUT/study.md with a plot, OUT/study.svg.
//
// Runs already in study.csv are skipped, so an interrupted study resumes; each
// finished run rewrites the CSV atomically. A run whose segmenter fails (exit
// status, timeout, a prediction that cannot be read) is a `failed` row, and
// the study goes on; a resume retries failed rows. Every row carries a
// fingerprint of the parameters it was made with, and resuming with other
// parameters is a UsageError naming them. With a shard i/n only the runs
// whose index k (scene-major: k = scene * configurations + configuration)
// has k mod n = i are made; run_study_merge joins the shards' CSVs.
// docs/study.md has the CSV columns, the baseline's rules and sharding recipes.

#include <json/value.h>

#include <cstdint>
#include <string>
#include <vector>

#include "occlusion/analysis/class_mapping.hpp"
#include "occlusion/analysis/clustered_inference.hpp"
#include "occlusion/analysis/confusion_matrix.hpp"
#include "occlusion/analysis/correlation.hpp"
#include "occlusion/analysis/mesh_estimation.hpp"
#include "occlusion/analysis/sensor_model.hpp"
#include "occlusion/analysis/virtual_scanner.hpp"
#include "occlusion/app/cloud_occlusion_job.hpp"
#include "occlusion/app/key.hpp"
#include "occlusion/app/viewpoint_choice.hpp"
#include "occlusion/core/progress.hpp"
#include "occlusion/io/csv_file.hpp"

namespace occlusion {

// The segmenter that needs no GPU: analysis/baseline_segmenter.hpp.
inline constexpr const char* kBaselineSegmenter = "baseline";

// -poc's defaults, with the exterior variant on: the study reports both levels.
CloudOcclusionRequest default_study_tracing();
// -rgoc's defaults for the baseline, but clusters of any size: a real room's
// walls and floor are far larger than -rgoc's max_cluster_size of 100000.
RegionGrowingOptions default_study_estimation();

// The study's reference set: a 3 x 3 grid (docs/study.md says why).
inline constexpr unsigned kReferenceViewpoints = 9;

// scan_model: the scan as the ideal subset of the scene's points that the
// viewpoints see, or as a terrestrial laser scanner measures the scene's
// surfaces (the virtual scanner, analysis/virtual_scanner.hpp).
inline constexpr const char* kIdealScan = "ideal";
inline constexpr const char* kLaserScan = "laser";

// A scene of the study, and the study-wide keys it sets otherwise: rooms
// scanned at another density, with their own openings, or exported y-up.
struct StudyScene {
  StudyScene() = default;
  StudyScene(std::string scene_path)  // NOLINT: a scene without overrides is its path
      : path(std::move(scene_path)) {}
  StudyScene(const char* scene_path) : path(scene_path) {}  // NOLINT: as above
  std::string path;  // a labelled cloud with class names, an S3DIS room, ...
  // Key -> value, for keys of study_scene_override_keys() only (checked as
  // those keys are); empty: the study's values.
  Json::Value overrides{Json::objectValue};
};

// The study's keys a scene entry may set for itself: the point model of its
// scans and measures (primitive, point_radius, disc_coverage,
// normal_neighbours, self_tolerance), its openings (polygon_path) and where
// its configurations stand (frame, up).
const std::vector<std::string>& study_scene_override_keys();

struct StudyRequest {
  std::vector<StudyScene> scenes;
  std::vector<NamedViewpointChoice> configurations;
  // How clouds are traced, as -poc takes it (its path, viewpoints and out do
  // not apply). Its point_radius, octree keys, seed, threads and
  // skip_bad_lines serve the whole study, the scan included.
  CloudOcclusionRequest tracing = default_study_tracing();
  double self_tolerance = -1.0;  // of the scan, as -fscan; negative: 2 * point_radius
  // kIdealScan or kLaserScan. A laser scan scans the scene's mesh (the OBJ
  // beside it) from each configuration's viewpoints with `laser`, noise
  // drawn from the seed, returns beyond max_incidence lost.
  std::string scan_model = kIdealScan;
  LaserScannerModel laser;
  double max_incidence = SimulationOptions{}.max_incidence_deg;
  std::string format = "ply";  // of the scanned clouds written for the segmenter
  // N: measure every scanned cloud's occlusion from the same N viewpoints on a
  // grid over the whole scene, so that the measure ranks configurations by
  // what their scans lack, not by where they stood; 0: from each
  // configuration's own viewpoints (then a configuration is measured from
  // where it scanned, and its scan's holes stay out of sight).
  unsigned occlusion_num_vp = kReferenceViewpoints;
  // "scanned": mIoU over the points the scan kept (what the segmenter saw);
  // "full": over every point of the scene, those the scan missed counting
  // as misses of their class (occlusion's whole cost).
  std::string scoring = "scanned";
  // "baseline", or a shell command with {input} (the scanned cloud) and
  // {output} (where it must write its prediction) in it.
  std::string segmenter = kBaselineSegmenter;
  // What the command writes to {output} (its extension): a cloud with
  // coordinates and labels (ply, pcd, txt), paired with {input} point by
  // point by position, so that every pairing is checked; or, when asked for,
  // a bare label file (labels), whose order nothing can check.
  std::string segmenter_output = "ply";
  // Seconds one segmenter command may run before it is killed and its run
  // marked failed; 0: no limit.
  double segmenter_timeout = 0.0;
  RegionGrowingOptions estimation = default_study_estimation();  // the baseline's planes
  std::string class_mapping = ClassMapping::kDefaultBuiltin;     // as -eval: table3.1 or scannet20
  std::string mapping_path;  // as -eval; "" = class_mapping as it is
  std::vector<std::string> ignored_classes;
  MeanOver mean_over = MeanOver::support;  // as -eval: which classes mIoU averages
  std::string shard = "0/1";               // "i/n"
  std::string out;                         // required
  // Other studies' folders (their study.csv) of the same runs: the summary
  // sets each one's within-scene slopes beside this study's, and their
  // difference, from one bootstrap over the paired runs.
  std::vector<std::string> compare_with;
  // Resuming: keep the failed rows of study.csv instead of retrying them.
  bool skip_failed = false;
  // Start again: drop the rows of study.csv (even if made with other
  // parameters) instead of resuming.
  bool fresh = false;
  // Each run's scan, occlusion and baseline planes are refused, with their
  // estimate, above it (app/memory_budget); 0: the machine's memory.
  std::uint64_t max_memory_mb = 0;
};

struct StudyShard {
  std::size_t index = 0;
  std::size_t count = 1;
};
// "i/n" with 0 <= i < n. UsageError naming --shard otherwise.
StudyShard parse_shard(const std::string& text);

// One occlusion measure against mIoU over the table's rows that have both.
struct MeasureCorrelation {
  std::string measure;  // a column: visible_fraction, occlusion_level, ...
  Correlation correlation;
  // The same runs with their scenes: intervals, p-values and the within-scene
  // slope (analysis/clustered_inference.hpp).
  ClusteredAssociation association;
};

// This study against another of the same runs, for one measure: runs paired
// by scene and configuration (both with the measure and an mIoU).
struct StudyComparison {
  std::string study;    // the other study's folder, as given
  std::string measure;  // a column: occlusion_level, ...
  PairedSlopes slopes;  // first: the other study; second: this one
};

struct StudyReport {
  std::string job = "study";  // or "study_merge"
  StudyRequest request;       // as run (merge: out only)
  // Every parameter of the rows (app/study_parameters): the request's, or for
  // a merge the shards' study.parameters.json (empty when none has one).
  Json::Value parameters{Json::objectValue};
  std::vector<std::string> inputs;  // merge: the CSVs joined
  std::size_t runs_total = 0;       // scenes x configurations
  std::size_t runs_in_shard = 0;
  std::size_t runs_skipped = 0;  // in the shard, already in study.csv
  std::size_t runs_computed = 0;
  std::size_t runs_failed = 0;  // rows of the table whose status is failed
  CsvTable table;               // every row of study.csv, in run order
  std::vector<MeasureCorrelation> correlations;
  std::vector<StudyComparison> comparisons;  // per compare_with study and measure
  std::vector<std::string> outputs;
  std::vector<std::string> warnings;
  double total_seconds = 0.0;
};

// Throws UsageError naming the option at fault (and the scene, for a
// scene's overrides).
void validate(const StudyRequest& request);
// The study as it applies to `scene`: `study` with the scene's overrides set
// and its scenes that one alone.
StudyRequest scene_request(StudyRequest study, const StudyScene& scene);
// Every key of the job (config section occlusion.study), declared once.
const Keys<StudyRequest>& study_keys();
// Those of them that only a sensor's scan uses (laser_*, max_incidence).
const Keys<StudyRequest>& study_sensor_keys();
// Writes OUT/study.csv (after every run), study.svg, study.md, study.json and
// OUT/runs/ (each run's scanned cloud and prediction). UsageError for bad
// options, a scene whose classes the mapping does not know, or a study.csv
// written with other columns; InputError for unreadable scenes and
// predictions, and for study.csv rows made with other parameters (naming the
// keys; `fresh` starts again instead). A segmenter that fails is no error: its
// row is `failed` and counted in runs_failed. Cancelled leaves study.csv with
// every finished row.
StudyReport run_study(const StudyRequest& request, const Progress& progress = {});

// Joins study CSVs (the shards') into OUT/study.csv, rows in run order, one
// per (scene, configuration): the first wins, and a second with other figures
// is a warning. Then writes the summary as run_study does. UsageError for
// CSVs with different columns or whose study.parameters.json beside them
// differ; InputError for unreadable ones. `compare_with` as the study's key.
StudyReport run_study_merge(const std::vector<std::string>& inputs, const std::string& out,
                            const std::vector<std::string>& compare_with = {});

// Headline: correlations (each measure's n, pearson, spearman against miou).
Json::Value to_json(const StudyReport& report);

}  // namespace occlusion
