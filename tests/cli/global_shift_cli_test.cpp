// A scene far from the origin (UTM coordinates) gives exactly the results it
// gives at the origin, job by job, and what the jobs write comes back in the
// scene's own coordinates: the readers' global shift (docs/formats.md).

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <sstream>

#include "occlusion/io/cloud_io.hpp"
#include "run_cli.hpp"

namespace occlusion {
namespace {

using testing::run_cli;
using testing::run_json;
using testing::TempDir;

// (500000, 5400000, 100): a UTM easting and northing, and a height.
const Eigen::Vector3d kUtm(500000.0, 5400000.0, 100.0);

// Coordinates on a 1/16 grid: exact in float and in decimal, so the shifted
// scene's local coordinates are exactly those of the scene at the origin.
std::string xyz(double x, double y, double z, const Eigen::Vector3d& at) {
  char text[96];
  std::snprintf(text, sizeof text, "%.4f %.4f %.4f", x + at.x(), y + at.y(), z + at.z());
  return text;
}

// A 4 x 3 x 2.5 room (an S3DIS room folder: floor, ceiling, walls) with a
// table inside and a hole in one wall, points every 1/16, with its origin at `at`.
std::string write_room(const TempDir& dir, const std::string& name, const Eigen::Vector3d& at) {
  const std::string room = dir.file(name);
  std::filesystem::create_directories(room + "/Annotations");
  const double step = 1.0 / 16.0;
  std::ostringstream floor, ceiling, wall, table;
  for (int i = 0; i <= 64; ++i) {
    for (int j = 0; j <= 48; ++j) {
      floor << xyz(i * step, j * step, 0.0, at) << " 120 120 120\n";
      ceiling << xyz(i * step, j * step, 2.5, at) << " 200 200 200\n";
    }
  }
  for (int k = 1; k < 40; ++k) {
    for (int i = 0; i <= 64; ++i) {
      wall << xyz(i * step, 0.0, k * step, at) << " 90 90 90\n";
      wall << xyz(i * step, 3.0, k * step, at) << " 90 90 90\n";
    }
    for (int j = 1; j < 48; ++j) {
      wall << xyz(0.0, j * step, k * step, at) << " 90 90 90\n";
      // A hole in the wall x = 4 that no opening covers: rays escape there.
      const bool hole = j > 16 && j < 32 && k > 8 && k < 24;
      if (!hole) wall << xyz(4.0, j * step, k * step, at) << " 90 90 90\n";
    }
  }
  for (int i = 0; i <= 16; ++i) {
    for (int j = 0; j <= 16; ++j) {
      table << xyz(1.5 + i * step, 1.0 + j * step, 0.75, at) << " 150 80 40\n";
    }
  }
  dir.write(name + "/Annotations/floor_1.txt", floor.str());
  dir.write(name + "/Annotations/ceiling_1.txt", ceiling.str());
  dir.write(name + "/Annotations/wall_1.txt", wall.str());
  dir.write(name + "/Annotations/table_1.txt", table.str());
  return "'" + room + "'";
}

// A window just in front of the wall y = 3, in the frame at `at`.
std::string write_window(const TempDir& dir, const std::string& name, const Eigen::Vector3d& at) {
  dir.write(name, xyz(1.0, 2.875, 1.0, at) + "\n" + xyz(2.5, 2.875, 1.0, at) + "\n" +
                      xyz(2.5, 2.875, 2.0, at) + "\n" + xyz(1.0, 2.875, 2.0, at) + "\n");
  return "'" + dir.file(name) + "'";
}

std::string viewpoint(double x, double y, double z, const Eigen::Vector3d& at) {
  char text[96];
  std::snprintf(text, sizeof text, " --viewpoint %.4f,%.4f,%.4f", x + at.x(), y + at.y(),
                z + at.z());
  return text;
}

struct Scenes {
  TempDir dir;
  std::string near, far;
  Scenes()
      : near(write_room(dir, "near", Eigen::Vector3d::Zero())), far(write_room(dir, "far", kUtm)) {}
};

void expect_shift(const Json::Value& json, const Eigen::Vector3d& shift) {
  ASSERT_TRUE(json["global_shift"].isArray()) << json.toStyledString();
  for (Json::ArrayIndex a = 0; a < 3; ++a) {
    EXPECT_EQ(json["global_shift"][a].asDouble(), shift[a]);
  }
}

TEST(GlobalShiftCli, CloudOcclusionEqualsTheSceneAtTheOrigin) {
  const Scenes scenes;
  const std::string options = " --point-radius 0.05 --num-rays-per-vp 4000 --seed 3";
  for (const char* views : {" --pattern 7", " --num-vp 4"}) {
    const Json::Value here = run_json("-poc " + scenes.near + views + options);
    const Json::Value there = run_json("-poc " + scenes.far + views + options);
    EXPECT_EQ(there["occlusion_level"].asDouble(), here["occlusion_level"].asDouble()) << views;
    EXPECT_EQ(there["hits"], here["hits"]);
    expect_shift(here, Eigen::Vector3d::Zero());
    expect_shift(there, kUtm);
    // Reported viewpoints are in the file's frame.
    ASSERT_EQ(there["viewpoints"].size(), here["viewpoints"].size());
    for (Json::ArrayIndex v = 0; v < here["viewpoints"].size(); ++v) {
      for (Json::ArrayIndex a = 0; a < 3; ++a) {
        EXPECT_NEAR(there["viewpoints"][v]["position"][a].asDouble(),
                    here["viewpoints"][v]["position"][a].asDouble() + kUtm[a], 1e-6);
      }
    }
  }
  // Explicit viewpoints and openings in each scene's own coordinates.
  const std::string here_window =
      write_window(scenes.dir, "near_window.txt", Eigen::Vector3d::Zero());
  const std::string there_window = write_window(scenes.dir, "far_window.txt", kUtm);
  const Json::Value here =
      run_json("-poc " + scenes.near + viewpoint(1.0, 1.5, 1.25, Eigen::Vector3d::Zero()) +
               viewpoint(3.0, 2.0, 1.5, Eigen::Vector3d::Zero()) + " --polygon-path " +
               here_window + " --exterior" + options);
  const Json::Value there = run_json("-poc " + scenes.far + viewpoint(1.0, 1.5, 1.25, kUtm) +
                                     viewpoint(3.0, 2.0, 1.5, kUtm) + " --polygon-path " +
                                     there_window + " --exterior" + options);
  EXPECT_GT(here["through_openings"].asUInt64(), 0u);  // the window lets rays out
  EXPECT_GT(here["occlusion_level"].asDouble(), 0.0);  // and so does the hole
  EXPECT_EQ(there["occlusion_level"].asDouble(), here["occlusion_level"].asDouble());
  EXPECT_EQ(there["through_openings"], here["through_openings"]);
  EXPECT_EQ(there["exterior"]["occlusion_level"].asDouble(),
            here["exterior"]["occlusion_level"].asDouble());

  // Openings in the local frame (as a tool that drew the shifted positions
  // would give them) can block nothing: refused, not ignored.
  const testing::CliRun local = run_cli("-poc " + scenes.far + viewpoint(1.0, 1.5, 1.25, kUtm) +
                                        " --polygon-path " + here_window + " -q" + options);
  EXPECT_EQ(local.exit_code, 3) << local.err;
  EXPECT_NE(local.err.find("add the shift"), std::string::npos) << local.err;
}

TEST(GlobalShiftCli, ScanEqualsTheSceneAtTheOriginAndWritesTheFileFrame) {
  const Scenes scenes;
  const std::string options = " --pattern 4 --point-radius 0.04 --format ply";
  const Json::Value here =
      run_json("-fscan " + scenes.near + options + " --out '" + scenes.dir.file("near_out") + "'");
  const Json::Value there =
      run_json("-fscan " + scenes.far + options + " --out '" + scenes.dir.file("far_out") + "'");
  EXPECT_LT(here["visible_fraction"].asDouble(), 1.0);
  EXPECT_EQ(there["visible_fraction"].asDouble(), here["visible_fraction"].asDouble());
  EXPECT_EQ(there["visible_points"], here["visible_points"]);
  EXPECT_EQ(there["classes"], here["classes"]);
  expect_shift(there, kUtm);

  // The full output, read back, holds the input's coordinates exactly.
  const PointCloud input = read_cloud(scenes.dir.file("far"));
  const PointCloud written = read_cloud(scenes.dir.file("far_out/far.scan_full.ply"));
  ASSERT_EQ(written.size(), input.size());
  EXPECT_EQ(written.shift, kUtm);
  for (std::size_t i = 0; i < input.size(); ++i) {
    ASSERT_EQ(written.original_position(i), input.original_position(i)) << i;
  }
}

TEST(GlobalShiftCli, RegionGrowingEqualsTheSceneAtTheOrigin) {
  const Scenes scenes;
  const std::string options = " --pattern 1 --samples-per-unit-area 200 --seed 2";
  const Json::Value here = run_json("-rgoc " + scenes.near + options);
  const Json::Value there = run_json("-rgoc " + scenes.far + options);
  EXPECT_GT(here["planes"].size(), 4u);
  EXPECT_EQ(there["occlusion_level"].asDouble(), here["occlusion_level"].asDouble());
  EXPECT_EQ(there["planes"].size(), here["planes"].size());
  expect_shift(there, kUtm);
  // Planes are reported in the file's frame.
  for (Json::ArrayIndex p = 0; p < here["planes"].size(); ++p) {
    for (Json::ArrayIndex a = 0; a < 3; ++a) {
      EXPECT_NEAR(there["planes"][p]["centroid"][a].asDouble(),
                  here["planes"][p]["centroid"][a].asDouble() + kUtm[a], 1e-6);
    }
  }
}

TEST(GlobalShiftCli, EvaluationEqualsTheSceneAtTheOrigin) {
  const Scenes scenes;
  // The prediction, in the seed table's evaluation ids (wall 0, floor and
  // ceiling 1): every point right but the table, called floor; in reverse
  // order, so points are paired by their coordinates.
  const auto prediction = [&](const std::string& room, const Eigen::Vector3d& at) {
    const PointCloud truth = read_cloud(scenes.dir.file(room));
    std::ostringstream text;
    for (std::size_t k = truth.size(); k-- > 0;) {
      const Eigen::Vector3d p = truth.original_position(k) - at;
      const int label = truth.class_names.at(truth.labels[k]) == "wall" ? 0 : 1;
      text << xyz(p.x(), p.y(), p.z(), at) << ' ' << label << '\n';
    }
    scenes.dir.write(room + "_prediction.txt", text.str());
    return "'" + scenes.dir.file(room + "_prediction.txt") + "'";
  };
  const std::string near_prediction = prediction("near", {0, 0, 0});
  const std::string far_prediction = prediction("far", kUtm);
  // Paired by identical coordinates, then by nearest neighbour.
  for (const char* distance : {" --max-distance 0", " --max-distance 0.01"}) {
    const Json::Value here =
        run_json("-eval " + scenes.near + " --prediction " + near_prediction + distance);
    const Json::Value there =
        run_json("-eval " + scenes.far + " --prediction " + far_prediction + distance);
    ASSERT_TRUE(here["miou"].isDouble()) << here.toStyledString();
    EXPECT_LT(here["miou"].asDouble(), 1.0);
    EXPECT_GT(here["miou"].asDouble(), 0.5);
    EXPECT_EQ(there["miou"], here["miou"]) << distance;
    EXPECT_EQ(there["overall_accuracy"], here["overall_accuracy"]);
    EXPECT_EQ(there["classes"], here["classes"]);
    EXPECT_EQ(there["confusion"], here["confusion"]);
    EXPECT_EQ(there["beyond_distance_points"].asUInt64(), 0u);
  }
}

}  // namespace
}  // namespace occlusion
