// A file name that is not UTF-8 (Linux names are bytes) must not make the
// `--json` report invalid JSON: the bytes are replaced by U+FFFD (issue 13).

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "run_cli.hpp"

namespace occlusion {
namespace {

TEST(NonUtf8Names, JsonReportStaysValidUtf8) {
  const testing::TempDir dir;
  const std::string name = "r\xE9union.obj";  // Latin-1 "réunion"
  std::filesystem::copy_file(std::string(OCCLUSION_SOURCE_DIR) + "/files/sample_room.obj",
                             dir.file(name));
  const testing::CliRun run = testing::run_cli(
      "-moc '" + dir.file(name) + "' --pattern 1 --samples-per-unit-area 20 --seed 1 --json -q");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Json::Value json = testing::parse_json(run.out);
  EXPECT_EQ(json["job"].asString(), "mesh_occlusion");
  EXPECT_EQ(run.out.find("r\xE9union"), std::string::npos) << "raw Latin-1 byte in the JSON";
  EXPECT_NE(run.out.find("r\xEF\xBF\xBDunion.obj"), std::string::npos) << run.out;
}

}  // namespace
}  // namespace occlusion
