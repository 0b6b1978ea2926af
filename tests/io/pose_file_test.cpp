#include "occlusion/io/pose_file.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "io/cloud_test_support.hpp"
#include "io/scratch_directory.hpp"

namespace occlusion {
namespace {

void expect_near(const Eigen::Vector3d& actual, const Eigen::Vector3d& expected, double tolerance) {
  EXPECT_LT((actual - expected).norm(), tolerance)
      << actual.transpose() << " vs " << expected.transpose();
}

// Within double rounding: 1e-12 on the rotation, relative on the translation.
void expect_same_pose(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  EXPECT_LT((a.linear() - b.linear()).cwiseAbs().maxCoeff(), 1e-12) << a.matrix() << "\nvs\n"
                                                                    << b.matrix();
  EXPECT_LT((a.translation() - b.translation()).norm(),
            1e-12 * std::max(1.0, b.translation().norm()))
      << a.matrix() << "\nvs\n"
      << b.matrix();
}

// 3DTK's scan001.pose (dat/, 3DTK commit 672da12f): its translation in
// centimetres, left-handed, y up, is (-3.10605, -7.50803, 156.917); in metres
// in the tool's frame (x = z, y = -x, z = y) that is (1.56917, 0.0310605, -0.0750803).
TEST(PoseFile, ThreeDtkTranslationIsCentimetresInTheLeftHandedFrame) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("scan001.pose");
  testing::write_text(path, "-3.10605 -7.50803 156.917\n1.35694 -0.852409 -0.56224\n");
  const ScanPose pose = read_pose_file(path);
  EXPECT_EQ(pose.format, PoseFormat::k3dtk);
  expect_near(pose.scan_to_scene.translation(), {1.56917, 0.0310605, -0.0750803}, 1e-12);
}

// Worked by hand from 3DTK's EulerToMatrix4: angles (0, 90, 0) give
// Ry = [[0,0,1],[0,1,0],[-1,0,0]], which takes 3DTK's z (forward) to its x
// (right) and x to -z. A point 1 m to the right of a scanner placed 2 m ahead
// (t = (0, 0, 200) cm) lies at R (100, 0, 0) + t = (0, 0, 100) cm: 1 m ahead
// of the scene's origin, (1, 0, 0) m in the tool's frame. And the rotation is
// -90 degrees about the tool's z: forward (x) turns to the right (-y).
TEST(PoseFile, ThreeDtkRotationWorkedByHand) {
  const ScanPose yaw = pose_from_numbers({0, 0, 200, 0, 90, 0}, PoseFormat::k3dtk);
  const Eigen::Vector3d scanner_point = point_from_3dtk({100, 0, 0});
  expect_near(scanner_point, {0, -1, 0}, 1e-15);
  expect_near(yaw.scan_to_scene * scanner_point, {1, 0, 0}, 1e-12);
  expect_near(yaw.scan_to_scene.linear() * Eigen::Vector3d::UnitX(), {0, -1, 0}, 1e-12);
  expect_near(yaw.scan_to_scene.linear() * Eigen::Vector3d::UnitY(), {1, 0, 0}, 1e-12);

  // Rx(90) takes 3DTK's y (up) to z (forward): the tool's z to its x.
  const ScanPose pitch = pose_from_numbers({0, 0, 0, 90, 0, 0}, PoseFormat::k3dtk);
  expect_near(pitch.scan_to_scene.linear() * Eigen::Vector3d::UnitZ(), {1, 0, 0}, 1e-12);
  expect_near(pitch.scan_to_scene.linear() * Eigen::Vector3d::UnitY(), {0, 1, 0}, 1e-12);
  EXPECT_NEAR(pitch.scan_to_scene.linear().determinant(), 1.0, 1e-12);
}

TEST(PoseFile, MatrixIsReadInRows) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("registration.txt");
  // A quarter turn about z (x -> y) and a translation, as CloudCompare writes it.
  testing::write_text(path,
                      "0.000000 -1.000000 0.000000 10.5\n1.000000 0.000000 0.000000 -2\n"
                      "0 0 1 0.25\n0 0 0 1\n");
  const ScanPose pose = read_pose_file(path);
  EXPECT_EQ(pose.format, PoseFormat::kMatrix);
  expect_near(pose.scan_to_scene * Eigen::Vector3d(1, 0, 0), {10.5, -1, 0.25}, 1e-12);
}

TEST(PoseFile, MatrixWithFourDecimalsIsTheNearestRotation) {
  const double c = 0.7071, s = 0.7071;  // 45 degrees to 4 decimals
  const ScanPose pose =
      pose_from_numbers({c, -s, 0, 0, s, c, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}, PoseFormat::kMatrix);
  const Eigen::Matrix3d r = pose.scan_to_scene.linear();
  EXPECT_LT((r.transpose() * r - Eigen::Matrix3d::Identity()).norm(), 1e-14);
  expect_near(r * Eigen::Vector3d::UnitX(), {std::sqrt(0.5), std::sqrt(0.5), 0}, 1e-14);
}

void expect_refused(const std::vector<double>& numbers, PoseFormat format,
                    const std::string& message_part) {
  try {
    pose_from_numbers(numbers, format);
    ADD_FAILURE() << "expected a refusal containing '" << message_part << "'";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find(message_part), std::string::npos) << error.what();
  }
}

TEST(PoseFile, RefusesWhatIsNoRigidMotion) {
  expect_refused({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1, 1}, PoseFormat::kMatrix, "last row");
  // Scaled by 1.01 (a unit mix-up or a similarity from a registration tool).
  expect_refused({1.01, 0, 0, 0, 0, 1.01, 0, 0, 0, 0, 1.01, 0, 0, 0, 0, 1}, PoseFormat::kMatrix,
                 "not a rotation");
  // A mirror (left-handed data read as right-handed) is orthonormal but no rotation.
  expect_refused({1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}, PoseFormat::kMatrix, "mirrors");
  // A transposed (column-written) matrix with a translation.
  expect_refused({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 3, 4, 5, 1}, PoseFormat::kMatrix, "last row");
  expect_refused({0, 0, 0, 1, 0, 0, 0.5}, PoseFormat::kTum, "length");
  expect_refused({0, 0, NAN, 0, 0, 0, 1}, PoseFormat::kTum, "not finite");
  expect_refused({1, 2, 3, 4, 5}, PoseFormat::k3dtk, "6 numbers");
}

TEST(PoseFile, TumLineWithTimestamp) {
  testing::ScratchDirectory dir;
  const std::string path = dir.file("pose.txt");
  // A TUM ground-truth line: a half turn about z.
  testing::write_text(path, "# timestamp tx ty tz qx qy qz qw\n1305031102.1758 1 2 3 0 0 1 0\n");
  const ScanPose pose = read_pose_file(path);
  EXPECT_EQ(pose.format, PoseFormat::kTum);
  ASSERT_TRUE(pose.timestamp);
  EXPECT_DOUBLE_EQ(*pose.timestamp, 1305031102.1758);
  expect_near(pose.scan_to_scene * Eigen::Vector3d(1, 0, 0), {0, 2, 3}, 1e-12);
}

TEST(PoseFile, AmbiguousFilesAreRefusedWithAdvice) {
  testing::ScratchDirectory dir;
  const std::string seven = dir.file("seven.txt");
  testing::write_text(seven, "1 2 3 0 0 0 1\n");
  testing::expect_input_error([&] { read_pose_file(seven); }, "seven.txt", 0, "w first");
  // Said to be TUM, it is read.
  EXPECT_EQ(read_pose_file(seven, PoseFormat::kTum).scan_to_scene.translation(),
            Eigen::Vector3d(1, 2, 3));

  const std::string six = dir.file("six.txt");
  testing::write_text(six, "1 2 3\n0 0 0\n");
  testing::expect_input_error([&] { read_pose_file(six); }, "six.txt", 0, "3dtk");

  const std::string trajectory = dir.file("trajectory.txt");
  testing::write_text(trajectory, "1 0 0 0 0 0 0 1\n2 1 0 0 0 0 0 1\n");
  testing::expect_input_error([&] { read_pose_file(trajectory); }, "trajectory.txt", 0,
                              "trajectory");
  testing::expect_input_error([&] { read_pose_file(trajectory, PoseFormat::kTum); },
                              "trajectory.txt", 2, "trajectory");

  const std::string words = dir.file("words.txt");
  testing::write_text(words, "1 0 0 0\n0 1 0 0\n0 0 1 x\n0 0 0 1\n");
  testing::expect_input_error([&] { read_pose_file(words); }, "words.txt", 3, "not a number");
}

// A pose written back in its format reads back as the same transform.
TEST(PoseFile, EachFormatRoundTrips) {
  testing::ScratchDirectory dir;
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
  motion.linear() = (Eigen::AngleAxisd(0.6931, Eigen::Vector3d::UnitZ()) *
                     Eigen::AngleAxisd(-0.3, Eigen::Vector3d(1, 2, 3).normalized()))
                        .toRotationMatrix();
  motion.translation() = Eigen::Vector3d(1.79387, 0.720047, -1.0 / 3.0);
  Eigen::Isometry3d locked = Eigen::Isometry3d::Identity();  // 3DTK's gimbal lock: ay = 90
  locked.linear() =
      pose_from_numbers({0, 0, 0, 30, 90, 0}, PoseFormat::k3dtk).scan_to_scene.linear();
  locked.translation() = Eigen::Vector3d(-4, 5e5, 0.001);
  for (const Eigen::Isometry3d& transform : {motion, locked}) {
    for (const PoseFormat format : {PoseFormat::kMatrix, PoseFormat::kTum, PoseFormat::k3dtk}) {
      for (const bool timestamp : {false, true}) {
        if (timestamp && format != PoseFormat::kTum) continue;
        ScanPose pose;
        pose.scan_to_scene = transform;
        pose.format = format;
        if (timestamp) pose.timestamp = 1305031102.1758;
        const std::string path =
            dir.file(std::string("scan.") + (format == PoseFormat::k3dtk ? "pose" : "txt"));
        write_pose_file(path, pose);
        const ScanPose back = read_pose_file(path, format);
        SCOPED_TRACE(testing::read_bytes(path));
        EXPECT_EQ(back.format, format);
        EXPECT_EQ(back.timestamp, pose.timestamp);
        expect_same_pose(back.scan_to_scene, transform);
        // And from the numbers alone.
        expect_same_pose(pose_from_numbers(pose_numbers(pose), format).scan_to_scene, transform);
      }
    }
  }
}

// docs/formats.md's example, a quarter turn about z then 10 m along x, in
// each format.
TEST(PoseFile, TheDocumentedExampleIsOnePoseInEveryFormat) {
  Eigen::Isometry3d expected = Eigen::Isometry3d::Identity();
  expected.linear() << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  expected.translation() = Eigen::Vector3d(10, 0, 0);
  const std::vector<std::pair<std::vector<double>, PoseFormat>> examples = {
      {{0, -1, 0, 10, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}, PoseFormat::kMatrix},
      {{10, 0, 0, 0, 0, 0.7071068, 0.7071068}, PoseFormat::kTum},
      {{0, 0, 1000, 0, -90, 0}, PoseFormat::k3dtk}};
  for (const auto& [numbers, format] : examples) {
    const Eigen::Isometry3d pose = pose_from_numbers(numbers, format).scan_to_scene;
    EXPECT_LT((pose.matrix() - expected.matrix()).cwiseAbs().maxCoeff(), 1e-7)
        << pose_format_name(format) << "\n"
        << pose.matrix();
  }
}

TEST(PoseFile, FormatNames) {
  for (const PoseFormat format : {PoseFormat::kMatrix, PoseFormat::kTum, PoseFormat::k3dtk}) {
    EXPECT_EQ(pose_format_from_name(pose_format_name(format)), format);
  }
  EXPECT_FALSE(pose_format_from_name("TUM"));
  EXPECT_FALSE(pose_format_from_name("frames"));
}

}  // namespace
}  // namespace occlusion
