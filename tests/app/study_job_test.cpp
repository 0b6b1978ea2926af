#include "occlusion/app/study_job.hpp"
#include "occlusion/app/config.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "io/scratch_directory.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/json_file.hpp"
#include "occlusion/app/json_output.hpp"
#include "occlusion/core/random.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/label_file.hpp"

namespace occlusion {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::ScratchDirectory;
using testing::write_text;

const std::string kSource = OCCLUSION_SOURCE_DIR;

// config/study.json (the office from patterns 7, 4 and 1: C+U+L, C+U, C) with
// few rays, so that a whole study takes about a second.
StudyRequest office_study(const std::string& out) {
  StudyRequest request;
  apply_config(load_config(kSource + "/config/study.json"), "study", study_keys(), request);
  request.tracing.num_rays_per_vp = 400;
  request.out = out;
  return request;
}

// The table without its timings, which differ from one computation to the next.
std::vector<std::vector<std::string>> figures(const CsvTable& table) {
  std::vector<std::vector<std::string>> rows = table.rows;
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    if (table.columns[c].find("_seconds") == std::string::npos) continue;
    for (auto& row : rows) row[c].clear();
  }
  return rows;
}

double number(const CsvTable& table, std::size_t row, const std::string& column) {
  return std::stod(table.rows.at(row).at(table.column(column)));
}

std::size_t count(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

// tests/support/study_segmenter.py in one of its modes (its docstring): a
// segmenter that answers with a cloud, or misbehaves in a given way.
std::string test_segmenter(const std::string& mode) {
  return "python3 '" + kSource + "/tests/support/study_segmenter.py' " + mode + " {input} {output}";
}

// The scanned cloud's points, each labelled wall (evaluation id 0).
const std::string kAllWall = test_segmenter("wall");

TEST(StudyJob, VisibleFractionFallsAsViewpointsAreRemoved) {
  const ScratchDirectory dir;
  const StudyReport report = run_study(office_study(dir.file("study")));
  EXPECT_EQ(report.runs_total, 3u);
  EXPECT_EQ(report.runs_computed, 3u);
  EXPECT_EQ(report.runs_skipped, 0u);
  const CsvTable& table = report.table;
  ASSERT_EQ(table.rows.size(), 3u);
  EXPECT_EQ(table.rows[0][table.column("configuration")], "pattern_7");
  EXPECT_EQ(table.rows[2][table.column("configuration")], "pattern_1");
  // Pattern 7 sees from C, U and L, pattern 4 from C and U, pattern 1 from C:
  // each scan keeps a subset of the one before, so this holds exactly.
  EXPECT_GT(number(table, 0, "visible_fraction"), number(table, 1, "visible_fraction"));
  EXPECT_GT(number(table, 1, "visible_fraction"), number(table, 2, "visible_fraction"));
  EXPECT_GT(number(table, 0, "scanned_points"), number(table, 1, "scanned_points"));
  EXPECT_EQ(number(table, 2, "viewpoints"), 1.0);
  for (std::size_t r = 0; r < 3; ++r) {
    EXPECT_GT(number(table, r, "miou"), 0.0);
    EXPECT_LT(number(table, r, "miou"), 1.0);
    EXPECT_GE(number(table, r, "exterior_occlusion_level"), number(table, r, "occlusion_level"));
    EXPECT_EQ(table.rows[r][table.column("segmenter")],
              "baseline (geometric, region-growing planes)");
  }

  ASSERT_EQ(report.correlations.size(), 3u);
  for (const auto& m : report.correlations) {
    EXPECT_EQ(m.correlation.n, 3u) << m.measure;
    EXPECT_TRUE(m.correlation.pearson) << m.measure;
  }
  const std::string svg = read_bytes(dir.file("study/study.svg"));
  EXPECT_EQ(count(svg, "<circle"), 9u);  // 3 runs x 3 measures
  EXPECT_EQ(count(svg, "class=\"fit\""), 3u);
  const std::string markdown = read_bytes(dir.file("study/study.md"));
  EXPECT_NE(markdown.find("baseline (geometric, region-growing planes)"), std::string::npos);
  EXPECT_NE(markdown.find("![mIoU against occlusion](study.svg)"), std::string::npos);
  EXPECT_NE(markdown.find("| occlusion_level | 3 |"), std::string::npos);
  EXPECT_EQ(read_csv(dir.file("study/study.csv")).rows, table.rows);
  EXPECT_TRUE(fs::exists(dir.file("study/study.json")));

  // The scanned cloud the segmenter saw is the ground truth it is scored against.
  const PointCloud scanned = read_cloud(dir.file("study/runs/office_1__pattern_1.scan.ply"));
  EXPECT_EQ(static_cast<double>(scanned.size()), number(table, 2, "scanned_points"));
  EXPECT_EQ(read_label_file(dir.file("study/runs/office_1__pattern_1.baseline.labels")).size(),
            scanned.size());
}

TEST(StudyJob, ShardsMergeIntoTheFullRun) {
  const ScratchDirectory dir;
  const StudyReport full = run_study(office_study(dir.file("full")));
  StudyRequest first = office_study(dir.file("shard0"));
  first.shard = "0/2";
  StudyRequest second = office_study(dir.file("shard1"));
  second.shard = "1/2";
  EXPECT_EQ(run_study(first).runs_in_shard, 2u);  // runs 0 and 2
  EXPECT_EQ(run_study(second).runs_in_shard, 1u);
  const StudyReport merged = run_study_merge(
      {dir.file("shard1/study.csv"), dir.file("shard0/study.csv")}, dir.file("merged"));
  EXPECT_EQ(merged.job, "study_merge");
  EXPECT_TRUE(merged.warnings.empty());
  EXPECT_EQ(figures(merged.table), figures(full.table));
  EXPECT_EQ(figures(read_csv(dir.file("merged/study.csv"))), figures(full.table));
  ASSERT_EQ(merged.correlations.size(), full.correlations.size());
  for (std::size_t m = 0; m < full.correlations.size(); ++m) {
    EXPECT_EQ(merged.correlations[m].correlation.pearson, full.correlations[m].correlation.pearson);
    EXPECT_EQ(merged.correlations[m].correlation.spearman,
              full.correlations[m].correlation.spearman);
  }
  EXPECT_TRUE(fs::exists(dir.file("merged/study.md")));
  EXPECT_TRUE(fs::exists(dir.file("merged/study.svg")));

  // A run twice, with the same figures, is one row.
  const StudyReport again =
      run_study_merge({dir.file("full/study.csv"), dir.file("shard0/study.csv")}, dir.file("m2"));
  EXPECT_EQ(figures(again.table), figures(full.table));
}

TEST(StudyJob, ARestartMakesOnlyTheMissingRuns) {
  const ScratchDirectory dir;
  const StudyRequest request = office_study(dir.file("study"));
  const StudyReport first = run_study(request);
  CsvTable interrupted = read_csv(dir.file("study/study.csv"));
  interrupted.rows.erase(interrupted.rows.begin() + 1);  // pattern_4
  write_csv(dir.file("study/study.csv"), interrupted);

  const StudyReport resumed = run_study(request);
  EXPECT_EQ(resumed.runs_computed, 1u);
  EXPECT_EQ(resumed.runs_skipped, 2u);
  EXPECT_EQ(figures(resumed.table), figures(first.table));
  // The kept rows are the file's, to the letter (timings included).
  EXPECT_EQ(resumed.table.rows[0], interrupted.rows[0]);

  const StudyReport nothing_left = run_study(request);
  EXPECT_EQ(nothing_left.runs_computed, 0u);
  EXPECT_EQ(nothing_left.table.rows, resumed.table.rows);
}

TEST(StudyJob, ASegmenterCommandPlugsIn) {
  const ScratchDirectory dir;
  StudyRequest request = office_study(dir.file("study"));
  request.configurations.resize(1);
  request.segmenter = kAllWall;
  const StudyReport report = run_study(request);
  const CsvTable& table = report.table;
  ASSERT_EQ(table.rows.size(), 1u);
  EXPECT_EQ(table.rows[0][table.column("segmenter")], request.segmenter);
  const std::string prediction = dir.file("study/runs/office_1__pattern_7.prediction.ply");
  EXPECT_EQ(static_cast<double>(read_cloud(prediction).size()), number(table, 0, "scanned_points"));

  // Everything called wall: accuracy is the walls' share of the scanned points.
  const PointCloud scanned = read_cloud(dir.file("study/runs/office_1__pattern_7.scan.ply"));
  std::size_t walls = 0;
  for (const auto label : scanned.labels) walls += scanned.class_names[label] == "wall" ? 1 : 0;
  EXPECT_NEAR(number(table, 0, "overall_accuracy"),
              static_cast<double>(walls) / static_cast<double>(scanned.size()), 1e-9);
  EXPECT_NEAR(number(table, 0, "iou_wall"), number(table, 0, "overall_accuracy"), 1e-9);
  EXPECT_EQ(number(table, 0, "iou_floor+ceiling"), 0.0);
}

std::string cell(const CsvTable& table, std::size_t row, const std::string& column) {
  return table.rows.at(row).at(table.column(column));
}

// The figures of one row, timings left out.
std::vector<std::string> row_figures(const CsvTable& table, std::size_t row) {
  CsvTable one{table.columns, {table.rows.at(row)}};
  return figures(one).front();
}

TEST(StudyJob, ARunWhoseSegmenterFailsFailsAloneAndIsRetried) {
  const ScratchDirectory dir;
  const std::string flag = dir.file("pattern_4_fails");
  write_text(flag, "");
  StudyRequest request = office_study(dir.file("study"));
  // Fails on pattern_4 while the flag exists, saying why on stderr.
  request.segmenter = "case {input} in *pattern_4*) if [ -e '" + flag +
                      "' ]; then echo 'CUDA out of memory' >&2; exit 3; fi;; esac; " + kAllWall;
  const StudyReport failing = run_study(request);
  EXPECT_EQ(failing.runs_computed, 3u);
  EXPECT_EQ(failing.runs_failed, 1u);
  const CsvTable& table = failing.table;
  ASSERT_EQ(table.rows.size(), 3u);
  EXPECT_EQ(cell(table, 0, "status"), "ok");
  EXPECT_EQ(cell(table, 1, "status"), "failed");
  EXPECT_EQ(cell(table, 2, "status"), "ok");
  const std::string why = cell(table, 1, "failure");
  EXPECT_NE(why.find("exit status 3"), std::string::npos) << why;
  EXPECT_NE(why.find("CUDA out of memory"), std::string::npos) << why;
  EXPECT_EQ(cell(table, 1, "miou"), "");
  EXPECT_NE(cell(table, 1, "visible_fraction"), "");  // the scan and measure did run
  EXPECT_EQ(cell(table, 0, "failure"), "");
  // The correlations leave the failed run out.
  for (const auto& m : failing.correlations) EXPECT_EQ(m.correlation.n, 2u) << m.measure;
  EXPECT_NE(read_bytes(dir.file("study/study.md")).find("## Failed runs"), std::string::npos);

  // The other rows are what a study without the failure gives.
  StudyRequest clean = request;
  clean.out = dir.file("clean");
  fs::remove(flag);
  const StudyReport reference = run_study(clean);
  ASSERT_EQ(reference.runs_failed, 0u);
  EXPECT_EQ(row_figures(table, 0), row_figures(reference.table, 0));
  EXPECT_EQ(row_figures(table, 2), row_figures(reference.table, 2));

  // Keeping failed rows makes nothing; a plain resume retries only the failed run.
  StudyRequest keep = request;
  keep.skip_failed = true;
  const StudyReport kept = run_study(keep);
  EXPECT_EQ(kept.runs_computed, 0u);
  EXPECT_EQ(kept.runs_failed, 1u);
  const StudyReport retried = run_study(request);
  EXPECT_EQ(retried.runs_computed, 1u);
  EXPECT_EQ(retried.runs_skipped, 2u);
  EXPECT_EQ(retried.runs_failed, 0u);
  EXPECT_EQ(figures(retried.table), figures(reference.table));
}

TEST(StudyJob, ATimeoutOrABadLabelFileFailsTheRun) {
  const ScratchDirectory dir;
  StudyRequest request = office_study(dir.file("slow"));
  request.configurations.resize(1);
  // Killed at the timeout, not waited for: it never says "finished".
  request.segmenter = "echo started; sleep 30; echo finished # {input} {output}";
  request.segmenter_timeout = 0.5;
  const StudyReport slow = run_study(request);
  ASSERT_EQ(slow.table.rows.size(), 1u);
  EXPECT_EQ(slow.runs_failed, 1u);
  const std::string why = cell(slow.table, 0, "failure");
  EXPECT_NE(why.find("timed out"), std::string::npos) << why;
  EXPECT_NE(why.find("started"), std::string::npos) << why;
  EXPECT_EQ(why.find("finished"), std::string::npos) << why;

  // Two labels for hundreds of points, in a label file asked for.
  request.out = dir.file("short");
  request.segmenter = "printf '0\\n0\\n' > {output} # {input}";
  request.segmenter_output = "labels";
  request.segmenter_timeout = 0.0;
  const StudyReport bad = run_study(request);
  EXPECT_EQ(bad.runs_failed, 1u);
  EXPECT_NE(cell(bad.table, 0, "failure").find("cannot be scored"), std::string::npos)
      << cell(bad.table, 0, "failure");

  // Writing nothing is a failure too.
  request.out = dir.file("silent");
  request.segmenter = "true {input} {output}";
  EXPECT_NE(cell(run_study(request).table, 0, "failure").find("wrote nothing"), std::string::npos);
}

// One run (pattern_7) with `segmenter`, its output as `segmenter_output` says.
StudyReport one_run(const ScratchDirectory& dir, const std::string& name,
                    const std::string& segmenter, const std::string& segmenter_output = "ply") {
  StudyRequest request = office_study(dir.file(name));
  request.configurations.resize(1);
  request.segmenter = segmenter;
  request.segmenter_output = segmenter_output;
  return run_study(request);
}

TEST(StudyJob, ACloudPredictionIsPairedByPositionAndALabelFileOffByOneIsRefused) {
  const ScratchDirectory dir;
  // The ground truth as a cloud, written in reverse order: paired by
  // position, every label finds its point.
  const StudyReport truth = one_run(dir, "truth", test_segmenter("truth"));
  ASSERT_EQ(truth.runs_failed, 0u) << cell(truth.table, 0, "failure");
  EXPECT_EQ(number(truth.table, 0, "miou"), 1.0);
  EXPECT_EQ(number(truth.table, 0, "overall_accuracy"), 1.0);

  // Issue 29: a segmenter whose bare labels are one line late. By default the
  // study wants a cloud, so the label file is refused (a failed row, not a
  // slightly worse mIoU).
  const StudyReport late = one_run(dir, "late", test_segmenter("off_by_one"));
  EXPECT_EQ(late.runs_failed, 1u);
  EXPECT_EQ(cell(late.table, 0, "status"), "failed");
  EXPECT_EQ(cell(late.table, 0, "miou"), "");
  const std::string why = cell(late.table, 0, "failure");
  EXPECT_NE(why.find("segmenter_output is ply"), std::string::npos) << why;
  EXPECT_NE(why.find("segmenter_output labels"), std::string::npos) << why;

  // Asked for explicitly, label files are paired by order, which nothing can
  // check: the same segmenter then passes with a slightly lower mIoU (the
  // risk docs/study.md states), and the right order scores 1.
  const StudyReport risky = one_run(dir, "risky", test_segmenter("off_by_one"), "labels");
  ASSERT_EQ(risky.runs_failed, 0u);
  EXPECT_LT(number(risky.table, 0, "miou"), 1.0);
  EXPECT_GT(number(risky.table, 0, "miou"), 0.9);
  const StudyReport in_order =
      one_run(dir, "in_order", test_segmenter("labels_in_order"), "labels");
  EXPECT_EQ(number(in_order.table, 0, "miou"), 1.0);
}

TEST(StudyJob, ACloudPredictionWithMissingExtraOrMovedPointsFailsItsRun) {
  const ScratchDirectory dir;
  for (const auto& [mode, reason] : std::vector<std::pair<std::string, std::string>>{
           {"drop_last", "1 points of {input} have no predicted point at their coordinates"},
           {"extra_point", "1 predicted points are none of {input}'s"},
           // Issue 44, 2.6: the reader dropped the NaN point, the rest paired,
           // and the run scored ok.
           {"nan_point", "1 points with a non-finite coordinate (NaN or infinity)"},
           {"moved_point",
            "1 points of {input} have no predicted point at their coordinates "
            "(the first: point 0 at ("}}) {
    const StudyReport report = one_run(dir, mode, test_segmenter(mode));
    EXPECT_EQ(report.runs_failed, 1u) << mode;
    EXPECT_EQ(cell(report.table, 0, "status"), "failed") << mode;
    EXPECT_EQ(cell(report.table, 0, "miou"), "") << mode;
    const std::string why = cell(report.table, 0, "failure");
    EXPECT_NE(why.find(reason), std::string::npos) << mode << ": " << why;
    EXPECT_NE(why.find("paired with {input} by position"), std::string::npos) << why;
  }
  // txt and pcd outputs are clouds too: x y z label in text, paired the same way.
  const StudyReport text = one_run(dir, "text", test_segmenter("truth"), "txt");
  EXPECT_EQ(text.runs_failed, 0u) << cell(text.table, 0, "failure");
  EXPECT_EQ(number(text.table, 0, "overall_accuracy"), 1.0);
  const StudyReport nan_text = one_run(dir, "nan_text", test_segmenter("nan_point"), "txt");
  EXPECT_EQ(nan_text.runs_failed, 1u);
  EXPECT_NE(cell(nan_text.table, 0, "failure").find("non-finite"), std::string::npos)
      << cell(nan_text.table, 0, "failure");
}

// study.csv and study.md are text: no invalid UTF-8, no control bytes but line ends.
void expect_text(const std::string& path) {
  const std::string bytes = read_bytes(path);
  EXPECT_EQ(valid_utf8(bytes), bytes) << path;
  for (const char c : bytes) {
    const auto byte = static_cast<unsigned char>(c);
    EXPECT_TRUE(byte >= 0x20 || c == '\n') << path << ": control byte " << int(byte);
    if (byte < 0x20 && c != '\n') break;
  }
}

TEST(StudyJob, ASegmenterThatPrintsBinaryBytesLeavesTextFiles) {
  const ScratchDirectory dir;
  const StudyReport report = one_run(dir, "binary", test_segmenter("binary_failure"));
  EXPECT_EQ(report.runs_failed, 1u);
  const std::string why = cell(report.table, 0, "failure");
  EXPECT_NE(why.find("exit status 5"), std::string::npos) << why;
  EXPECT_NE(why.find("model crashed \xEF\xBF\xBD"), std::string::npos) << why;
  expect_text(dir.file("binary/study.csv"));
  expect_text(dir.file("binary/study.md"));
  EXPECT_NE(read_bytes(dir.file("binary/study.md")).find("model crashed"), std::string::npos);
}

TEST(StudyJob, CancellingKeepsEveryFinishedRowAndNoPartialOne) {
  const ScratchDirectory dir;
  const StudyRequest request = office_study(dir.file("study"));
  std::atomic<bool> cancel{false};
  std::vector<std::string> stages;
  Progress progress;
  progress.cancel = &cancel;
  progress.report = [&](const std::string& stage, double) {
    stages.push_back(stage);
    // As a scheduler's SIGTERM would, in the middle of the second run.
    if (stage.find("[run 2/3") == 0 && stage.find("measuring") != std::string::npos) {
      cancel = true;
    }
  };
  EXPECT_THROW(run_study(request, progress), Cancelled);
  const CsvTable kept = read_csv(dir.file("study/study.csv"));
  ASSERT_EQ(kept.rows.size(), 1u);
  EXPECT_EQ(cell(kept, 0, "configuration"), "pattern_7");
  // Progress: runs done of those to make, time spent, and an estimate once a run is done.
  ASSERT_FALSE(stages.empty());
  EXPECT_EQ(stages.front().rfind("[run 1/3, 0:00 elapsed] office_1 pattern_7: ", 0), 0u)
      << stages.front();
  const bool estimated = std::any_of(stages.begin(), stages.end(), [](const std::string& s) {
    return s.rfind("[run 2/3, ", 0) == 0 && s.find(" left] office_1 pattern_4: ") != s.npos;
  });
  EXPECT_TRUE(estimated);

  const StudyReport resumed = run_study(request);
  EXPECT_EQ(resumed.runs_skipped, 1u);
  EXPECT_EQ(resumed.runs_computed, 2u);
}

TEST(StudyJob, ResumingWithOtherParametersIsRefusedNamingThem) {
  const ScratchDirectory dir;
  StudyRequest request = office_study(dir.file("study"));
  const StudyReport first = run_study(request);
  const std::string fingerprint = cell(first.table, 0, "fingerprint");
  EXPECT_EQ(fingerprint.size(), 16u);
  EXPECT_NE(cell(first.table, 1, "fingerprint"), fingerprint);  // other viewpoints

  StudyRequest changed = request;
  changed.tracing.point_radius = 0.05;
  changed.estimation.normal_k = 30;
  try {
    run_study(changed);
    FAIL() << "no error";
  } catch (const UsageError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("3 rows made with other parameters"), std::string::npos) << what;
    EXPECT_NE(what.find("point_radius (was 0.06, now 0.05)"), std::string::npos) << what;
    EXPECT_NE(what.find("normal_k (was 50, now 30)"), std::string::npos) << what;
    EXPECT_EQ(what.find("num_rays_per_vp"), std::string::npos) << what;
    EXPECT_NE(what.find("--fresh"), std::string::npos) << what;
  }
  // A configuration that keeps its name but not its viewpoints is named too.
  StudyRequest moved = request;
  moved.configurations[2].choice = ViewpointChoice::from_pattern(2);
  try {
    run_study(moved);
    FAIL() << "no error";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("configuration 'pattern_1'"), std::string::npos)
        << e.what();
  }
  // Keys declared after studies existed (stations, class mapping) join the fingerprint only once
  // set
  // ("was absent"): at their defaults a study run before them still resumes. (The office
  // has no stations, so the range would be refused at load, after the fingerprints.)
  StudyRequest ranged = request;
  ranged.tracing.min_range = 0.5;
  try {
    run_study(ranged);
    FAIL() << "no error";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("min_range (was absent, now 0.5)"), std::string::npos)
        << e.what();
  }
  StudyRequest named = request;
  named.tracing.class_names_path = dir.file("names.txt");
  try {
    run_study(named);
    FAIL() << "no error";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("class_names (was absent, now"), std::string::npos)
        << e.what();
  }
  // Threads do not change the figures, nor where the openings file is: the same study.
  StudyRequest threads = request;
  threads.tracing.threads = 1;
  fs::copy_file(request.tracing.polygon_path, dir.file("openings_copy.txt"));
  threads.tracing.polygon_path = dir.file("openings_copy.txt");
  EXPECT_EQ(run_study(threads).runs_skipped, 3u);
  // But what it holds does.
  write_text(dir.file("one_opening.txt"), "2 5 0.9\n3.6 5 0.9\n3.6 5 2.2\n2 5 2.2\n");
  threads.tracing.polygon_path = dir.file("one_opening.txt");
  try {
    run_study(threads);
    FAIL() << "no error";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("polygon_file"), std::string::npos) << e.what();
  }

  changed.fresh = true;
  const StudyReport fresh = run_study(changed);
  EXPECT_EQ(fresh.runs_computed, 3u);
  EXPECT_EQ(fresh.runs_skipped, 0u);
  EXPECT_NE(cell(fresh.table, 0, "fingerprint"), fingerprint);
  changed.fresh = false;
  EXPECT_EQ(run_study(changed).runs_skipped, 3u);

  // study.json lists every parameter the rows depend on.
  const std::string json = read_bytes(dir.file("study/study.json"));
  for (const char* key :
       {"\"self_tolerance\"", "\"exterior_classes\"", "\"light_radius\"", "\"normal_k\"",
        "\"ransac_distance\"", "\"mapping_path\"", "\"mean_over\"", "\"ignored_classes\"",
        "\"occlusion_num_vp\"", "\"segmenter_output\"", "\"seed\""}) {
    EXPECT_NE(json.find(key), std::string::npos) << key;
  }
}

TEST(StudyJob, AConstantMeasureHasNoCorrelation) {
  const ScratchDirectory dir;
  StudyRequest request = office_study(dir.file("study"));
  // Three names for the same viewpoints: one measurement, counted once.
  for (auto& configuration : request.configurations) {
    configuration.choice = ViewpointChoice::from_pattern(7);
  }
  const StudyReport report = run_study(request);
  ASSERT_EQ(report.table.rows.size(), 3u);
  for (const auto& m : report.correlations) {
    EXPECT_EQ(m.correlation.n, 1u);
    EXPECT_FALSE(m.correlation.pearson) << m.measure;
  }
  // Three different viewpoint sets whose scans measure the same: the measure
  // is constant, and its correlation undefined, not a number.
  CsvTable table = report.table;
  const std::size_t positions = table.column("viewpoint_positions");
  for (std::size_t r = 0; r < 3; ++r) {
    table.rows[r][positions] = std::to_string(r + 1) + " 1 1";
    table.rows[r][table.column("miou")] = std::to_string(0.2 + 0.1 * static_cast<double>(r));
  }
  write_csv(dir.file("constant.csv"), table);
  const StudyReport merged = run_study_merge({dir.file("constant.csv")}, dir.file("merged"));
  for (const auto& m : merged.correlations) {
    EXPECT_EQ(m.correlation.n, 3u);
    EXPECT_FALSE(m.correlation.pearson) << m.measure;
    EXPECT_FALSE(m.correlation.spearman) << m.measure;
    EXPECT_FALSE(m.correlation.fit) << m.measure;
    EXPECT_FALSE(m.association.within_scene_slope.value) << m.measure;
  }
  const bool warned = std::any_of(merged.warnings.begin(), merged.warnings.end(), [](auto& w) {
    return w.find("visible_fraction is the same") != std::string::npos &&
           w.find("undefined") != std::string::npos;
  });
  EXPECT_TRUE(warned);
  EXPECT_NE(read_bytes(dir.file("merged/study.json")).find("\"pearson\" : null"),
            std::string::npos);
}

TEST(StudyJob, MeanOverChoosesTheClassesMiouAverages) {
  const ScratchDirectory dir;
  StudyRequest request = office_study(dir.file("study"));
  request.configurations.resize(1);
  request.segmenter = kAllWall;
  request.mean_over = MeanOver::pointcept;
  const StudyReport report = run_study(request);
  const CsvTable& table = report.table;
  EXPECT_EQ(cell(table, 0, "mean_over"), "pointcept");
  // Pointcept: every evaluation class, an empty IoU counting 0.
  double sum = 0.0;
  std::size_t classes = 0;
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    if (table.columns[c].rfind("iou_", 0) != 0) continue;
    ++classes;
    if (!table.rows[0][c].empty()) sum += std::stod(table.rows[0][c]);
  }
  EXPECT_EQ(classes, 12u);
  EXPECT_NEAR(number(table, 0, "miou"), sum / 12.0, 1e-9);
  // All wall: only wall has an IoU above 0, so the rules differ by their class counts.
  request.out = dir.file("support");
  request.mean_over = MeanOver::support;
  const CsvTable support = run_study(request).table;
  EXPECT_GT(number(support, 0, "miou"), number(table, 0, "miou"));
}

TEST(StudyJob, BadOptionsAreUsageErrors) {
  const ScratchDirectory dir;
  EXPECT_EQ(parse_shard("3/10").index, 3u);
  EXPECT_EQ(parse_shard("3/10").count, 10u);
  for (const char* bad : {"", "3", "10/10", "1/0", "-1/2", "a/b", "1/2/3"}) {
    EXPECT_THROW(parse_shard(bad), UsageError) << bad;
  }
  const auto fails = [&](const std::function<void(StudyRequest&)>& change) {
    StudyRequest request = office_study(dir.file("study"));
    change(request);
    EXPECT_THROW(validate(request), UsageError);
  };
  fails([](StudyRequest& r) { r.segmenter = "python infer.py {input}"; });
  fails([](StudyRequest& r) { r.segmenter_output = "exe"; });
  fails([](StudyRequest& r) { r.configurations[1].name = "pattern_7"; });
  fails([](StudyRequest& r) { r.configurations[0].choice = ViewpointChoice::from_pattern(9); });
  fails([](StudyRequest& r) { r.out.clear(); });
  fails([](StudyRequest& r) { r.scenes.clear(); });
  fails([](StudyRequest& r) { r.scenes.push_back(r.scenes[0]); });
  fails([](StudyRequest& r) { r.tracing.point_radius = 0.0; });
  fails([](StudyRequest& r) { r.shard = "2/2"; });
  fails([](StudyRequest& r) { r.segmenter_timeout = -1.0; });
  StudyRequest good = office_study(dir.file("study"));
  EXPECT_NO_THROW(validate(good));
}

TEST(StudyJob, ConfigurationsComeFromTheConfig) {
  const ScratchDirectory dir;
  const StudyRequest request = office_study(dir.file("study"));
  ASSERT_EQ(request.configurations.size(), 3u);
  EXPECT_EQ(request.configurations[1].name, "pattern_4");
  EXPECT_EQ(request.configurations[1].choice.pattern, 4);
  EXPECT_DOUBLE_EQ(request.tracing.point_radius, 0.06);
  EXPECT_TRUE(request.tracing.exterior);
  // Relative to the config file's folder, as every path of a config.
  EXPECT_EQ(request.scenes[0].path, kSource + "/files/s3dis_synthetic/Area_1/office_1");

  write_text(dir.file("c.json"), R"({"occlusion": {"study": {"configurations": [
      {"name": "grid", "num_vp": 4},
      {"name": "two", "viewpoints": [[1, 1, 1], [2, 2, 2]]}]}}})");
  StudyRequest other;
  apply_config(load_config(dir.file("c.json")), "study", study_keys(), other);
  ASSERT_EQ(other.configurations.size(), 2u);
  EXPECT_EQ(other.configurations[0].choice.kind, ViewpointChoice::Kind::kGrid);
  EXPECT_EQ(other.configurations[1].choice.points.size(), 2u);

  write_text(dir.file("bad.json"), R"({"occlusion": {"study": {"configurations": [
      {"name": "x", "pattern": 1, "num_vp": 2}]}}})");
  try {
    load_config(dir.file("bad.json"));
    FAIL() << "no error";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("configurations[0]"), std::string::npos) << e.what();
  }
  write_text(dir.file("typo.json"), R"({"occlusion": {"study": {"configurations": [
      {"name": "x", "patern": 1}]}}})");
  EXPECT_THROW(load_config(dir.file("typo.json")), UsageError);
}

}  // namespace
}  // namespace occlusion

namespace occlusion {
namespace {

// "x y z;x y z;..." of the table's viewpoint_positions column.
std::vector<Eigen::Vector3d> row_viewpoints(const CsvTable& table, std::size_t row) {
  std::vector<Eigen::Vector3d> points;
  std::istringstream text(table.rows.at(row).at(table.column("viewpoint_positions")));
  std::string item;
  while (std::getline(text, item, ';')) {
    std::istringstream coordinates(item);
    Eigen::Vector3d p;
    coordinates >> p.x() >> p.y() >> p.z();
    points.push_back(p);
  }
  return points;
}

TEST(StudyJob, UpPlacesAGridConfigurationAtMidHeightAlongThatAxis) {
  // A grid stands at mid-height over the floor plan: under +z its points share
  // z and spread in x and y; under +x they share x and spread in y and z.
  const ScratchDirectory dir;
  for (const std::string up : {"+z", "+x"}) {
    SCOPED_TRACE(up);
    StudyRequest request = office_study(dir.file("study" + up));
    request.configurations = {{"grid_4", ViewpointChoice::from_grid(4)}};
    request.tracing.up = up;
    request.tracing.exterior = false;
    const StudyReport report = run_study(request);
    const std::vector<Eigen::Vector3d> points = row_viewpoints(report.table, 0);
    ASSERT_EQ(points.size(), 4u);
    const int height = up == "+z" ? 2 : 0;
    for (int axis = 0; axis < 3; ++axis) {
      double lo = points[0][axis], hi = points[0][axis];
      for (const auto& p : points) {
        lo = std::min(lo, p[axis]);
        hi = std::max(hi, p[axis]);
      }
      if (axis == height) {
        EXPECT_NEAR(hi - lo, 0.0, 1e-4) << "axis " << axis;
      } else {
        EXPECT_GT(hi - lo, 0.5) << "axis " << axis;
      }
    }
  }
  // A study run under one up does not resume under another.
  StudyRequest other = office_study(dir.file("study+z"));
  other.configurations = {{"grid_4", ViewpointChoice::from_grid(4)}};
  other.tracing.up = "+y";
  other.tracing.exterior = false;
  EXPECT_THROW(run_study(other), UsageError);
}

}  // namespace
}  // namespace occlusion

namespace occlusion {
namespace {

// Rows of a study of 8 scenes x 3 configurations whose mIoU falls by
// `slope` per unit of occlusion level inside each scene, around a level of
// its own per scene that rises with the scene's occlusion (so the pooled
// runs alone would mislead).
CsvTable planted_study(const CsvTable& like, double slope) {
  CsvTable table;
  table.columns = like.columns;
  Rng random(5);
  for (int scene = 0; scene < 8; ++scene) {
    for (int configuration = 0; configuration < 3; ++configuration) {
      std::vector<std::string> row = like.rows.at(0);
      const double occlusion = 0.1 * scene + 0.05 * configuration + 0.01 * random.uniform();
      const double miou = 0.2 + 0.08 * scene + slope * occlusion + 0.002 * random.uniform();
      row[table.column("run")] = std::to_string(scene * 3 + configuration);
      row[table.column("scene")] = "room_" + std::to_string(scene);
      row[table.column("configuration")] = "c" + std::to_string(configuration);
      row[table.column("occlusion_level")] = std::to_string(occlusion);
      row[table.column("miou")] = std::to_string(miou);
      row[table.column("viewpoint_positions")] = std::to_string(configuration) + " 2 1.5";
      table.rows.push_back(row);
    }
  }
  return table;
}

TEST(StudyJob, StudyMdOpensWithTheAnswerAndItsUncertainty) {
  const ScratchDirectory dir;
  const StudyReport real = run_study(office_study(dir.file("real")));
  // One scene: a slope, but no interval, and the answer says so.
  const std::string one_scene = read_bytes(dir.file("real/study.md"));
  EXPECT_NE(one_scene.find("# Occlusion study\n\n**Answer (descriptive only):**"),
            std::string::npos)
      << one_scene.substr(0, 400);
  EXPECT_NE(one_scene.find("1 scene is too few for an interval"), std::string::npos);

  for (const double slope : {-0.5, 0.0}) {
    SCOPED_TRACE(slope);
    const std::string name = slope < 0 ? "effect" : "none";
    write_csv(dir.file(name + ".csv"), planted_study(real.table, slope));
    const StudyReport merged = run_study_merge({dir.file(name + ".csv")}, dir.file(name));
    const MeasureCorrelation& occlusion = merged.correlations.at(0);
    ASSERT_EQ(occlusion.measure, "occlusion_level");
    EXPECT_EQ(occlusion.association.runs, 24u);
    EXPECT_EQ(occlusion.association.scenes, 8u);
    const ClusteredEstimate& within = occlusion.association.within_scene_slope;
    ASSERT_TRUE(within.value && within.interval95);
    EXPECT_NEAR(*within.value, slope, 0.05);
    EXPECT_LT(within.interval95->lo, slope);
    EXPECT_GT(within.interval95->hi, slope);
    const std::string markdown = read_bytes(dir.file(name + "/study.md"));
    const Json::Value json = read_json_file(dir.file(name + "/study.json"), "study report");
    const Json::Value& inference = json["correlations"][0]["inference"]["within_scene_slope"];
    EXPECT_EQ(inference["interval95"].size(), 2u);
    EXPECT_EQ(json["correlations"][0]["scenes"].asUInt(), 8u);
    if (slope < 0) {
      // The pooled runs rise with occlusion (the scenes' own levels); the
      // answer is the within-scene fall.
      EXPECT_GT(*occlusion.correlation.pearson, 0.0);
      EXPECT_LT(within.interval95->hi, 0.0);
      EXPECT_NE(markdown.find("**Answer:** more occlusion, lower mIoU: within a scene"),
                std::string::npos)
          << markdown.substr(0, 400);
    } else {
      EXPECT_LT(within.interval95->lo, 0.0);
      EXPECT_NE(markdown.find("**Answer:** no effect of occlusion_level on mIoU can be told from "
                              "noise"),
                std::string::npos)
          << markdown.substr(0, 400);
    }
    EXPECT_NE(markdown.find("24 runs in 8 scenes"), std::string::npos);
  }
}

TEST(StudyJob, AnAnswerThatCannotBeGivenSaysWhichSideDidNotVary) {
  const ScratchDirectory dir;
  const StudyReport real = run_study(office_study(dir.file("real")));
  // A segmenter that scores the same whatever the scan (an untrained model:
  // mIoU 0 everywhere), while the occlusion level varies in every scene.
  CsvTable flat_miou = planted_study(real.table, -0.5);
  for (auto& row : flat_miou.rows) row[flat_miou.column("miou")] = "0";
  // Configurations that all see a scene alike, while mIoU varies.
  CsvTable flat_measure = planted_study(real.table, -0.5);
  for (auto& row : flat_measure.rows) {
    const std::string scene = row[flat_measure.column("scene")];
    row[flat_measure.column("occlusion_level")] = "0." + scene.substr(scene.size() - 1);
  }
  const struct {
    const char* name;
    const CsvTable* table;
    const char* answer;
  } cases[] = {
      {"flat_miou", &flat_miou,
       "**Answer:** this study cannot say: mIoU is the same (0) in every run, so there is "
       "nothing to relate to occlusion_level (24 runs in 8 scenes)."},
      {"flat_measure", &flat_measure,
       "**Answer:** this study cannot say: no scene was scanned from configurations whose "
       "occlusion_level differs"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    write_csv(dir.file(std::string(c.name) + ".csv"), *c.table);
    run_study_merge({dir.file(std::string(c.name) + ".csv")}, dir.file(c.name));
    const std::string markdown = read_bytes(dir.file(std::string(c.name) + "/study.md"));
    EXPECT_EQ(markdown.find(std::string("# Occlusion study\n\n") + c.answer), 0u)
        << markdown.substr(0, 400);
  }
}

}  // namespace
}  // namespace occlusion

namespace occlusion {
namespace {

TEST(StudyJob, ConfigurationsWithTheSameViewpointsCountOnce) {
  const ScratchDirectory dir;
  StudyRequest request = office_study(dir.file("study"));
  request.tracing.exterior = false;
  request.configurations = {
      {"pair", ViewpointChoice::from_points({{1.0, 1.0, 1.2}, {4.5, 3.5, 1.2}})},
      {"centre", ViewpointChoice::from_pattern(1)},
      {"pair_reversed", ViewpointChoice::from_points({{4.5, 3.5, 1.2}, {1.0, 1.0, 1.2}})},
      {"corner", ViewpointChoice::from_points({{0.8, 4.0, 2.0}})}};
  const StudyReport report = run_study(request);
  EXPECT_EQ(report.table.rows.size(), 4u);  // every run stays in the table
  const std::string warning =
      "office_1: configuration 'pair_reversed' places the same viewpoints as 'pair'";
  EXPECT_EQ(std::count_if(report.warnings.begin(), report.warnings.end(),
                          [&](const std::string& w) { return w.rfind(warning, 0) == 0; }),
            1);
  for (const auto& m : report.correlations) {
    EXPECT_EQ(m.correlation.n, 3u) << m.measure;
    EXPECT_EQ(m.association.runs, 3u) << m.measure;
  }
}

}  // namespace
}  // namespace occlusion

namespace occlusion {
namespace {

TEST(StudyJob, FullScoringCountsThePointsTheScanMissedAsMisses) {
  // Everything called wall. Over the scan's points accuracy is the walls it
  // kept over the points it kept; over the full scene, the walls it kept over
  // every point of the scene: the two differ by scanned_points / points.
  const ScratchDirectory dir;
  double accuracy[2] = {0, 0};
  const char* scorings[2] = {"scanned", "full"};
  CsvTable table;
  for (int k = 0; k < 2; ++k) {
    StudyRequest request = office_study(dir.file(std::string("study_") + scorings[k]));
    request.configurations = {{"centre", ViewpointChoice::from_pattern(1)}};
    request.tracing.exterior = false;
    request.segmenter = kAllWall;
    request.scoring = scorings[k];
    table = run_study(request).table;
    accuracy[k] = number(table, 0, "overall_accuracy");
  }
  const double kept = number(table, 0, "scanned_points") / number(table, 0, "points");
  ASSERT_LT(kept, 0.95);  // the centre alone misses points, or the test says nothing
  EXPECT_NEAR(accuracy[1], accuracy[0] * kept, 1e-9);
  // The walls' IoU: tp over the walls' points plus the others called wall.
  const PointCloud scene = read_cloud(kSource + "/files/s3dis_synthetic/Area_1/office_1");
  const PointCloud scanned = read_cloud(dir.file("study_full/runs/office_1__centre.scan.ply"));
  const auto walls = [](const PointCloud& cloud) {
    double n = 0;
    for (const auto label : cloud.labels) n += cloud.class_names[label] == "wall" ? 1 : 0;
    return n;
  };
  const double iou_full =
      walls(scanned) / (walls(scene) + (static_cast<double>(scanned.size()) - walls(scanned)));
  EXPECT_NEAR(number(table, 0, "iou_wall"), iou_full, 1e-9);
}

}  // namespace
}  // namespace occlusion
