// `occlusion -moc` end to end: exit codes, JSON output, config files, outputs.

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

const std::string kSource = OCCLUSION_SOURCE_DIR;
const std::string kCornell = "'" + kSource + "/files/cornell_box/CornellBox-Original.obj'";

TEST(Cli, HelpAndUsage) {
  const CliRun help = run_cli("--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("-moc"), std::string::npos);
  const CliRun moc_help = run_cli("-moc --help");
  EXPECT_EQ(moc_help.exit_code, 0);
  EXPECT_NE(moc_help.out.find("--samples-per-unit-area"), std::string::npos);
  EXPECT_EQ(run_cli("").exit_code, 2);
  const CliRun unknown = run_cli("-frobnicate x");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("unknown command"), std::string::npos);
}

TEST(Cli, JsonIsOneObjectWithTheHeadline) {
  const CliRun run =
      run_cli("-moc " + kCornell + " --pattern 1 --samples-per-unit-area 200 --seed 3 --json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Json::Value json = parse_json(run.out);
  EXPECT_EQ(json["job"].asString(), "mesh_occlusion");
  const double level = json["occlusion_level"].asDouble();
  EXPECT_GT(level, 0.0);
  EXPECT_LT(level, 1.0);
  EXPECT_EQ(json["faces"].asUInt64(), 36u);
  ASSERT_EQ(json["viewpoints"].size(), 1u);
  EXPECT_EQ(json["viewpoints"][0]["name"].asString(), "centre");
  EXPECT_NEAR(json["viewpoints"][0]["visible_fraction"].asDouble(), 1 - level, 1e-12);
  EXPECT_EQ(json["parameters"]["seed"].asUInt64(), 3u);
  // Progress goes to stderr, never into the JSON.
  EXPECT_NE(run.err.find("[moc] tracing"), std::string::npos);
  // Same seed, same answer.
  const CliRun again =
      run_cli("-moc " + kCornell + " --pattern 1 --samples-per-unit-area 200 --seed 3 --json -q");
  EXPECT_EQ(parse_json(again.out)["occlusion_level"].asDouble(), level);
  EXPECT_TRUE(again.err.empty()) << again.err;
}

TEST(Cli, ExplicitViewpoints) {
  const CliRun run = run_cli("-moc " + kCornell +
                             " --viewpoint 0,1,0.5 --viewpoint 0.5,1.5,-0.5 --json -q "
                             "--samples-per-unit-area 100");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Json::Value json = parse_json(run.out);
  ASSERT_EQ(json["viewpoints"].size(), 2u);
  EXPECT_EQ(json["viewpoints"][1]["position"][2].asDouble(), -0.5);
  EXPECT_TRUE(json["parameters"]["pattern"].isNull());
}

TEST(Cli, ViewpointInsideAClosedSolidIsWarnedAbout) {
  const TempDir dir;
  // The unit cube, every face's normal (e1 x e2) pointing out.
  dir.write("cube.obj",
            "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
            "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\n"
            "f 4 8 7\nf 4 7 3\nf 1 5 8\nf 1 8 4\nf 2 3 7\nf 2 7 6\n");
  const std::string moc = "-moc '" + dir.file("cube.obj") + "' --json -q --viewpoint ";
  const CliRun inside = run_cli(moc + "0.5,0.4,0.6");
  ASSERT_EQ(inside.exit_code, 0) << inside.err;
  const Json::Value warnings = parse_json(inside.out)["warnings"];
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].asString().find("100 % of its rays first hit the back of a face"),
            std::string::npos)
      << warnings[0].asString();
  const CliRun outside = run_cli(moc + "3,0.4,0.6");
  ASSERT_EQ(outside.exit_code, 0) << outside.err;
  EXPECT_EQ(parse_json(outside.out)["warnings"].size(), 0u) << outside.out;
}

TEST(Cli, InputErrorsExitThree) {
  const CliRun missing = run_cli("-moc /nonexistent/room.obj");
  EXPECT_EQ(missing.exit_code, 3);
  EXPECT_NE(missing.err.find("/nonexistent/room.obj"), std::string::npos);

  const TempDir dir;
  dir.write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
  const CliRun bad = run_cli("-moc '" + dir.file("bad.obj") + "'");
  EXPECT_EQ(bad.exit_code, 3);
  EXPECT_NE(bad.err.find("bad.obj:4"), std::string::npos) << bad.err;
}

// A vertex line with text after its numbers, or statements separated by a
// lone CR, answered for another mesh with exit 0.
TEST(Cli, VertexLinesWithJunkExitThreeAndLoneCrEndsALine) {
  const TempDir dir;
  dir.write("junk.obj", "v 0 0 0\nv 1 0 0 hello world\nv 0 1 0\nf 1 2 3\n");
  const CliRun junk = run_cli("-moc '" + dir.file("junk.obj") + "' -q");
  EXPECT_EQ(junk.exit_code, 3);
  EXPECT_NE(junk.err.find("junk.obj:2: vertex has 'hello'"), std::string::npos) << junk.err;
  // Two triangles of a unit square; the second's vertices follow CRs.
  dir.write("mac.obj", "v 0 0 0\nv 1 0 0\rv 1 1 0\rv 0 1 0\nf 1 2 3\nf 1 3 4\n");
  const Json::Value json = run_json("-moc '" + dir.file("mac.obj") + "' --viewpoint 0.5,0.5,1");
  EXPECT_EQ(json["faces"].asUInt64(), 2u);
  EXPECT_NEAR(json["total_area"].asDouble(), 1.0, 1e-12);
}

// Samples are counted before any is drawn: legs of 1e10 gave 0 samples and a
// null level with exit 0, legs of 1e9 an internal length error. Refused
// (usage, exit 2) with the count and the key to lower, budget or none.
TEST(Cli, SampleCountBeyondMemoryIsRefusedUpFront) {
  const TempDir dir;
  for (const std::string leg : {"1e10", "1e9", "1e5"}) {
    dir.write("huge.obj", "v 0 0 0\nv " + leg + " 0 0\nv 0 " + leg + " 0\nf 1 2 3\n");
    const CliRun run = run_cli("-moc '" + dir.file("huge.obj") + "' --pattern 1 -q");
    EXPECT_EQ(run.exit_code, 2) << leg << ": " << run.err;
    EXPECT_NE(run.err.find(" samples x 1 viewpoints"), std::string::npos) << leg << run.err;
    EXPECT_NE(run.err.find("lower samples_per_unit_area"), std::string::npos) << leg << run.err;
  }
  const CliRun budget = run_cli("-moc '" + dir.file("huge.obj") +
                                "' --pattern 1 -q --samples-per-unit-area 0.01 --max-memory-mb 1");
  EXPECT_EQ(budget.exit_code, 2) << budget.err;
  EXPECT_NE(budget.err.find("50,000,000 samples"), std::string::npos) << budget.err;
  EXPECT_NE(budget.err.find("max_memory_mb = 1"), std::string::npos) << budget.err;
}

TEST(Cli, UsageErrorsExitTwo) {
  for (const std::string args :
       {"-moc", "-moc x.obj --pattern 9", "-moc x.obj --pattern", "-moc x.obj --seed abc",
        "-moc x.obj --viewpoint 1,2", "-moc x.obj --viewpoint 1,2,z",
        "-moc x.obj --pattern 1 --viewpoint 1,2,3", "-moc x.obj --samples-per-unit-area 0",
        "-moc x.obj --octree-resolution -1", "-moc x.obj --enable-acceleration maybe",
        "-moc x.obj --bogus", "-moc x.obj y.obj"}) {
    const CliRun run = run_cli(args);
    EXPECT_EQ(run.exit_code, 2) << args << ": " << run.err;
    EXPECT_FALSE(run.err.empty()) << args;
  }
}

TEST(Cli, ConfigErrorsNameTheKey) {
  const TempDir dir;
  dir.write("unknown.json", R"({"occlusion": {"mesh": {"path": "a.obj", "sampels": 3}}})");
  const CliRun unknown = run_cli("-moc --config '" + dir.file("unknown.json") + "'");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("occlusion.mesh.sampels"), std::string::npos) << unknown.err;

  dir.write("type.json", R"({"occlusion": {"mesh": {"pattern": "four"}}})");
  const CliRun type = run_cli("-moc --config '" + dir.file("type.json") + "'");
  EXPECT_EQ(type.exit_code, 2);
  EXPECT_NE(type.err.find("occlusion.mesh.pattern"), std::string::npos) << type.err;

  dir.write("broken.json", R"({"occlusion": )");
  EXPECT_EQ(run_cli("-moc --config '" + dir.file("broken.json") + "'").exit_code, 2);
  EXPECT_EQ(run_cli("-moc --config '" + dir.file("absent.json") + "'").exit_code, 2);
}

TEST(Cli, ConfigRunsAndOptionsOverrideIt) {
  const std::string config = "'" + kSource + "/config/cornell_box.json'";
  const CliRun from_config = run_cli("-moc --config " + config + " --json -q");
  ASSERT_EQ(from_config.exit_code, 0) << from_config.err;
  const Json::Value a = parse_json(from_config.out);
  EXPECT_EQ(a["parameters"]["pattern"].asInt(), 1);
  EXPECT_EQ(a["parameters"]["samples_per_unit_area"].asDouble(), 2000.0);
  EXPECT_EQ(a["parameters"]["seed"].asUInt64(), 1u);

  const CliRun overridden =
      run_cli("-moc --pattern 7 --config " + config + " --samples-per-unit-area 50 --json -q");
  ASSERT_EQ(overridden.exit_code, 0) << overridden.err;
  const Json::Value b = parse_json(overridden.out);
  EXPECT_EQ(b["parameters"]["pattern"].asInt(), 7);
  EXPECT_EQ(b["viewpoints"].size(), 3u);
  EXPECT_EQ(b["parameters"]["samples_per_unit_area"].asDouble(), 50.0);
}

TEST(Cli, ExampleConfigRuns) {
  const CliRun run = run_cli("-moc --config '" + kSource + "/config/example.json' --json -q");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_GT(parse_json(run.out)["faces"].asUInt64(), 1000u);
}

TEST(Cli, OutWritesJsonPlyAndCsvAtomically) {
  const TempDir dir;
  const std::string out = dir.file("results");
  for (int round = 0; round < 2; ++round) {  // the second round replaces the first
    const CliRun run = run_cli("-moc " + kCornell + " --samples-per-unit-area 50 -q --out '" + out +
                               "' --seed " + std::to_string(round));
    ASSERT_EQ(run.exit_code, 0) << run.err;
  }
  const std::string json_text = testing::read_text(out + "/CornellBox-Original.moc.json");
  EXPECT_EQ(parse_json(json_text)["parameters"]["seed"].asUInt64(), 1u);
  EXPECT_EQ(testing::read_text(out + "/CornellBox-Original.moc.ply").rfind("ply\n", 0), 0u);
  const std::string csv = testing::read_text(out + "/CornellBox-Original.moc.csv");
  EXPECT_EQ(csv.rfind("face,group,area,samples,visible_fraction\n", 0), 0u);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 37);
  // Only the three outputs: no temporary files left behind.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(out),
                          std::filesystem::directory_iterator()),
            3);
}

TEST(Cli, OutIntoAFileIsAnError) {
  const TempDir dir;
  dir.write("taken", "precious");
  const CliRun run = run_cli("-moc " + kCornell + " -q --out '" + dir.file("taken") + "'");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("taken"), std::string::npos);
  EXPECT_EQ(testing::read_text(dir.file("taken")), "precious");
}

}  // namespace
}  // namespace occlusion
