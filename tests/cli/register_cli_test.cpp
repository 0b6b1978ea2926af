// register end to end on PCL's tutorial pair: the refined pose written in
// the initial pose's format and read back as the report gives it, the fit
// reported, and the refusals' exit codes and messages.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>

#include "run_cli.hpp"

namespace occlusion {
namespace {

using testing::read_text;
using testing::run_cli;
using testing::run_json;
using testing::TempDir;

const std::string kSource = OCCLUSION_SOURCE_DIR;
const std::string kPair = "'" + kSource + "/files/pcl/room_scan2.pcd' --target '" + kSource +
                          "/files/pcl/room_scan1.pcd'";

// The tutorial's guess, 0.6931 rad about z then (1.79387, 0.720047, 0), as
// a 4 x 4 in rows, its translation moved by `dx`.
std::string tutorial_matrix(double dx = 0.0) {
  const double c = std::cos(0.6931), s = std::sin(0.6931);
  std::ostringstream text;
  text.precision(17);
  text << c << " " << -s << " 0 " << 1.79387 + dx << "\n"
       << s << " " << c << " 0 0.720047\n0 0 1 0\n0 0 0 1\n";
  return text.str();
}

TEST(RegisterCli, TutorialPairIsRefinedAndThePoseWrittenInItsFormat) {
  const TempDir dir;
  dir.write("guess.txt", tutorial_matrix());
  const Json::Value report = run_json("register " + kPair + " --initial-pose '" +
                                      dir.file("guess.txt") + "' --out '" + dir.path() + "'");
  EXPECT_EQ(report["job"].asString(), "register");
  EXPECT_TRUE(report["converged"].asBool());
  EXPECT_GT(report["overlap"].asDouble(), report["before"]["overlap"].asDouble());
  EXPECT_GT(report["rms"].asDouble(), 0.0);
  EXPECT_LT(report["rms"].asDouble(), report["before"]["rms"].asDouble());
  ASSERT_EQ(report["levels"].size(), 3u);
  EXPECT_GT(report["levels"][0]["iterations"].asUInt(), 0u);
  // The written pose is the report's, 16 numbers in rows.
  std::istringstream written(read_text(dir.file("room_scan2.refined.txt")));
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) {
      double value = NAN;
      ASSERT_TRUE(written >> value);
      EXPECT_NEAR(value, report["refined_pose"]["matrix"][r][c].asDouble(), 1e-12);
    }
  }
  EXPECT_TRUE(std::filesystem::exists(dir.file("room_scan2.register.json")));
}

TEST(RegisterCli, ATumPoseIsWrittenBackAsATumLine) {
  const TempDir dir;
  // The tutorial's guess as tx ty tz qx qy qz qw: half the angle about z.
  std::ostringstream tum;
  tum.precision(17);
  tum << "1.79387 0.720047 0 0 0 " << std::sin(0.6931 / 2) << " " << std::cos(0.6931 / 2) << "\n";
  dir.write("guess.tum", tum.str());
  // Seven numbers could be a w-first quaternion: the format must be said.
  const auto unsaid =
      run_cli("register " + kPair + " --initial-pose '" + dir.file("guess.tum") + "'");
  EXPECT_EQ(unsaid.exit_code, 3);
  EXPECT_NE(unsaid.err.find("cannot tell the pose's format"), std::string::npos) << unsaid.err;
  const Json::Value report =
      run_json("register " + kPair + " --initial-pose '" + dir.file("guess.tum") +
               "' --pose-format tum --out '" + dir.path() + "'");
  EXPECT_EQ(report["pose_format"].asString(), "tum");
  // The line written: the refined translation, then a unit quaternion whose
  // angle is the report's.
  std::istringstream written(read_text(dir.file("room_scan2.refined.tum")));
  std::string line;
  while (std::getline(written, line) && line.rfind('#', 0) == 0) {
  }
  std::istringstream numbers(line);
  double t[3], q[4];
  for (double& v : t) ASSERT_TRUE(numbers >> v);
  for (double& v : q) ASSERT_TRUE(numbers >> v);
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(t[axis], report["refined_pose"]["translation"][axis].asDouble(), 1e-12);
  }
  EXPECT_NEAR(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3], 1.0, 1e-12);
  EXPECT_NEAR(2.0 * std::acos(std::abs(q[3])) * 180.0 / 3.14159265358979323846,
              report["refined_pose"]["rotation_deg"].asDouble(), 1e-9);
}

// The tutorial's guess as a project's pose: rows of a 4 x 4 in JSON.
std::string tutorial_pose_json() {
  std::istringstream numbers(tutorial_matrix());
  std::string json = "[";
  for (int r = 0; r < 4; ++r) {
    json += r == 0 ? "[" : ", [";
    for (int c = 0; c < 4; ++c) {
      std::string value;
      numbers >> value;
      json += (c == 0 ? "" : ", ") + value;
    }
    json += "]";
  }
  return json + "]";
}

TEST(RegisterCli, AProjectsScansAreRefinedOntoTheFirstAndTheProjectWrittenBack) {
  // The scans beside the project, named relative to it: the refined project
  // written into another folder must still find them.
  const TempDir dir;
  for (const char* name : {"room_scan1.pcd", "room_scan2.pcd"}) {
    std::filesystem::copy_file(kSource + "/files/pcl/" + name, dir.file(name));
  }
  // The first scan's pose from a file beside them, which the refined
  // project names as it is (the first scan is not refined).
  dir.write("identity.txt", "1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n");
  dir.write("room.project.json",
            "{\"scans\": [{\"path\": \"room_scan1.pcd\", \"pose_file\": \"identity.txt\"},\n "
            "{\"path\": \"room_scan2.pcd\", \"pose\": " +
                tutorial_pose_json() + "}]}\n");
  // Named from the working folder (the CLI's too): its scans resolve to
  // paths relative to it, which the folder written into is not.
  const std::string project =
      std::filesystem::relative(dir.file("room.project.json"), std::filesystem::current_path())
          .string();
  const Json::Value report = run_json("register '" + project + "' --out '" + dir.path() + "/out'");
  ASSERT_EQ(report["project_scans"].size(), 1u);
  const Json::Value& scan = report["project_scans"][0];
  EXPECT_TRUE(scan["converged"].asBool());
  EXPECT_GT(scan["overlap"].asDouble(), scan["before"]["overlap"].asDouble());
  // The project read back places scan 2 at the refined pose: its station,
  // the pose's translation, is -fscan's second default viewpoint (points
  // beyond 1 m of their station dropped, to keep the run short).
  const Json::Value refined =
      run_json("-fscan '" + dir.path() + "/out/room.refined.project.json' --max-range 1");
  ASSERT_EQ(refined["viewpoints"].size(), 2u);
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(refined["viewpoints"][1]["position"][axis].asDouble(),
                scan["refined_pose"]["translation"][axis].asDouble(), 1e-9);
  }
}

TEST(RegisterCli, ScansThatDoNotOverlapAreRefusedSayingWhatToDo) {
  const TempDir dir;
  dir.write("far.txt", tutorial_matrix(100.0));
  const auto run = run_cli("register " + kPair + " --initial-pose '" + dir.file("far.txt") +
                           "' --out '" + dir.path() + "'");
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_NE(run.err.find("do not overlap"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("max_distance"), std::string::npos) << run.err;
  // Nothing written for a refused pair.
  EXPECT_FALSE(std::filesystem::exists(dir.file("room_scan2.refined.txt")));
}

TEST(RegisterCli, APoseFileThatIsNoRigidMotionIsRefusedNamingIt) {
  const TempDir dir;
  dir.write("scaled.txt", "2 0 0 0\n0 2 0 0\n0 0 2 0\n0 0 0 1\n");
  const auto run =
      run_cli("register " + kPair + " --initial-pose '" + dir.file("scaled.txt") + "'");
  EXPECT_EQ(run.exit_code, 3);
  EXPECT_NE(run.err.find("scaled.txt"), std::string::npos) << run.err;
  const auto missing = run_cli("register " + kPair);
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("initial-pose"), std::string::npos) << missing.err;
}

}  // namespace
}  // namespace occlusion
