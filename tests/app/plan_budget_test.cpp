// plan's budgets and its cap on candidates are applied before the work they
// bound (issue 44, 2.5): samples of 3e5 per unit area grew to 4.7 GB before
// their work was refused, and a candidates file of a million lines was read
// and filtered whole, then refused naming keys plan does not have.

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <string>

#include "io/scratch_directory.hpp"
#include "occlusion/analysis/mesh_sampling.hpp"
#include "occlusion/analysis/station_candidates.hpp"
#include "occlusion/app/errors.hpp"
#include "occlusion/app/memory_budget.hpp"
#include "occlusion/app/plan_job.hpp"
#include "occlusion/app/work_budget.hpp"
#include "support/plan_request.hpp"
#include "support/plan_scenes.hpp"

namespace occlusion {
namespace {

// The stages a plan reported before it ended.
struct Stages {
  std::set<std::string> seen;
  Progress progress() {
    Progress p;
    p.report = [this](const std::string& stage, double) { seen.insert(stage); };
    return p;
  }
};

void expect_no_target_made(const Stages& stages) {
  for (const char* stage : {"sampling", "surfels", "building octree", "tracing", "selecting"}) {
    EXPECT_EQ(stages.seen.count(stage), 0u) << stage << " ran before the refusal";
  }
}

void expect_only_plan_keys(const std::string& message) {
  for (const char* other : {"pattern", "num_vp", "viewpoints", "num_rays_per_vp"}) {
    EXPECT_EQ(message.find(other), std::string::npos) << other << ": " << message;
  }
}

TEST(PlanBudget, WorkBeyondTheBudgetIsRefusedBeforeAnySampleIsDrawn) {
  PlanRequest request = testing::plan_mesh_request();
  request.samples_per_unit_area = 2000.0;
  request.max_work = 1e-3;  // a million ray steps
  request.spacing = 0.5;    // a grid whose free-space test fits the budget: the samples do not
  Stages stages;
  try {
    plan_mesh(testing::two_rooms(), request, stages.progress());
    FAIL() << "a plan over the work budget ran";
  } catch (const WorkBudgetError& error) {
    const std::string message = error.what();
    for (const char* named :
         {"samples_per_unit_area", "spacing", "candidates file", "max_work", "ray steps"}) {
      EXPECT_NE(message.find(named), std::string::npos) << named << ": " << message;
    }
    expect_only_plan_keys(message);
  }
  expect_no_target_made(stages);
}

// -moc's samples alone fit the budget; with what plan keeps per target and
// the coverage matrix they do not: refused before they are drawn (they were
// drawn, then refused by the matrix's check).
TEST(PlanBudget, MemoryBeyondTheBudgetIsRefusedBeforeAnySampleIsDrawn) {
  const TriangleMesh mesh = testing::two_rooms();
  PlanRequest request = testing::plan_mesh_request();
  request.samples_per_unit_area = 200.0;
  const std::uint64_t samples = total_samples(mesh, request.samples_per_unit_area);
  const std::uint64_t samples_alone = mesh_occlusion_memory(mesh, 200.0, 1).bytes;
  request.max_memory_mb = samples_alone / (1 << 20) + 1;
  ASSERT_GT(plan_memory(mesh_occlusion_memory(mesh, 200.0, 1), samples, 1, false).bytes,
            request.max_memory_mb << 20)
      << "the scene is too small for this test";
  Stages stages;
  try {
    plan_mesh(mesh, request, stages.progress());
    FAIL() << "a plan over the memory budget ran";
  } catch (const UsageError& error) {
    const std::string message = error.what();
    for (const char* named : {"max_memory_mb", "samples_per_unit_area", "spacing"}) {
      EXPECT_NE(message.find(named), std::string::npos) << named << ": " << message;
    }
    expect_only_plan_keys(message);
  }
  expect_no_target_made(stages);
}

// A point model is a cloud's targets: it is not made for a plan refused.
TEST(PlanBudget, ACloudsPlanBeyondTheBudgetIsRefusedBeforeItsPointModel) {
  PointCloud cloud;
  for (int i = 0; i <= 40; ++i) {
    for (int j = 0; j <= 40; ++j) {
      cloud.positions.emplace_back(0.1f * i, 0.1f * j, 0.0f);
      cloud.positions.emplace_back(0.1f * i, 0.0f, 0.1f * j);
      cloud.positions.emplace_back(0.1f * i, 4.0f, 0.1f * j);
      cloud.positions.emplace_back(0.0f, 0.1f * i, 0.1f * j);
      cloud.positions.emplace_back(4.0f, 0.1f * i, 0.1f * j);
      cloud.positions.emplace_back(0.1f * i, 0.1f * j, 4.0f);
    }
  }
  PlanRequest request;
  request.path = "<cloud>";
  request.max_work = 1e-6;
  Stages stages;
  try {
    plan_cloud(cloud, request, stages.progress());
    FAIL() << "a plan over the work budget ran";
  } catch (const WorkBudgetError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("spacing"), std::string::npos) << message;
    expect_only_plan_keys(message);
  }
  expect_no_target_made(stages);
}

// The free-space filter probes every grid position with hundreds of rays and
// tests its clearance against every face: a fine grid is refused before it
// is filtered (100,000 positions took 30 s, then were refused for their
// coverage's work).
TEST(PlanBudget, AFilterBeyondTheBudgetIsRefusedBeforeItRuns) {
  PlanRequest request = testing::plan_mesh_request();
  request.spacing = 0.05;  // 20,301 positions
  request.max_work = 0.01;
  Stages stages;
  try {
    plan_mesh(testing::two_rooms(), request, stages.progress());
    FAIL() << "a plan over the work budget ran";
  } catch (const WorkBudgetError& error) {
    const std::string message = error.what();
    for (const char* named : {"free-space probes", "face tests", "spacing", "candidates file"}) {
      EXPECT_NE(message.find(named), std::string::npos) << named << ": " << message;
    }
    expect_only_plan_keys(message);
  }
  for (const char* stage : {"clearance", "candidates"}) {
    EXPECT_EQ(stages.seen.count(stage), 0u) << stage << " ran before the refusal";
  }
  expect_no_target_made(stages);
}

// A position a line, `count` of them spread over the floor of room A.
void write_positions(const std::string& path, std::size_t count, const std::string& after) {
  std::ofstream out(path);
  for (std::size_t i = 0; i < count; ++i) {
    out << 0.5 + 5.0 * static_cast<double>(i % 1000) / 1000.0 << ' '
        << 0.5 + 4.0 * static_cast<double>(i / 1000) / 1000.0 << " 1.5\n";
  }
  out << after;
}

// The file is refused as a grid that large is, naming the cap, and read no
// further than the cap: a bad line after it is never reached.
TEST(PlanBudget, ACandidatesFileBeyondTheCapIsRefusedWithoutReadingItWhole) {
  testing::ScratchDirectory dir;
  const std::string file = dir.file("many.txt");
  write_positions(file, kMaxCandidates + 1, "not a position\n");
  PlanRequest request = testing::plan_mesh_request();
  request.candidates_path = file;
  request.max_work = 1e-3;  // refused for its work had it been read
  Stages stages;
  try {
    plan_mesh(testing::two_rooms(), request, stages.progress());
    FAIL() << "a plan of more candidates than the cap ran";
  } catch (const KeyError& error) {
    EXPECT_EQ(error.key, "candidates") << error.what();
    const std::string message = error.what();
    EXPECT_NE(message.find("more than " + std::to_string(kMaxCandidates)), std::string::npos)
        << message;
  }
  EXPECT_EQ(stages.seen.count("candidates"), 0u) << "the candidates were filtered";
  expect_no_target_made(stages);
}

}  // namespace
}  // namespace occlusion
