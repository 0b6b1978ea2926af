// `occlusion study` and `study merge` as a user runs them, on config/study.json.

#include <gtest/gtest.h>
#include <json/reader.h>

#include <filesystem>
#include <sstream>

#include "run_cli.hpp"

namespace occlusion {
namespace {

using testing::CliRun;
using testing::parse_json;
using testing::run_cli;
using testing::run_json;
using testing::TempDir;

const std::string kConfig =
    "study --config '" + std::string(OCCLUSION_SOURCE_DIR) + "/config/study.json'";

TEST(StudyCli, ASegmenterCommandLeavesStdoutToTheJson) {
  const TempDir dir;
  // The "network" hands back the scanned cloud itself, labels and class names
  // included: a perfect segmentation, read as a labelled cloud. Its chatter on
  // stdout must not reach ours.
  const CliRun run =
      run_cli(kConfig + " --pattern 1 --num-rays-per-vp 300 --out '" + dir.file("study") +
              "' --segmenter 'echo chatter; cp {input} {output}' "
              "--segmenter-output ply --json -q");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Json::Value json = parse_json(run.out);
  EXPECT_EQ(json["job"].asString(), "study");
  EXPECT_EQ(json["runs_computed"].asUInt(), 1u);
  ASSERT_EQ(json["rows"].size(), 1u);
  EXPECT_EQ(json["rows"][0]["configuration"].asString(), "pattern_1");
  EXPECT_DOUBLE_EQ(json["rows"][0]["miou"].asDouble(), 1.0);
  EXPECT_NE(run.err.find("chatter"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(dir.file("study/runs/office_1__pattern_1.prediction.ply")));

  const CliRun merged = run_cli("study merge '" + dir.file("merged") + "' '" +
                                dir.file("study/study.csv") + "' --json");
  ASSERT_EQ(merged.exit_code, 0) << merged.err;
  EXPECT_EQ(parse_json(merged.out)["rows"].size(), 1u);
  EXPECT_TRUE(std::filesystem::exists(dir.file("merged/study.md")));
}

TEST(StudyCli, ExitCodesFollowTheContract) {
  const TempDir dir;
  const std::string out = " --out '" + dir.file("study") + "'";
  EXPECT_EQ(run_cli(kConfig + out + " --shard 2/2").exit_code, 2);
  EXPECT_EQ(run_cli("study" + out).exit_code, 2);  // no scenes
  EXPECT_EQ(run_cli(kConfig + out + " --segmenter 'infer.py {input}'").exit_code, 2);
  EXPECT_EQ(run_cli("study merge '" + dir.file("m") + "' '" + dir.file("none.csv") + "'").exit_code,
            3);
  EXPECT_EQ(run_cli("study merge '" + dir.file("m") + "'").exit_code, 2);
  EXPECT_EQ(
      run_cli(kConfig + out + " --pattern 1 --segmenter 'exit 4 # {input} {output}' -q").exit_code,
      1);
  const CliRun help = run_cli("study --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("--shard I/N"), std::string::npos);
}

}  // namespace
}  // namespace occlusion
