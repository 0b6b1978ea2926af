#include "occlusion/analysis/label_transfer.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

#include "occlusion/core/random.hpp"

namespace occlusion {
namespace {

using Points = std::vector<Eigen::Vector3f>;

TEST(LabelTransfer, NearestWithinDistanceAndUnlabelledBeyond) {
  const Points source = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<std::int32_t> labels = {4, 7, -1};
  const Points target = {{0.02f, 0, 0},         // 0.02 from the first
                         {0.97f, 0, 0},         // 0.03 from the second
                         {0, 0.96f, 0},         // the third, which has no label itself
                         {0.4f, 0.45f, 0.5f}};  // 0.78 from the first, farther from the others
  LabelTransferOptions options;
  options.max_distance = 0.05;
  const LabelTransfer result = transfer_labels(source, labels, target, options);
  EXPECT_EQ(result.labels, (std::vector<std::int32_t>{4, 7, -1, -1}));
  EXPECT_EQ(result.beyond_distance, 1u);  // the unlabelled source point is not "beyond"
  EXPECT_NEAR(result.max_matched_distance, 0.04, 1e-6);

  options.max_distance = std::numeric_limits<double>::infinity();
  const LabelTransfer unlimited = transfer_labels(source, labels, target, options);
  EXPECT_EQ(unlimited.beyond_distance, 0u);
  EXPECT_EQ(unlimited.labels[3], 4);
}

TEST(LabelTransfer, MatchesBruteForceOnRandomPoints) {
  Rng rng(7);
  const auto random_point = [&rng] {
    return Eigen::Vector3f(static_cast<float>(rng.uniform()), static_cast<float>(rng.uniform()),
                           static_cast<float>(rng.uniform()));
  };
  Points source, target;
  std::vector<std::int32_t> labels;
  for (int i = 0; i < 2000; ++i) {
    source.push_back(random_point());
    labels.push_back(i);  // the label names the point, so the test sees which one was chosen
  }
  for (int i = 0; i < 3000; ++i) target.push_back(random_point());
  LabelTransferOptions options;
  options.max_distance = 0.04;
  options.threads = 3;
  const LabelTransfer result = transfer_labels(source, labels, target, options);

  std::size_t beyond = 0;
  for (std::size_t t = 0; t < target.size(); ++t) {
    std::size_t best = 0;
    for (std::size_t s = 1; s < source.size(); ++s) {
      if ((source[s] - target[t]).squaredNorm() < (source[best] - target[t]).squaredNorm()) {
        best = s;
      }
    }
    const float distance = (source[best] - target[t]).norm();
    if (distance > 0.04f) {
      ++beyond;
      EXPECT_EQ(result.labels[t], -1) << t;
    } else {
      // A different index is fine only for an exact tie.
      const auto chosen = static_cast<std::size_t>(result.labels[t]);
      EXPECT_FLOAT_EQ((source[chosen] - target[t]).squaredNorm(),
                      (source[best] - target[t]).squaredNorm())
          << t;
    }
  }
  EXPECT_EQ(result.beyond_distance, beyond);
  EXPECT_GT(beyond, 0u);
  EXPECT_LT(beyond, target.size());
}

TEST(LabelTransfer, EmptySourceAndBadArguments) {
  const Points target = {{0, 0, 0}, {1, 1, 1}};
  const LabelTransfer empty = transfer_labels({}, {}, target);
  EXPECT_EQ(empty.labels, (std::vector<std::int32_t>{-1, -1}));
  EXPECT_EQ(empty.beyond_distance, 2u);
  EXPECT_THROW(transfer_labels({{0, 0, 0}}, {}, target), std::invalid_argument);
  LabelTransferOptions zero;
  zero.max_distance = 0.0;
  EXPECT_THROW(transfer_labels({{0, 0, 0}}, {1}, target, zero), std::invalid_argument);
}

}  // namespace
}  // namespace occlusion
