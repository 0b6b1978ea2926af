#include "occlusion/analysis/clustered_inference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "occlusion/analysis/correlation.hpp"
#include "occlusion/core/random.hpp"

namespace occlusion {
namespace {

TEST(ClusteredInference, WithinSceneSlopeIgnoresWhatDiffersBetweenScenes) {
  // Scene 0: x 0, 1, 2 with y 1, 0.9, 0.8; scene 1: x 10, 11 with y 5, 4.8.
  // Centred: sxy = -0.2 - 0.1, sxx = 2 + 0.5, so the slope is -0.12, while
  // the scene with more of x has more of y and the pooled r is positive.
  const std::vector<double> x = {0, 1, 2, 10, 11};
  const std::vector<double> y = {1, 0.9, 0.8, 5, 4.8};
  const std::vector<std::size_t> scene = {7, 7, 7, 3, 3};
  ASSERT_TRUE(within_scene_slope(x, y, scene));
  EXPECT_NEAR(*within_scene_slope(x, y, scene), -0.12, 1e-12);
  EXPECT_GT(*pearson_correlation(x, y), 0.9);
}

TEST(ClusteredInference, NothingToEstimateWhenEverySceneHasOneRun) {
  const std::vector<double> x = {0.1, 0.2, 0.3, 0.4};
  const std::vector<double> y = {0.9, 0.8, 0.7, 0.6};
  const std::vector<std::size_t> scene = {0, 1, 2, 3};
  EXPECT_FALSE(within_scene_slope(x, y, scene));
  const ClusteredAssociation a = clustered_association(x, y, scene, {200, 200, 1});
  EXPECT_EQ(a.runs, 4u);
  EXPECT_EQ(a.scenes, 4u);
  ASSERT_TRUE(a.pearson.value);
  EXPECT_NEAR(*a.pearson.value, -1.0, 1e-12);
  // Four scenes are too few for an interval, and no shuffle within a scene
  // can change anything.
  EXPECT_FALSE(a.pearson.interval95);
  EXPECT_FALSE(a.pearson.p_value);
  EXPECT_FALSE(a.within_scene_slope.value);
}

TEST(ClusteredInference, PermutationPValueMatchesTheCountOfEqualOrderings) {
  // One scene, x = y = 1, 2, 3: of the 6 orderings of x, the identity gives
  // r = 1 and the reversal r = -1, so |r| >= 1 for a third of them:
  // p = (1 + P / 3) / (1 + P).
  const std::vector<double> x = {1, 2, 3};
  const ClusteredAssociation a = clustered_association(x, x, {0, 0, 0}, {100, 6000, 5});
  ASSERT_TRUE(a.pearson.p_value);
  EXPECT_NEAR(*a.pearson.p_value, 1.0 / 3.0, 0.02);
  ASSERT_TRUE(a.spearman.p_value);
  EXPECT_NEAR(*a.spearman.p_value, 1.0 / 3.0, 0.02);
  EXPECT_FALSE(a.pearson.interval95);  // one scene
}

// Ten scenes of six runs: y = slope x + the scene's own level + noise.
struct Study {
  std::vector<double> x, y;
  std::vector<std::size_t> scene;
};
Study simulated(double slope, double noise, std::uint64_t seed) {
  Study s;
  Rng random(seed);
  for (std::size_t k = 0; k < 10; ++k) {
    const double level = random.uniform();
    for (int run = 0; run < 6; ++run) {
      const double x = 0.2 + 0.6 * random.uniform();
      s.x.push_back(x);
      s.y.push_back(level + slope * x + noise * (random.uniform() - 0.5));
      s.scene.push_back(k);
    }
  }
  return s;
}

TEST(ClusteredInference, AnEffectGetsAnIntervalAroundItThatExcludesZero) {
  const Study s = simulated(-0.5, 0.05, 3);
  const ClusteredAssociation a = clustered_association(s.x, s.y, s.scene);
  EXPECT_EQ(a.scenes, 10u);
  EXPECT_EQ(a.runs, 60u);
  ASSERT_TRUE(a.within_scene_slope.value);
  EXPECT_NEAR(*a.within_scene_slope.value, -0.5, 0.05);
  ASSERT_TRUE(a.within_scene_slope.interval95);
  EXPECT_LT(a.within_scene_slope.interval95->lo, -0.5 + 0.02);
  EXPECT_GT(a.within_scene_slope.interval95->hi, -0.5 - 0.02);
  EXPECT_LT(a.within_scene_slope.interval95->hi, 0.0);
  ASSERT_TRUE(a.within_scene_slope.p_value);
  EXPECT_LE(*a.within_scene_slope.p_value, 2.0 / 2001.0);
  // The same seed gives the same figures.
  const ClusteredAssociation again = clustered_association(s.x, s.y, s.scene);
  EXPECT_EQ(again.within_scene_slope.interval95->lo, a.within_scene_slope.interval95->lo);
  EXPECT_EQ(again.pearson.p_value, a.pearson.p_value);
}

TEST(ClusteredInference, WithoutAnEffectFalseAlarmsStayNearFivePercent) {
  // Under no effect, p < 0.05 should come up in about 5 % of studies and the
  // slope's interval should hold 0 in about 95 %.
  int alarms = 0, covered = 0;
  const int studies = 200;
  for (int k = 0; k < studies; ++k) {
    const Study s = simulated(0.0, 0.2, 100 + static_cast<std::uint64_t>(k));
    const ClusteredAssociation a =
        clustered_association(s.x, s.y, s.scene, {400, 400, static_cast<std::uint64_t>(k)});
    alarms += *a.within_scene_slope.p_value < 0.05;
    covered +=
        a.within_scene_slope.interval95->lo <= 0.0 && a.within_scene_slope.interval95->hi >= 0.0;
  }
  EXPECT_LE(alarms, 20) << "of " << studies;    // 10 expected
  EXPECT_GE(covered, 170) << "of " << studies;  // 190 expected
}

TEST(ClusteredInference, PairedSlopesAndTheirDifferenceByHand) {
  // First study: scene 0 x 0, 1 with y 1, 0 (sxx 0.5, sxy -0.5); scene 1
  // x 0, 2 with y 1, 0 (sxx 2, sxy -1): slope -1.5 / 2.5 = -0.6.
  // Second, its own x: scene 0 x 0, 1 with y 1, 0.5 (sxx 0.5, sxy -0.25);
  // scene 1 x 0, 1 with y 1, 0.8 (sxx 0.5, sxy -0.1): slope -0.35.
  // Difference, second - first: 0.25. Two scenes: no interval.
  const std::vector<std::size_t> scene = {4, 4, 9, 9};
  const PairedSlopes paired =
      paired_slopes({0, 1, 0, 2}, {1, 0, 1, 0}, {0, 1, 0, 1}, {1, 0.5, 1, 0.8}, scene, {200, 1, 1});
  EXPECT_EQ(paired.runs, 4u);
  EXPECT_EQ(paired.scenes, 2u);
  ASSERT_TRUE(paired.first.value && paired.second.value && paired.difference.value);
  EXPECT_NEAR(*paired.first.value, -0.6, 1e-12);
  EXPECT_NEAR(*paired.second.value, -0.35, 1e-12);
  EXPECT_NEAR(*paired.difference.value, 0.25, 1e-12);
  EXPECT_FALSE(paired.difference.interval95);
  EXPECT_THROW(paired_slopes({0, 1}, {1, 0}, {0}, {1}, {0, 0}), std::invalid_argument);
}

TEST(ClusteredInference, PairedDifferenceKeepsThePairingThatEachSlopeVariesOver) {
  // Eight scenes whose slopes differ widely; the second study's mIoU is the
  // first's plus 0.3 x in every run, so every draw of scenes gives slopes
  // 0.3 apart: the difference's interval is that point, while each slope's
  // spans the scenes' spread. Drawn unpaired it would be as wide as theirs.
  std::vector<double> x, y_first, y_second;
  std::vector<std::size_t> scene;
  for (std::size_t s = 0; s < 8; ++s) {
    for (const double level : {0.0, 0.5, 1.0}) {
      x.push_back(level + 0.1 * static_cast<double>(s));
      y_first.push_back(0.7 - (0.1 + 0.1 * static_cast<double>(s)) * x.back());
      y_second.push_back(y_first.back() + 0.3 * x.back());
      scene.push_back(s);
    }
  }
  const InferenceOptions options{500, 1, 3};
  const PairedSlopes paired = paired_slopes(x, y_first, x, y_second, scene, options);
  ASSERT_TRUE(paired.difference.interval95 && paired.first.interval95);
  EXPECT_NEAR(*paired.difference.value, 0.3, 1e-12);
  EXPECT_NEAR(paired.difference.interval95->lo, 0.3, 1e-12);
  EXPECT_NEAR(paired.difference.interval95->hi, 0.3, 1e-12);
  EXPECT_GT(paired.first.interval95->hi - paired.first.interval95->lo, 0.2);
  // Each slope's interval is the one the study's own table gives.
  const ClusteredAssociation alone = clustered_association(x, y_first, scene, options);
  ASSERT_TRUE(alone.within_scene_slope.interval95);
  EXPECT_EQ(alone.within_scene_slope.interval95->lo, paired.first.interval95->lo);
  EXPECT_EQ(alone.within_scene_slope.interval95->hi, paired.first.interval95->hi);
}

TEST(ClusteredInference, RefusesBadInput) {
  const std::vector<double> x = {1, 2, 3};
  EXPECT_THROW(clustered_association(x, x, {0, 0}), std::invalid_argument);
  EXPECT_THROW(clustered_association(x, {1, 2}, {0, 0, 0}), std::invalid_argument);
  EXPECT_THROW(clustered_association(x, {1, 2, std::numeric_limits<double>::infinity()}, {0, 0, 0}),
               std::invalid_argument);
  EXPECT_THROW(clustered_association(x, x, {0, 0, 0}, {0, 10, 1}), std::invalid_argument);
}

}  // namespace
}  // namespace occlusion
