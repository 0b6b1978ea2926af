#include "occlusion/app/study_job.hpp"
#include "occlusion/app/config.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>

#include "io/scratch_directory.hpp"
#include "occlusion/app/errors.hpp"
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
  // POSIX sh: as many labels as the scanned PLY has points, all wall (id 0).
  request.segmenter =
      "n=$(head -c 2000 {input} | sed -n 's/^element vertex //p'); "
      "awk -v n=\"$n\" 'BEGIN { for (i = 0; i < n; i++) print 0 }' > {output}";
  const StudyReport report = run_study(request);
  const CsvTable& table = report.table;
  ASSERT_EQ(table.rows.size(), 1u);
  EXPECT_EQ(table.rows[0][table.column("segmenter")], request.segmenter);
  const std::string prediction = dir.file("study/runs/office_1__pattern_7.prediction.labels");
  const auto labels = read_label_file(prediction);
  EXPECT_EQ(static_cast<double>(labels.size()), number(table, 0, "scanned_points"));

  // Everything called wall: accuracy is the walls' share of the scanned points.
  const PointCloud scanned = read_cloud(dir.file("study/runs/office_1__pattern_7.scan.ply"));
  std::size_t walls = 0;
  for (const auto label : scanned.labels) walls += scanned.class_names[label] == "wall" ? 1 : 0;
  EXPECT_NEAR(number(table, 0, "overall_accuracy"),
              static_cast<double>(walls) / static_cast<double>(scanned.size()), 1e-9);
  EXPECT_NEAR(number(table, 0, "iou_wall"), number(table, 0, "overall_accuracy"), 1e-9);
  EXPECT_EQ(number(table, 0, "iou_floor+ceiling"), 0.0);
}

TEST(StudyJob, AFailingSegmenterStopsTheStudyWithoutARow) {
  const ScratchDirectory dir;
  StudyRequest request = office_study(dir.file("study"));
  request.configurations.resize(1);
  request.segmenter = "echo on stdout; exit 3 # {input} {output}";
  try {
    run_study(request);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("exit status 3"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir.file("study/study.csv")));
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
  EXPECT_EQ(request.scenes[0], kSource + "/files/s3dis_synthetic/Area_1/office_1");

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
