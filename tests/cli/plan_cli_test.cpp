// plan end to end (issue 41): a target beyond what the candidates can see
// says what was asked, what can be reached and what was chosen, in text and
// JSON; the refinement's figures come with it; a plan no candidate is free
// for is refused with advice, exit code non-zero.

#include <gtest/gtest.h>

#include <string>

#include "occlusion/io/obj_writer.hpp"
#include "run_cli.hpp"
#include "support/plan_scenes.hpp"

namespace occlusion {
namespace {

using testing::run_cli;
using testing::run_json;
using testing::TempDir;

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// A 4 x 4 room and, beside it, a closed crate no station can see.
std::string room_and_crate(const TempDir& dir) {
  TriangleMesh mesh = testing::empty_room();
  testing::add_facing_box(mesh, {5, 0, 0}, {6, 1, 1}, false, "crate");
  const std::string path = dir.file("room_and_crate.obj");
  write_obj(path, mesh);
  return "'" + path + "'";
}

TEST(PlanCli, ATargetOutOfReachSaysWhatWasAskedReachableAndChosen) {
  const TempDir dir;
  const std::string scene = room_and_crate(dir);
  const std::string ask = "plan " + scene + " --target-coverage 0.99 --samples-per-unit-area 20";
  const auto text = run_cli(ask);
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_TRUE(has(text.out, "the fewest new stations for 99.0 %: NOT reachable")) << text.out;
  EXPECT_TRUE(has(text.out, "chosen      most: aimed at")) << text.out;
  EXPECT_TRUE(has(text.out, "(all that can be reached)")) << text.out;
  EXPECT_TRUE(has(text.out, "spacing")) << text.out;

  const Json::Value json = run_json(ask);
  const double reachable = json["reachable_coverage"].asDouble();
  // The room's 4 x 4 x 3 box (80 m^2) of the 86 m^2 with the crate.
  EXPECT_NEAR(reachable, 80.0 / 86.0, 0.02);
  EXPECT_DOUBLE_EQ(json["aimed_coverage"].asDouble(), reachable);
  EXPECT_NEAR(json["coverage"].asDouble(), reachable, 1e-9);
  EXPECT_EQ(json["out_of_reach"]["chosen"].asString(), "most");
  EXPECT_DOUBLE_EQ(json["out_of_reach"]["share_coverage"].asDouble(), 0.99 * reachable);
  EXPECT_GE(json["out_of_reach"]["share_reached_by_first_new_stations"].asUInt64(), 1u);
  const Json::Value& refinement = json["refinement"];
  ASSERT_TRUE(refinement.isObject()) << refinement;
  EXPECT_LE(refinement["positions_traced"].asUInt64(), refinement["positions_budget"].asUInt64());
  EXPECT_GE(refinement["coverage_after"].asDouble(), refinement["coverage_before"].asDouble());
  EXPECT_TRUE(json["candidates"]["spacing_auto"].asBool());

  EXPECT_EQ(json["out_of_reach"]["most_reached_by_new_stations"].asUInt64(),
            json["stations"].size());
  EXPECT_TRUE(has(text.out, "the choice  all")) << text.out;

  const Json::Value share = run_json(ask + " --out-of-reach share");
  EXPECT_EQ(share["out_of_reach"]["chosen"].asString(), "share");
  EXPECT_DOUBLE_EQ(share["aimed_coverage"].asDouble(), 0.99 * reachable);
  // The most takes at least the stations the share takes.
  EXPECT_GE(share["out_of_reach"]["most_reached_by_new_stations"].asUInt64(),
            share["stations"].size());
}

TEST(PlanCli, NoFreeCandidateIsRefusedSayingWhatToDo) {
  const TempDir dir;
  const auto run = run_cli("plan " + room_and_crate(dir) +
                           " --stations 1 --clearance 5 --samples-per-unit-area 5");
  EXPECT_NE(run.exit_code, 0);
  EXPECT_TRUE(has(run.err, "no candidate position is free")) << run.err;
  EXPECT_TRUE(has(run.err, "lower --clearance")) << run.err;
}

}  // namespace
}  // namespace occlusion
