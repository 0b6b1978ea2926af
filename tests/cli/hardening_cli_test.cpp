// Abusive and interrupted runs: documented exit codes for absurd values, far
// coordinates, and an interrupted run that leaves the previous outputs intact
// and no temporary file behind.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <sstream>
#include <thread>

#include "run_cli.hpp"

namespace occlusion {
namespace {

using testing::CliRun;
using testing::read_text;
using testing::run_cli;
using testing::run_json;
using testing::TempDir;

const std::string kSource = OCCLUSION_SOURCE_DIR;
const std::string kRoom = "'" + kSource + "/files/sample_room.obj'";

// A 1 m x 1 m wall of 21 x 21 points at z = 0, plus a floor, as a text cloud.
std::string small_cloud(const TempDir& dir) {
  std::ostringstream text;
  for (int i = 0; i <= 20; ++i) {
    for (int j = 0; j <= 20; ++j) {
      text << i * 0.05 << ' ' << j * 0.05 << " 0\n";
      text << i * 0.05 << " 0 " << 0.05 + j * 0.05 << '\n';
    }
  }
  dir.write("cloud.txt", text.str());
  return "'" + dir.file("cloud.txt") + "'";
}

std::vector<std::string> entries(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

TEST(Hardening, AbsurdValuesGetTheUsageExitCode) {
  const TempDir dir;
  const std::string cloud = small_cloud(dir);
  const std::string quiet = " -q --viewpoint 0.5,0.5,0.5";
  EXPECT_EQ(run_cli("-poc " + cloud + quiet + " --point-radius 1e39").exit_code, 2);
  EXPECT_EQ(run_cli("-rgoc " + cloud + quiet + " --normal-k 4000000000").exit_code, 2);
  EXPECT_EQ(run_cli("-fscan " + cloud + quiet + " --self-tolerance -1").exit_code, 2);
  EXPECT_EQ(run_cli("-moc " + kRoom + " -q --num-vp 70000").exit_code, 2);
}

TEST(Hardening, ConfigNestedTooDeepIsAUsageError) {
  const TempDir dir;
  std::string deep = "{\"mesh\": {\"viewpoints\": ";
  for (int i = 0; i < 5000; ++i) deep += '[';
  for (int i = 0; i < 5000; ++i) deep += ']';
  deep += "}}";
  dir.write("deep.json", deep);
  const CliRun run = run_cli("-moc " + kRoom + " -q --config '" + dir.file("deep.json") + "'");
  EXPECT_EQ(run.exit_code, 2) << run.err;
}

// A mesh 5e6 units from the origin (a UTM northing) gives the levels it
// gives at the origin.
TEST(Hardening, ShiftedMeshGivesTheSameLevel) {
  const TempDir dir;
  std::ostringstream near, far;
  const double shift = 5e6;
  const char* corners[] = {"0 0 0", "4 0 0", "4 3 0", "0 3 0", "1 1 1", "3 1 1", "3 2 1", "1 2 1"};
  for (const char* corner : corners) {
    std::istringstream in(corner);
    double x, y, z;
    in >> x >> y >> z;
    near << "v " << x << ' ' << y << ' ' << z << '\n';
    far.precision(17);
    far << "v " << x + shift << ' ' << y + shift << ' ' << z << '\n';
  }
  const std::string faces = "g floor\nf 1 2 3\nf 1 3 4\ng table\nf 5 6 7\nf 5 7 8\n";
  dir.write("near.obj", near.str() + faces);
  dir.write("far.obj", far.str() + faces);
  const std::string options = " --samples-per-unit-area 2000 --seed 4";
  const Json::Value here =
      run_json("-moc '" + dir.file("near.obj") + "' --viewpoint 2,1.5,3" + options);
  const std::string far_viewpoint = " --viewpoint 5000002,5000001.5,3";
  const Json::Value there =
      run_json("-moc '" + dir.file("far.obj") + "'" + far_viewpoint + options);
  // From 3 m up, the 2 m x 1 m table 1 m up shades 3 m x 1.5 m of the 12 m^2
  // floor: 4.5 of the 14 m^2.
  EXPECT_NEAR(here["occlusion_level"].asDouble(), 4.5 / 14.0, 0.01);
  EXPECT_NEAR(there["occlusion_level"].asDouble(), here["occlusion_level"].asDouble(), 1e-9);
}

// A run killed by Ctrl-C while tracing leaves the previous run's outputs as
// they were, every one of them, and no temporary file.
TEST(Hardening, InterruptedRunKeepsTheOldOutputs) {
  const TempDir dir;
  const std::string out = dir.file("out");
  run_json("-moc " + kRoom + " --pattern 1 --samples-per-unit-area 50 --out '" + out + "'");
  const std::vector<std::string> before = entries(out);
  ASSERT_EQ(before.size(), 3u);
  std::vector<std::string> old_bytes;
  for (const auto& name : before) old_bytes.push_back(read_text(out + "/" + name));

  const std::string err = dir.file("err");
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const std::string command = std::string("exec '") + OCCLUSION_CLI_PATH + "' -moc " + kRoom +
                                " --pattern 1 --samples-per-unit-area 20000 --out '" + out +
                                "' 2>'" + err + "'";
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  // Wait until it traces, so that the signal comes mid-run.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (read_text(err).find("tracing") == std::string::npos &&
         std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ASSERT_EQ(::kill(child, SIGINT), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT) << read_text(err);
  EXPECT_NE(read_text(err).find("cancelled"), std::string::npos) << read_text(err);

  EXPECT_EQ(entries(out), before);
  for (std::size_t i = 0; i < before.size(); ++i) {
    EXPECT_EQ(read_text(out + "/" + before[i]), old_bytes[i]) << before[i];
  }
}

// A run whose last output cannot be written replaces none: before, the new
// .ply and .csv sat beside the old .json.
TEST(Hardening, FailedWriteKeepsTheWholeOldSet) {
  const TempDir dir;
  const std::string out = dir.file("out");
  run_json("-moc " + kRoom + " --pattern 1 --samples-per-unit-area 50 --out '" + out + "'");
  const std::string json = out + "/sample_room.moc.json";
  ASSERT_TRUE(std::filesystem::exists(json));
  // The report's place is taken by a folder, so the last rename must fail.
  std::filesystem::remove(json);
  std::filesystem::create_directories(json + "/keep");
  const std::vector<std::string> before = entries(out);
  std::vector<std::string> old_bytes;
  for (const auto& name : before) {
    if (name != "sample_room.moc.json") old_bytes.push_back(read_text(out + "/" + name));
  }

  const CliRun run =
      run_cli("-moc " + kRoom + " -q --pattern 2 --samples-per-unit-area 60 --out '" + out + "'");
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_EQ(entries(out), before);
  std::size_t i = 0;
  for (const auto& name : before) {
    if (name != "sample_room.moc.json") {
      EXPECT_EQ(read_text(out + "/" + name), old_bytes[i++]) << name;
    }
  }
}

}  // namespace
}  // namespace occlusion
