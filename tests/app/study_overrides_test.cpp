// A scene of the study with settings of its own (docs/study.md, "Scenes with
// settings of their own"): what it changes, what it refuses, and how it resumes.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "io/scratch_directory.hpp"
#include "occlusion/app/config.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/job_registry.hpp"
#include "occlusion/app/key_sources.hpp"
#include "occlusion/app/study_job.hpp"
#include "occlusion/io/cloud_io.hpp"

namespace occlusion {
namespace {

namespace fs = std::filesystem;
using testing::read_bytes;
using testing::ScratchDirectory;
using testing::write_text;

const std::string kSource = OCCLUSION_SOURCE_DIR;
const std::string kOffice = kSource + "/files/s3dis_synthetic/Area_1/office_1";
const std::string kBefore = kSource + "/tests/support/study_before_overrides";

// Every other point of the office (light enough for the sanitized suite) as
// a labelled PLY with z up, and the same room turned so that y is up:
// (x, y, z) -> (x, z, -y), a rotation, so what a viewpoint sees of it is the
// same once the viewpoint is turned with it.
void write_rooms(const std::string& z_up, const std::string& y_up) {
  const PointCloud office = read_cloud(kOffice);
  ASSERT_FALSE(office.shifted());
  std::vector<bool> keep(office.size());
  for (std::size_t i = 0; i < keep.size(); i += 2) keep[i] = true;
  PointCloud room = office.subset(keep);
  write_cloud(z_up, room);
  for (auto& p : room.positions) p = Eigen::Vector3f(p.x(), p.z(), -p.y());
  write_cloud(y_up, room);
}

// Both rooms from a 2 x 2 grid at mid-height, few rays: about a second a run.
StudyRequest room_study(const std::string& z_up, const std::string& y_up, const std::string& out) {
  StudyRequest request;
  request.scenes = {z_up, y_up};
  request.configurations = {{"grid_4", ViewpointChoice::from_grid(4)}};
  request.tracing.point_radius = 0.06;
  request.tracing.num_rays_per_vp = 400;
  request.tracing.exterior = false;
  request.out = out;
  return request;
}

std::string cell(const CsvTable& table, std::size_t row, const std::string& column) {
  return table.rows.at(row).at(table.column(column));
}

double number(const CsvTable& table, std::size_t row, const std::string& column) {
  return std::stod(cell(table, row, column));
}

// A row without its timings, which differ from one computation to the next.
std::vector<std::string> figures(const CsvTable& table, std::size_t row) {
  std::vector<std::string> cells = table.rows.at(row);
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    if (table.columns[c].find("_seconds") != std::string::npos) cells[c].clear();
  }
  return cells;
}

// "x y z;x y z;..." of the table's viewpoint_positions column.
std::vector<Eigen::Vector3d> row_viewpoints(const CsvTable& table, std::size_t row) {
  std::vector<Eigen::Vector3d> points;
  std::istringstream text(cell(table, row, "viewpoint_positions"));
  std::string item;
  while (std::getline(text, item, ';')) {
    std::istringstream coordinates(item);
    Eigen::Vector3d p;
    coordinates >> p.x() >> p.y() >> p.z();
    points.push_back(p);
  }
  return points;
}

bool any_contains(const std::vector<std::string>& texts, const std::string& part) {
  return std::any_of(texts.begin(), texts.end(),
                     [&](const std::string& t) { return t.find(part) != std::string::npos; });
}

std::string usage_error(const std::function<void()>& call) {
  try {
    call();
  } catch (const UsageError& e) {
    return e.what();
  }
  return "(nothing thrown)";
}

TEST(StudyOverrides, AnUpOverrideMakesAYUpCopySeeWhatTheZUpRoomSees) {
  const ScratchDirectory dir;
  write_rooms(dir.file("room_z.ply"), dir.file("room_y.ply"));

  // The study's up (+z) for both: the y-up copy's grid stands at mid-depth,
  // and sees another share of the room.
  const StudyRequest plain =
      room_study(dir.file("room_z.ply"), dir.file("room_y.ply"), dir.file("plain"));
  const CsvTable without = run_study(plain).table;
  ASSERT_EQ(without.rows.size(), 2u);
  const double z_seen = number(without, 0, "visible_fraction");
  // (measured: 0.9774 against the original's 0.9820; its grid stands at two
  // heights, y 0.90 and 2.10)
  EXPECT_GT(std::abs(number(without, 1, "visible_fraction") - z_seen), 0.004);
  const auto heights = row_viewpoints(without, 1);
  ASSERT_EQ(heights.size(), 4u);
  EXPECT_GT(std::abs(heights[0].y() - heights[2].y()), 0.5);

  // The copy's own up: it sees what the original sees, from the original's
  // viewpoints turned with the room (the table is in each file's frame).
  StudyRequest turned = plain;
  turned.out = dir.file("turned");
  turned.scenes[1].overrides["up"] = "+y";
  const StudyReport report = run_study(turned);
  const CsvTable& with = report.table;
  ASSERT_EQ(with.rows.size(), 2u);
  EXPECT_NEAR(number(with, 1, "visible_fraction"), z_seen, 1e-4);
  EXPECT_NEAR(number(with, 1, "scanned_points"), number(with, 0, "scanned_points"), 3.0);
  const auto original = row_viewpoints(with, 0), copy = row_viewpoints(with, 1);
  ASSERT_EQ(original.size(), 4u);
  ASSERT_EQ(copy.size(), 4u);
  for (const auto& p : original) {
    const Eigen::Vector3d expected(p.x(), p.z(), -p.y());
    const bool found = std::any_of(copy.begin(), copy.end(),
                                   [&](const auto& q) { return (q - expected).norm() < 1e-3; });
    EXPECT_TRUE(found) << "no viewpoint of room_y at " << expected.transpose();
  }
  // The other scene is untouched: the same figures and fingerprint.
  EXPECT_EQ(figures(with, 0), figures(without, 0));
  EXPECT_NE(cell(with, 1, "fingerprint"), cell(without, 1, "fingerprint"));

  // study.json and study.md say which scene had settings of its own.
  const Json::Value json = to_json(report);
  EXPECT_EQ(json["parameters"]["scene_overrides"]["room_y"]["up"].asString(), "+y");
  EXPECT_FALSE(json["parameters"]["scene_overrides"].isMember("room_z"));
  EXPECT_EQ(json["parameters"]["scenes"][1]["up"].asString(), "+y");
  const std::string markdown = read_bytes(dir.file("turned/study.md"));
  EXPECT_NE(markdown.find("| room_y | up +y |"), std::string::npos) << markdown;
  // room_z appears first in the table of runs, not in that of scenes' own settings.
  EXPECT_EQ(markdown.find("| room_z | "), markdown.find("| room_z | grid_4"));
}

TEST(StudyOverrides, ChangingAnOverrideMakesThatScenesRowsAgainOnly) {
  const ScratchDirectory dir;
  write_rooms(dir.file("room_z.ply"), dir.file("room_y.ply"));
  StudyRequest request =
      room_study(dir.file("room_z.ply"), dir.file("room_y.ply"), dir.file("study"));
  request.scenes[1].overrides["up"] = "+y";
  const CsvTable first = run_study(request).table;

  // The same overrides: nothing to make.
  EXPECT_EQ(run_study(request).runs_skipped, 2u);

  // Another radius for room_y: its row is made again, room_z's kept.
  request.scenes[1].overrides["point_radius"] = 0.05;
  const StudyReport again = run_study(request);
  EXPECT_EQ(again.runs_computed, 1u);
  EXPECT_EQ(again.runs_skipped, 1u);
  EXPECT_TRUE(any_contains(again.warnings,
                           "room_y: its own settings changed (point_radius (was "
                           "absent, now 0.05)), so its 1 rows"))
      << ::testing::PrintToString(again.warnings);
  EXPECT_EQ(figures(again.table, 0), figures(first, 0));
  EXPECT_NE(cell(again.table, 1, "fingerprint"), cell(first, 1, "fingerprint"));

  // A study-wide change is still refused: room_z's row was made with 0.06.
  // room_y's own 0.05 hides the change from its row, which is not named.
  StudyRequest wide = request;
  wide.tracing.point_radius = 0.05;
  const std::string refused = usage_error([&] { run_study(wide); });
  EXPECT_NE(refused.find("1 rows made with other parameters"), std::string::npos) << refused;
  EXPECT_NE(refused.find("point_radius (was 0.06, now 0.05)"), std::string::npos) << refused;

  // An override equal to the study's value changes no figure, nor the fingerprint.
  StudyRequest same = request;
  same.scenes[0].overrides["point_radius"] = 0.06;
  const StudyReport kept = run_study(same);
  EXPECT_EQ(kept.runs_skipped, 2u);
}

TEST(StudyOverrides, ShardsWhoseScenesHaveOtherSettingsDoNotMerge) {
  const ScratchDirectory dir;
  write_rooms(dir.file("room_z.ply"), dir.file("room_y.ply"));
  StudyRequest first = room_study(dir.file("room_z.ply"), dir.file("room_y.ply"), dir.file("s0"));
  first.scenes[1].overrides["up"] = "+y";
  first.shard = "0/2";
  StudyRequest second = first;
  second.out = dir.file("s1");
  second.shard = "1/2";
  second.scenes[1].overrides["up"] = "-z";
  run_study(first);
  run_study(second);
  const std::string why = usage_error([&] {
    run_study_merge({dir.file("s0/study.csv"), dir.file("s1/study.csv")}, dir.file("merged"));
  });
  EXPECT_NE(why.find("scene_overrides"), std::string::npos) << why;
  EXPECT_NE(why.find("only shards of one study merge"), std::string::npos) << why;
}

TEST(StudyOverrides, AStudyWrittenBeforeOverridesResumes) {
  const ScratchDirectory dir;
  write_cloud(dir.file("office_copy.ply"), read_cloud(kOffice));
  fs::create_directories(dir.file("study"));
  for (const char* name : {"study.csv", "study.parameters.json"})
    fs::copy_file(kBefore + "/" + name, dir.file(std::string("study/") + name));
  StudyRequest request;
  apply_config(load_config(kBefore + "/study.json"), "study", study_keys(), request);
  request.scenes.push_back(dir.file("office_copy.ply"));
  request.out = dir.file("study");

  // Its fingerprints are those that version wrote: both rows are kept.
  const StudyReport resumed = run_study(request);
  EXPECT_EQ(resumed.runs_skipped, 2u);
  EXPECT_EQ(resumed.runs_computed, 0u);
  const CsvTable before = read_csv(kBefore + "/study.csv");

  // A scene's own radius makes that scene's row again, and keeps the other.
  request.scenes[1].overrides["point_radius"] = 0.05;
  const StudyReport changed = run_study(request);
  EXPECT_EQ(changed.runs_computed, 1u);
  EXPECT_EQ(changed.runs_skipped, 1u);
  EXPECT_TRUE(any_contains(changed.warnings, "office_copy: its own settings changed"));
  EXPECT_EQ(changed.table.rows[0], before.rows[0]);
  EXPECT_NE(cell(changed.table, 1, "fingerprint"), cell(before, 1, "fingerprint"));
  EXPECT_EQ(cell(changed.table, 1, "scene"), "office_copy");
}

TEST(StudyOverrides, BadEntriesAreRefusedNamingTheSceneAndTheKey) {
  const ScratchDirectory dir;
  const auto config_error = [&](const std::string& scenes) {
    write_text(dir.file("c.json"), R"({"occlusion": {"study": {"scenes": )" + scenes + "}}}");
    return usage_error([&] { load_config(dir.file("c.json")); });
  };
  std::string why = config_error(R"(["a.ply", {"path": "b.ply", "radius": 0.05}])");
  EXPECT_NE(why.find("'occlusion.study.scenes'"), std::string::npos) << why;
  EXPECT_NE(why.find("scenes[1] (b.ply) has an unknown key 'radius'"), std::string::npos) << why;
  EXPECT_NE(why.find("point_radius"), std::string::npos) << why;  // what it may set
  why = config_error(R"([{"path": "c.ply", "up": "upwards"}])");
  EXPECT_NE(why.find("scenes[0] (c.ply): 'up' must be one of +x"), std::string::npos) << why;
  why = config_error(R"([{"path": "d.ply", "point_radius": -1}])");
  EXPECT_NE(why.find("(d.ply): 'point_radius' must be a number in (0"), std::string::npos) << why;
  why = config_error(R"([{"up": "+y"}])");
  EXPECT_NE(why.find("scenes[0] needs a \"path\""), std::string::npos) << why;
  why = config_error(R"([{"path": "e.ply", "num_rays_per_vp": 10}])");  // study-wide only
  EXPECT_NE(why.find("unknown key 'num_rays_per_vp'"), std::string::npos) << why;

  // A C++ caller's request is checked as a config is, naming the scene.
  StudyRequest request = room_study(kOffice, dir.file("room.ply"), dir.file("out"));
  request.scenes[1].overrides["frame"] = "tight";
  why = usage_error([&] { validate(request); });
  EXPECT_NE(why.find("room.ply"), std::string::npos) << why;
  EXPECT_NE(why.find("'frame' must be one of robust, bbox"), std::string::npos) << why;
  request.scenes[1].overrides = Json::Value(Json::objectValue);
  request.scenes[1].overrides["self_tolerance"] = 2e6;
  why = usage_error([&] { validate(request); });
  EXPECT_NE(why.find("room.ply"), std::string::npos) << why;
  EXPECT_NE(why.find("self_tolerance"), std::string::npos) << why;

  // A scene's openings file that cannot be read stops the study before its
  // first run, naming the file.
  request.scenes[1].overrides = Json::Value(Json::objectValue);
  request.scenes[1].overrides["polygon_path"] = dir.file("missing_openings.txt");
  try {
    run_study(request);
    FAIL() << "no error";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("missing_openings.txt"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir.file("out/study.csv")));
}

TEST(StudyOverrides, EntriesComeFromAConfigAndTheCommandLine) {
  const ScratchDirectory dir;
  // Relative paths, the openings' included, are the config folder's.
  fs::create_directories(dir.file("data"));
  write_text(dir.file("data/study.json"), R"({"occlusion": {"study": {"scenes": [
      "rooms/a.ply", {"path": "rooms/b.ply", "polygon_path": "b_openings.txt", "up": "+y",
                      "point_radius": "auto"}]}}})");
  StudyRequest request;
  apply_config(load_config(dir.file("data/study.json")), "study", study_keys(), request);
  ASSERT_EQ(request.scenes.size(), 2u);
  const fs::path data = fs::path(dir.file("data"));
  EXPECT_EQ(fs::path(request.scenes[0].path), data / "rooms/a.ply");
  EXPECT_TRUE(request.scenes[0].overrides.empty());
  EXPECT_EQ(fs::path(request.scenes[1].path), data / "rooms/b.ply");
  EXPECT_EQ(fs::path(request.scenes[1].overrides["polygon_path"].asString()),
            data / "b_openings.txt");
  // The scene's own request: its keys set, the others the study's.
  const StudyRequest b = scene_request(request, request.scenes[1]);
  EXPECT_EQ(b.tracing.up, "+y");
  EXPECT_TRUE(is_auto_radius(b.tracing.point_radius));
  EXPECT_EQ(fs::path(b.tracing.polygon_path), data / "b_openings.txt");
  EXPECT_EQ(b.tracing.num_rays_per_vp, request.tracing.num_rays_per_vp);
  EXPECT_EQ(scene_request(request, request.scenes[0]).tracing.up, "+z");

  // On the command line a scene with settings of its own is its JSON text.
  const JobInfo& study = *find_job("study");
  const KeySource cli = source_from_arguments(
      {"--scene", "a.ply", "--scene", R"({"path": "b.ply", "up": "+y"})", "--out", "o"}, study.keys,
      "study", study.positional);
  StudyRequest from_cli;
  apply_sources(study_keys(), {cli}, from_cli);
  ASSERT_EQ(from_cli.scenes.size(), 2u);
  EXPECT_EQ(from_cli.scenes[0].path, "a.ply");
  EXPECT_EQ(from_cli.scenes[1].path, "b.ply");
  EXPECT_EQ(from_cli.scenes[1].overrides["up"].asString(), "+y");
  const std::string why = usage_error([&] {
    source_from_arguments({"--scene", R"({"path": "b.ply", "upp": "+y"})"}, study.keys, "study",
                          study.positional);
  });
  EXPECT_NE(why.find("--scene"), std::string::npos) << why;
  EXPECT_NE(why.find("(b.ply) has an unknown key 'upp'"), std::string::npos) << why;
}

}  // namespace
}  // namespace occlusion
