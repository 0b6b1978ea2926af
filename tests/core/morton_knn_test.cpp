#include "occlusion/core/morton_knn.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "occlusion/core/morton_order.hpp"
#include "occlusion/core/parallel.hpp"
#include "occlusion/core/random.hpp"

namespace occlusion {
namespace {

using Answer = std::vector<std::uint32_t>;

// Every point against every other: the k smallest (squared distance, index).
Answer brute_force(const std::vector<Eigen::Vector3f>& points, std::size_t query, std::size_t k) {
  std::vector<std::pair<float, std::uint32_t>> all(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    all[i] = {knn_squared_distance(points[query], points[i]), static_cast<std::uint32_t>(i)};
  }
  k = std::min(k, all.size());
  std::partial_sort(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(k), all.end());
  Answer answer(k);
  for (std::size_t j = 0; j < k; ++j) answer[j] = all[j].second;
  return answer;
}

std::vector<Eigen::Vector3f> in_morton_order(const std::vector<Eigen::Vector3f>& points) {
  std::vector<Eigen::Vector3f> sorted;
  for (const std::uint32_t i : morton_order(points)) sorted.push_back(points[i]);
  return sorted;
}

// The search's answer for each query of `subset` (null: every point), on two threads.
std::vector<Answer> search_all(const MortonKnn& knn, const std::vector<std::uint32_t>* subset,
                               std::size_t k) {
  const std::size_t count = subset ? subset->size() : knn.size();
  std::vector<Answer> answers(count);
  std::vector<std::size_t> queries(count);
  parallel_for(count, 97, 2, [&](std::size_t first, std::size_t last) {
    knn.search(subset ? subset->data() : nullptr, first, last, k,
               [&](std::size_t n, std::size_t query, const std::uint32_t* ids, std::size_t got) {
                 answers[n].assign(ids, ids + got);
                 queries[n] = query;
               });
  });
  for (std::size_t n = 0; n < count; ++n) {
    EXPECT_EQ(queries[n], subset ? (*subset)[n] : n);
  }
  return answers;
}

void expect_exact(const std::vector<Eigen::Vector3f>& cloud, std::size_t k) {
  const std::vector<Eigen::Vector3f> points = in_morton_order(cloud);
  const MortonKnn knn(points, 2);
  const std::vector<Answer> answers = search_all(knn, nullptr, k);
  std::size_t wrong = 0;
  for (std::size_t q = 0; q < points.size(); ++q) {
    if (answers[q] != brute_force(points, q, k)) ++wrong;
  }
  EXPECT_EQ(wrong, 0u) << "of " << points.size() << " queries, k = " << k;
}

Eigen::Vector3f uniform_in(Rng& rng, const Eigen::Vector3f& lo, const Eigen::Vector3f& hi) {
  return Eigen::Vector3f(static_cast<float>(lo.x() + (hi.x() - lo.x()) * rng.uniform()),
                         static_cast<float>(lo.y() + (hi.y() - lo.y()) * rng.uniform()),
                         static_cast<float>(lo.z() + (hi.z() - lo.z()) * rng.uniform()));
}

TEST(MortonKnn, RandomPointsInACube) {
  Rng rng(1);
  std::vector<Eigen::Vector3f> cloud;
  for (int i = 0; i < 6000; ++i) {
    cloud.push_back(uniform_in(rng, Eigen::Vector3f(-2, -1, 0), Eigen::Vector3f(3, 1, 0.5)));
  }
  expect_exact(cloud, 17);
  expect_exact(cloud, 1);
  expect_exact(cloud, 65);
}

// A terrestrial scan's floor: the density falls a hundredfold with range, with
// points stored several times (some more than k times) and stray points far
// off in the air.
TEST(MortonKnn, FallingDensityDuplicatesAndStrayPoints) {
  Rng rng(2);
  std::vector<Eigen::Vector3f> cloud;
  while (cloud.size() < 8000) {
    const Eigen::Vector3f p = uniform_in(rng, Eigen::Vector3f(0, 0, 0), Eigen::Vector3f(20, 5, 0));
    // Density ~ 1 / (1 + x)^1.5: from 1 at x = 0 to about 1/100 at x = 20.
    if (rng.uniform() < std::pow(1.0 + p.x(), -1.5)) cloud.push_back(p);
  }
  for (int i = 0; i < 200; ++i) {
    const std::size_t copies = i < 5 ? 30 : 1 + i % 3;
    const Eigen::Vector3f p = cloud[static_cast<std::size_t>(i) * 37];
    for (std::size_t c = 0; c < copies; ++c) cloud.push_back(p);
  }
  for (int i = 0; i < 40; ++i) {
    cloud.push_back(
        uniform_in(rng, Eigen::Vector3f(-500, -500, 3), Eigen::Vector3f(500, 500, 900)));
  }
  expect_exact(cloud, 17);
  expect_exact(cloud, 65);
}

// A regular grid: many neighbours at exactly equal distances, which the
// index decides.
TEST(MortonKnn, RegularGridTiesGoByIndex) {
  std::vector<Eigen::Vector3f> cloud;
  for (int i = 0; i < 60; ++i) {
    for (int j = 0; j < 50; ++j) {
      cloud.emplace_back(0.01f * static_cast<float>(i), 0.05f * static_cast<float>(j), 1.0f);
      if (i % 3 == 0 && j % 2 == 0) {
        cloud.emplace_back(0.01f * static_cast<float>(i), 1.0f, 0.02f * static_cast<float>(j));
      }
    }
  }
  expect_exact(cloud, 17);
  expect_exact(cloud, 8);
}

TEST(MortonKnn, SubsetOfQueries) {
  Rng rng(3);
  std::vector<Eigen::Vector3f> cloud;
  for (int i = 0; i < 5000; ++i) {
    const double r = 1.0 + 10.0 * rng.uniform() * rng.uniform();  // denser near the middle
    const double a = 6.283185307179586 * rng.uniform();
    cloud.emplace_back(static_cast<float>(r * std::cos(a)), static_cast<float>(r * std::sin(a)),
                       static_cast<float>(0.3 * rng.uniform()));
  }
  const std::vector<Eigen::Vector3f> points = in_morton_order(cloud);
  const MortonKnn knn(points, 2);
  std::vector<std::uint32_t> subset;
  for (std::uint32_t i = 0; i < points.size(); i += 1 + (i % 7)) subset.push_back(i);
  const std::vector<Answer> answers = search_all(knn, &subset, 33);
  for (std::size_t n = 0; n < subset.size(); ++n) {
    ASSERT_EQ(answers[n], brute_force(points, subset[n], 33)) << "query " << subset[n];
  }
}

TEST(MortonKnn, FewerPointsThanAsked) {
  for (std::size_t count = 1; count <= 40; count += 13) {
    Rng rng(count);
    std::vector<Eigen::Vector3f> cloud;
    for (std::size_t i = 0; i < count; ++i) {
      cloud.push_back(uniform_in(rng, Eigen::Vector3f::Zero(), Eigen::Vector3f::Ones()));
    }
    const std::vector<Eigen::Vector3f> points = in_morton_order(cloud);
    const MortonKnn knn(points, 1);
    const std::vector<Answer> answers = search_all(knn, nullptr, 17);
    for (std::size_t q = 0; q < count; ++q) {
      ASSERT_EQ(answers[q].size(), std::min<std::size_t>(count, 17));
      EXPECT_EQ(answers[q], brute_force(points, q, 17));
    }
  }
}

TEST(MortonKnn, AllPointsCoincide) {
  const std::vector<Eigen::Vector3f> points(50, Eigen::Vector3f(1, 2, 3));
  const MortonKnn knn(points, 1);
  const std::vector<Answer> answers = search_all(knn, nullptr, 5);
  // Equal distances everywhere: the five smallest indices.
  for (const Answer& answer : answers) EXPECT_EQ(answer, (Answer{0, 1, 2, 3, 4}));
}

TEST(MortonKnn, RefusesPointsThatAreNotFinite) {
  std::vector<Eigen::Vector3f> points(20, Eigen::Vector3f::Zero());
  points[7].y() = std::nanf("");
  EXPECT_THROW(MortonKnn knn(points), std::invalid_argument);
}

}  // namespace
}  // namespace occlusion
