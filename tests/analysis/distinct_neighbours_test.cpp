#include "occlusion/analysis/distinct_neighbours.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "occlusion/core/morton_knn.hpp"

namespace occlusion {
namespace {

constexpr std::uint32_t kCap = 8;

// What a kd-tree's k = kCap nearest say, by sorting every distance.
DistinctNeighbour brute_force(const std::vector<Eigen::Vector3f>& positions, std::size_t q,
                              double same) {
  std::vector<float> squared;
  for (const Eigen::Vector3f& p : positions) {
    squared.push_back(knn_squared_distance(positions[q], p));
  }
  std::sort(squared.begin(), squared.end());
  DistinctNeighbour answer{0, std::numeric_limits<float>::infinity()};
  for (std::size_t k = 0; k < std::min<std::size_t>(kCap, squared.size()); ++k) {
    if (std::sqrt(static_cast<double>(squared[k])) <= same) {
      ++answer.coincident;
      continue;
    }
    answer.nearest_squared = squared[k];
    break;
  }
  return answer;
}

void expect_brute_force_answers(const std::vector<Eigen::Vector3f>& positions, double same) {
  std::vector<std::size_t> queries;
  for (std::size_t i = 0; i < positions.size(); i += 7) queries.push_back(i);
  const std::vector<double> sames(queries.size(), same);
  const auto found = distinct_neighbours(positions, queries, sames, kCap, 2);
  ASSERT_EQ(found.size(), queries.size());
  for (std::size_t k = 0; k < queries.size(); ++k) {
    const DistinctNeighbour expected = brute_force(positions, queries[k], same);
    EXPECT_EQ(found[k].coincident, expected.coincident) << "query " << queries[k];
    // Bit for bit: the same float sums.
    EXPECT_EQ(found[k].nearest_squared, expected.nearest_squared) << "query " << queries[k];
  }
}

TEST(DistinctNeighbours, EqualBruteForceOnARoomWithDuplicatesAndStrays) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<Eigen::Vector3f> positions;
  // A dense floor and a sparser wall.
  for (int i = 0; i < 3000; ++i) positions.emplace_back(4 * unit(random), 3 * unit(random), 0.0f);
  for (int i = 0; i < 600; ++i) positions.emplace_back(0.0f, 3 * unit(random), 2.5f * unit(random));
  // Points stored twice, and one stored twelve times (beyond the cap).
  for (int i = 0; i < 300; ++i) positions.push_back(positions[static_cast<std::size_t>(i * 5)]);
  for (int i = 0; i < 11; ++i) positions.push_back(positions[14]);
  // Strays, near and very far; a pair far out, close to each other.
  for (int i = 0; i < 20; ++i) positions.emplace_back(10.0f + 30.0f * unit(random), -8.0f, 4.0f);
  positions.emplace_back(900.0f, 900.0f, 900.0f);
  positions.emplace_back(900.0f, 900.0f, 900.5f);
  std::shuffle(positions.begin(), positions.end(), random);
  expect_brute_force_answers(positions, 1e-6);
  // A `same` that swallows near neighbours: answers move to the next distinct ones.
  expect_brute_force_answers(positions, 0.02);
}

TEST(DistinctNeighbours, FewPointsAndCoincidentClouds) {
  expect_brute_force_answers({Eigen::Vector3f(1, 2, 3), Eigen::Vector3f(1, 2, 4)}, 1e-6);
  expect_brute_force_answers(std::vector<Eigen::Vector3f>(5, Eigen::Vector3f(1, 2, 3)), 1e-6);
  expect_brute_force_answers(std::vector<Eigen::Vector3f>(30, Eigen::Vector3f(1, 2, 3)), 1e-6);
  std::vector<Eigen::Vector3f> line;
  for (int i = 0; i < 500; ++i) line.emplace_back(0.001f * static_cast<float>(i * i), 0.0f, 0.0f);
  expect_brute_force_answers(line, 1e-6);
}

TEST(DistinctNeighbours, SameAnswersOnAnyNumberOfThreads) {
  std::vector<Eigen::Vector3f> positions;
  std::mt19937 random(3);
  std::normal_distribution<float> normal(0.0f, 1.0f);
  for (int i = 0; i < 200000; ++i) {
    positions.emplace_back(normal(random), normal(random), 0.1f * normal(random));
  }
  std::vector<std::size_t> queries;
  for (std::size_t i = 0; i < positions.size(); i += 97) queries.push_back(i);
  const std::vector<double> same(queries.size(), 1e-6);
  const auto one = distinct_neighbours(positions, queries, same, kCap, 1);
  const auto four = distinct_neighbours(positions, queries, same, kCap, 4);
  for (std::size_t k = 0; k < queries.size(); ++k) {
    EXPECT_EQ(one[k].coincident, four[k].coincident);
    EXPECT_EQ(one[k].nearest_squared, four[k].nearest_squared);
  }
}

TEST(DistinctNeighbours, RefusesBadArguments) {
  const std::vector<Eigen::Vector3f> positions(3, Eigen::Vector3f(0, 0, 0));
  EXPECT_THROW(distinct_neighbours(positions, {3}, {1e-6}, kCap), std::invalid_argument);
  EXPECT_THROW(distinct_neighbours(positions, {0, 1}, {1e-6}, kCap), std::invalid_argument);
  std::vector<Eigen::Vector3f> nan = positions;
  nan[1].x() = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(distinct_neighbours(nan, {0}, {1e-6}, kCap), std::invalid_argument);
}

}  // namespace
}  // namespace occlusion
