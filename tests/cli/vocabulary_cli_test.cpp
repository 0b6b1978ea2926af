// The one vocabulary as a user meets it on the command line: generated help
// and docs, and the drifts found in issue 11 pinned as regressions.

#include <gtest/gtest.h>

#include "run_cli.hpp"

namespace occlusion {
namespace {

using testing::parse_json;
using testing::read_text;
using testing::run_cli;
using testing::TempDir;

const std::string kSource = OCCLUSION_SOURCE_DIR;
const std::string kOffice = "'" + kSource + "/files/s3dis_synthetic/Area_1/office_1'";

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(VocabularyCli, DocsOptionsIsTheGeneratedTable) {
  const auto run = run_cli("keys");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.out, read_text(kSource + "/docs/options.md"))
      << "docs/options.md is stale: regenerate it with build/occlusion keys > docs/options.md";
}

TEST(VocabularyCli, ScanRefusesKeysOfOtherJobsInItsConfig) {
  const TempDir dir;
  dir.write("c.json", R"({"occlusion": {"scan": {"num_rays_per_vp": 100}}})");
  const auto run = run_cli("-fscan " + kOffice + " --config " + dir.file("c.json") + " -q");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(contains(run.err, "unknown key 'occlusion.scan.num_rays_per_vp'")) << run.err;
  EXPECT_EQ(run_cli("-fscan " + kOffice + " --num-rays-per-vp 10 -q").exit_code, 2);
}

TEST(VocabularyCli, ThreadsCapHoldsInConfigFilesToo) {
  const TempDir dir;
  dir.write("c.json", R"({"occlusion": {"point_cloud": {"threads": 5000}}})");
  const auto run = run_cli("-poc " + kOffice + " --config " + dir.file("c.json") + " -q");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(contains(run.err, "'occlusion.point_cloud.threads' must be an integer 0..1024"))
      << run.err;
  EXPECT_EQ(run_cli("-poc " + kOffice + " --threads 5000 -q").exit_code, 2);
}

TEST(VocabularyCli, ConfigErrorsNameConfigKeys) {
  const TempDir dir;
  dir.write("c.json", R"({"occlusion": {"mesh": {"pattern": 9}}})");
  const auto run = run_cli("-moc x.obj --config " + dir.file("c.json") + " -q");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(contains(run.err, "'occlusion.mesh.pattern' must be an integer 1..7")) << run.err;
  EXPECT_FALSE(contains(run.err, "--pattern")) << run.err;
}

TEST(VocabularyCli, AbsurdValuesAreUsageErrors) {
  for (const char* bad : {"--point-radius 1e39", "--normal-k 4000000000", "--normal-k 4e9",
                          "--self-tolerance -2", "--num-rays-per-vp 0", "--threads -1"}) {
    const std::string job = std::string(bad).rfind("--normal-k", 0) == 0 ? "-rgoc " : "-fscan ";
    const std::string args = std::string(bad).rfind("--num-rays", 0) == 0 ? "-poc " : job;
    const auto run = run_cli(args + kOffice + " " + bad + " -q");
    EXPECT_EQ(run.exit_code, 2) << bad << ": " << run.err;
  }
}

TEST(VocabularyCli, BooleanOptionsAreFlagsOrTakeAValue) {
  const auto flag = parse_json(
      run_cli("-poc " + kOffice + " --exterior --num-rays-per-vp 200 --num-vp 1 --json -q").out);
  EXPECT_TRUE(flag["exterior"].isObject());
  const auto off = parse_json(
      run_cli("-poc " + kOffice + " --exterior=false --num-rays-per-vp 200 --num-vp 1 --json -q")
          .out);
  EXPECT_FALSE(off.isMember("exterior"));
  EXPECT_EQ(off["parameters"]["exterior"], Json::Value(false));
  EXPECT_EQ(off["parameters"]["num_rays_per_vp"].asUInt64(), 200u);
}

}  // namespace
}  // namespace occlusion
