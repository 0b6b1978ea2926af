#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <tuple>

#include "io/cloud_test_support.hpp"
#include "io/scratch_directory.hpp"
#include "occlusion/io/cloud_io.hpp"
#include "occlusion/io/polygon_file.hpp"

namespace occlusion {
namespace {

namespace fs = std::filesystem;

constexpr std::int32_t kFloor = 1, kWall = 2, kWindow = 5, kDoor = 6, kChair = 8, kClutter = 12;

// Writes <room>/<room>.txt and <room>/Annotations/<name> for each (name, text).
void make_room(const fs::path& room,
               const std::vector<std::pair<std::string, std::string>>& files) {
  fs::create_directories(room / "Annotations");
  std::string all;
  for (const auto& [name, text] : files) {
    testing::write_text((room / "Annotations" / name).string(), text);
    all += text;
  }
  testing::write_text((room / (room.filename().string() + ".txt")).string(), all);
}

TEST(S3dis, ClassNamesAreTheThirteenInOrder) {
  const std::vector<std::string> expected{"ceiling",  "floor", "wall",   "beam",  "column",
                                          "window",   "door",  "table",  "chair", "sofa",
                                          "bookcase", "board", "clutter"};
  EXPECT_EQ(s3dis_class_names(), expected);
}

TEST(S3dis, RoomIsLabelledFromItsAnnotations) {
  testing::ScratchDirectory dir;
  const fs::path room = dir.path() / "office_7";
  make_room(room, {{"chair_10.txt", "1 1 1 10 10 10\n"},
                   {"chair_2.txt", "2 2 2 20 20 20\n2.5 2 2 21 21 21\n"},
                   {"floor_1.txt", "3 3 0 30 30 30\n"},
                   {"stairs_1.txt", "4 4 4 40 40 40\n"}});
  testing::write_text((room / "Annotations" / "notes.md").string(), "not an annotation");
  CloudReadReport report;
  const PointCloud cloud = read_cloud(room.string() + "/", {}, &report);
  EXPECT_EQ(cloud.class_names, s3dis_class_names());
  ASSERT_EQ(cloud.size(), 5u);
  // The points in office_7.txt's order (chair_10's point first, as written);
  // chair_2 before chair_10: instances follow the numbers in the names.
  EXPECT_EQ(cloud.positions[0], Eigen::Vector3f(1, 1, 1));
  EXPECT_EQ(cloud.positions[1], Eigen::Vector3f(2, 2, 2));
  EXPECT_EQ(cloud.labels, (std::vector<std::int32_t>{kChair, kChair, kChair, kFloor, kClutter}));
  EXPECT_EQ(cloud.instances, (std::vector<std::int32_t>{1, 0, 0, 2, 3}));
  EXPECT_EQ(cloud.colours[0], (std::array<std::uint8_t, 3>{10, 10, 10}));
  EXPECT_EQ(report.rooms, std::vector<std::string>{"office_7"});
  EXPECT_TRUE(report.unverified_order.empty());
}

// A user's labels follow <room>.txt, whatever order the scanner wrote it in;
// each point is labelled from the annotation holding its coordinates, also
// for a point stored twice (in two annotation files).
TEST(S3dis, PointsFollowTheRoomFileInAnyOrder) {
  testing::ScratchDirectory dir;
  const fs::path room = dir.path() / "office_3";
  make_room(room, {{"floor_1.txt", "0 0 0 1 1 1\n1 0 0 1 1 1\n"},
                   {"wall_1.txt", "0 0 2 2 2 2\n5 5 5 2 2 2\n"},
                   {"chair_1.txt", "0.5 0.5 0.5 3 3 3\n5 5 5 3 3 3\n"}});
  testing::write_text((room / "office_3.txt").string(),
                      "5 5 5 2 2 2\n0 0 2 2 2 2\n0.5 0.5 0.5 3 3 3\n1 0 0 1 1 1\n5 5 5 3 3 3\n"
                      "0 0 0 1 1 1\n");
  CloudReadReport report;
  const PointCloud cloud = read_cloud(room.string(), {}, &report);
  EXPECT_TRUE(report.unverified_order.empty());
  ASSERT_EQ(cloud.size(), 6u);
  EXPECT_EQ(cloud.positions[2], Eigen::Vector3f(0.5f, 0.5f, 0.5f));
  EXPECT_EQ(cloud.positions[5], Eigen::Vector3f(0, 0, 0));
  // Annotations order is chair_1, floor_1, wall_1 (instances 0, 1, 2); the
  // duplicated (5,5,5) pairs in order of appearance: chair_1's copy first.
  EXPECT_EQ(cloud.labels,
            (std::vector<std::int32_t>{kChair, kWall, kChair, kFloor, kWall, kFloor}));
  EXPECT_EQ(cloud.instances, (std::vector<std::int32_t>{0, 2, 0, 1, 2, 1}));
  EXPECT_EQ(cloud.colours[0], (std::array<std::uint8_t, 3>{2, 2, 2}));  // the room file's
}

TEST(S3dis, WithoutAMatchingRoomFileThePointsAreInAnnotationsOrder) {
  testing::ScratchDirectory dir;
  const fs::path room = dir.path() / "office_4";
  make_room(room, {{"wall_1.txt", "9 9 9 1 1 1\n"}, {"floor_1.txt", "0 0 0 1 1 1\n"}});
  fs::remove(room / "office_4.txt");
  CloudReadReport report;
  PointCloud cloud = read_cloud(room.string(), {}, &report);
  EXPECT_EQ(cloud.labels, (std::vector<std::int32_t>{kFloor, kWall}));
  ASSERT_EQ(report.unverified_order.size(), 1u);
  EXPECT_NE(report.unverified_order[0].find("no office_4.txt"), std::string::npos);

  // A room file with a point no annotation holds, and missing one.
  testing::write_text((room / "office_4.txt").string(), "9 9 9 1 1 1\n0 0 0.5 1 1 1\n");
  report = {};
  cloud = read_cloud(room.string(), {}, &report);
  EXPECT_EQ(cloud.labels, (std::vector<std::int32_t>{kFloor, kWall}));
  ASSERT_EQ(report.unverified_order.size(), 1u);
  const std::string& why = report.unverified_order[0];
  EXPECT_NE(why.find("1 of office_4.txt's points are in no annotation file, the first (0.0"),
            std::string::npos)
      << why;
  EXPECT_NE(why.find("1 annotation points are not in office_4.txt"), std::string::npos) << why;
}

TEST(S3dis, UnknownClassNamesTheFile) {
  testing::ScratchDirectory dir;
  const fs::path room = dir.path() / "lobby_1";
  make_room(room, {{"floor_1.txt", "0 0 0 1 1 1\n"}, {"lamp_1.txt", "0 0 1 1 1 1\n"}});
  testing::expect_input_error([&] { read_cloud(room.string()); }, "lamp_1.txt", 0,
                              "unknown S3DIS class 'lamp'");
}

TEST(S3dis, AnnotationNameWithoutNumberIsAnError) {
  testing::ScratchDirectory dir;
  const fs::path room = dir.path() / "lobby_1";
  make_room(room, {{"floor.txt", "0 0 0 1 1 1\n"}});
  testing::expect_input_error([&] { read_cloud(room.string()); }, "floor.txt", 0,
                              "<class>_<number>.txt");
}

TEST(S3dis, UpperCaseExtensionIsAnErrorNotSkipped) {
  testing::ScratchDirectory dir;
  const fs::path room = dir.path() / "office_3";
  make_room(room, {{"floor_1.txt", "0 0 0 1 1 1\n"}, {"chair_7.TXT", "0 0 1 1 1 1\n"}});
  testing::expect_input_error([&] { read_cloud(room.string()); }, "chair_7.TXT", 0,
                              "the extension must be lower-case .txt");
}

TEST(S3dis, AnnotationThatIsNotARegularFileIsAnError) {
  testing::ScratchDirectory dir;
  const fs::path room = dir.path() / "office_4";
  make_room(room, {{"floor_1.txt", "0 0 0 1 1 1\n"}});
  fs::create_directories(room / "Annotations" / "chair_1.txt");
  testing::expect_input_error([&] { read_cloud(room.string()); }, "chair_1.txt", 0,
                              "is a directory, not a regular file");
}

TEST(S3dis, AnnotationsMustHaveSixColumns) {
  testing::ScratchDirectory dir;
  const fs::path room = dir.path() / "lobby_1";
  make_room(room, {{"floor_1.txt", "0 0 0 1 1 1\n0 0 0 1 1 1 5\n"}});
  testing::expect_input_error([&] { read_cloud(room.string()); }, "floor_1.txt", 2,
                              "must have 6 (x y z r g b)");
}

// Real S3DIS has a few such lines (Area_5/hallway_6: a 0x10 byte in a number).
TEST(S3dis, CorruptLineFailsOrIsSkippedAndCounted) {
  testing::ScratchDirectory dir;
  const fs::path room = dir.path() / "hallway_6";
  make_room(room, {{"ceiling_1.txt",
                    "22.350 6.692 3.048 185 187 182\n22.351 6.690 3.049 185 187 182\n"
                    "22.352 6.6\x10"
                    "92 3.048 185 187 182\n22.353 6.692 3.048 185 187 182\n"}});
  testing::expect_input_error([&] { read_cloud(room.string()); }, "ceiling_1.txt", 3, "\\x10");

  CloudReadOptions options;
  options.skip_bad_lines = true;
  CloudReadReport report;
  const PointCloud cloud = read_cloud(room.string(), options, &report);
  EXPECT_EQ(cloud.size(), 3u);
  EXPECT_EQ(report.skipped_lines, 1u);
}

TEST(S3dis, AreaConcatenatesRoomsWithUniqueInstances) {
  testing::ScratchDirectory dir;
  const fs::path area = dir.path() / "Area_9";
  make_room(area / "office_10", {{"wall_1.txt", "9 9 9 1 1 1\n"}});
  make_room(area / "office_2", {{"floor_1.txt", "0 0 0 1 1 1\n"}, {"wall_1.txt", "1 0 0 2 2 2\n"}});
  testing::write_text((area / "Area_9_alignmentAngle.txt").string(), "office_2 0\n");
  CloudReadReport report;
  const PointCloud cloud = read_cloud(area.string(), {}, &report);
  EXPECT_EQ(report.rooms, (std::vector<std::string>{"office_2", "office_10"}));
  ASSERT_EQ(cloud.size(), 3u);
  EXPECT_EQ(cloud.labels, (std::vector<std::int32_t>{kFloor, kWall, kWall}));
  EXPECT_EQ(cloud.instances, (std::vector<std::int32_t>{0, 1, 2}));
  EXPECT_EQ(cloud.positions[2], Eigen::Vector3f(9, 9, 9));
}

TEST(S3dis, AreaWithANonRoomFolderNamesIt) {
  testing::ScratchDirectory dir;
  const fs::path area = dir.path() / "Area_9";
  make_room(area / "office_1", {{"wall_1.txt", "9 9 9 1 1 1\n"}});
  fs::create_directories(area / "backup");
  testing::expect_input_error([&] { read_cloud(area.string()); }, "backup", 0, "not a room");
}

TEST(S3dis, AreaWithALoopOfLinksNamesTheLink) {
  testing::ScratchDirectory dir;
  const fs::path area = dir.path() / "Area_9";
  make_room(area / "office_1", {{"wall_1.txt", "9 9 9 1 1 1\n"}});
  fs::create_symlink("office_3", area / "office_2");
  fs::create_symlink("office_2", area / "office_3");
  testing::expect_input_error([&] { read_cloud(area.string()); }, "office_", 0,
                              "a loop of symbolic links");
}

TEST(S3dis, FolderThatIsNeitherRoomNorArea) {
  testing::ScratchDirectory dir;
  testing::write_text(dir.file("loose.txt"), "1 2 3\n");
  testing::expect_input_error([&] { read_cloud(dir.path().string()); }, dir.path().string(), 0,
                              "neither an S3DIS room");
}

// The committed synthetic room (files/s3dis_synthetic, made by generate_s3dis_room).
const std::string kSyntheticArea =
    std::string(OCCLUSION_SOURCE_DIR) + "/files/s3dis_synthetic/Area_1";

TEST(S3disSynthetic, AreaLoadsAsOneLabelledRoom) {
  CloudReadReport report;
  const PointCloud cloud = read_cloud(kSyntheticArea, {}, &report);
  EXPECT_EQ(report.rooms, std::vector<std::string>{"office_1"});
  EXPECT_EQ(report.skipped_lines, 0u);
  EXPECT_EQ(cloud.class_names, s3dis_class_names());
  ASSERT_GT(cloud.size(), 20000u);
  EXPECT_NO_THROW(cloud.validate());

  std::set<std::int32_t> labels(cloud.labels.begin(), cloud.labels.end());
  for (const std::int32_t label : labels) {
    EXPECT_GE(label, 0);
    EXPECT_LT(label, 13);
  }
  // ceiling floor wall window door table chair bookcase board clutter
  EXPECT_EQ(labels, (std::set<std::int32_t>{0, 1, 2, 5, 6, 7, 8, 10, 11, 12}));
  const std::set<std::int32_t> instances(cloud.instances.begin(), cloud.instances.end());
  EXPECT_EQ(instances.size(), 19u);  // 6 room surfaces, window, door, 11 furniture objects

  Eigen::Vector3f lo;
  Eigen::Vector3f hi;
  cloud.bounds(lo, hi);
  EXPECT_LT(lo.cwiseAbs().maxCoeff(), 0.01f);
  EXPECT_NEAR(hi.x(), 6.0, 0.01);
  EXPECT_NEAR(hi.y(), 5.0, 0.01);
  EXPECT_NEAR(hi.z(), 3.0, 0.01);

  // The points are office_1.txt's, in its order, and each carries the class
  // of the annotation file that holds it (checked file by file, by brute force).
  EXPECT_TRUE(report.unverified_order.empty());
  EXPECT_EQ(read_cloud(kSyntheticArea + "/office_1/office_1.txt").positions, cloud.positions);
  std::map<std::tuple<float, float, float>, std::int32_t> label_at;
  for (const auto& entry : fs::directory_iterator(kSyntheticArea + "/office_1/Annotations")) {
    const std::string stem = entry.path().stem().string();
    const std::string class_name = stem.substr(0, stem.rfind('_'));
    const auto& names = s3dis_class_names();
    const auto label = static_cast<std::int32_t>(std::find(names.begin(), names.end(), class_name) -
                                                 names.begin());
    for (const auto& p : read_cloud(entry.path().string()).positions) {
      label_at[{p.x(), p.y(), p.z()}] = label;
    }
  }
  ASSERT_EQ(label_at.size(), cloud.size());
  std::size_t agree = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const auto& p = cloud.positions[i];
    agree += label_at.at({p.x(), p.y(), p.z()}) == cloud.labels[i] ? 1 : 0;
  }
  EXPECT_EQ(agree, cloud.size());
}

TEST(S3disSynthetic, OpeningsOutlineHolesInTheWalls) {
  const PointCloud cloud = read_cloud(kSyntheticArea + "/office_1");
  const auto openings = read_polygons(kSyntheticArea + "/../openings.txt");
  ASSERT_EQ(openings.size(), 2u);
  for (std::size_t k = 0; k < openings.size(); ++k) {
    ASSERT_EQ(openings[k].size(), 4u);
    Eigen::Vector3d lo = openings[k][0];
    Eigen::Vector3d hi = openings[k][0];
    for (const auto& corner : openings[k]) {
      lo = lo.cwiseMin(corner);
      hi = hi.cwiseMax(corner);
    }
    // Flat in one axis (the wall's), open in the other two.
    const int normal_axis = (hi - lo).x() == 0 ? 0 : 1;
    const std::int32_t expected_label = normal_axis == 1 ? kWindow : kDoor;
    std::size_t opening_points = 0;
    std::size_t wall_points_in_hole = 0;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      const Eigen::Vector3d p = cloud.positions[i].cast<double>();
      // Wall points are looked for in the wall plane; the opening's own points
      // may stand off it (the open door leaf reaches 0.45 m into the room).
      const double off_plane = std::abs(p[normal_axis] - lo[normal_axis]);
      bool inside = off_plane < 0.5;
      for (int axis = 0; axis < 3; ++axis) {
        if (axis == normal_axis) continue;
        inside = inside && p[axis] > lo[axis] + 0.005 && p[axis] < hi[axis] - 0.005;
      }
      if (!inside) continue;
      if (cloud.labels[i] == kWall && off_plane < 0.05) ++wall_points_in_hole;
      if (cloud.labels[i] == expected_label) ++opening_points;
    }
    EXPECT_EQ(wall_points_in_hole, 0u) << "opening " << k;
    EXPECT_GT(opening_points, 50u) << "opening " << k;
  }
}

}  // namespace
}  // namespace occlusion
