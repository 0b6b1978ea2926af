#include "occlusion/analysis/station_selection.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <set>
#include <stdexcept>

#include "occlusion/core/random.hpp"

namespace occlusion {
namespace {

// A matrix from each candidate's list of seen targets, every target weighing `weight`.
CoverageMatrix matrix_of(const std::vector<std::vector<std::size_t>>& seen, std::size_t targets,
                         std::vector<double> weight = {}) {
  if (weight.empty()) weight.assign(targets, 1.0);
  CoverageMatrix matrix(seen.size(), weight);
  for (std::size_t c = 0; c < seen.size(); ++c) {
    for (std::size_t t : seen[c]) matrix.set_seen(c, t);
  }
  return matrix;
}

std::vector<std::size_t> range(std::size_t from, std::size_t to) {
  std::vector<std::size_t> out;
  for (std::size_t t = from; t < to; ++t) out.push_back(t);
  return out;
}

std::vector<std::size_t> new_stations(const StationSelection& selection) {
  std::vector<std::size_t> out;
  for (const auto& s : selection.stations) {
    if (!s.existing) out.push_back(s.candidate);
  }
  return out;
}

// Brute force: the weight the candidates in `set` cover together.
double union_weight(const CoverageMatrix& matrix, const std::vector<std::size_t>& set) {
  double sum = 0.0;
  for (std::size_t t = 0; t < matrix.targets(); ++t) {
    for (std::size_t c : set) {
      if (matrix.seen(c, t)) {
        sum += matrix.target_weight()[t];
        break;
      }
    }
  }
  return sum;
}

// Two rooms of 100 targets each (A: 0-99, B: 100-199). Candidate 0 stands in
// the doorway and sees 60 % of each room; candidate 1 sees all of room A,
// candidate 2 all of room B; candidates 3 and 4 see half a room each.
CoverageMatrix doorway_matrix() {
  std::vector<std::size_t> doorway = range(40, 160);
  return matrix_of({doorway, range(0, 100), range(100, 200), range(0, 50), range(150, 200)}, 200);
}

TEST(StationSelection, DoorwayGreedyNeedsThreeTheImprovementPassTwoOnePerRoom) {
  SelectionOptions options;
  options.target_coverage = 0.99;
  const StationSelection selection = select_stations(doorway_matrix(), options);
  // Greedy: the doorway (120 of 200), then a room (+40), then the other (+40).
  ASSERT_EQ(selection.greedy.size(), 3u);
  EXPECT_EQ(selection.greedy[0].candidate, 0u);
  EXPECT_DOUBLE_EQ(selection.greedy[0].coverage, 0.6);
  EXPECT_DOUBLE_EQ(selection.greedy[1].coverage, 0.8);
  EXPECT_DOUBLE_EQ(selection.greedy_coverage, 1.0);
  // After the pass: one station in each room, nothing else.
  const auto chosen = new_stations(selection);
  ASSERT_EQ(chosen.size(), 2u);
  EXPECT_EQ(std::set<std::size_t>(chosen.begin(), chosen.end()), (std::set<std::size_t>{1, 2}));
  EXPECT_TRUE(selection.target_reached);
  EXPECT_DOUBLE_EQ(selection.coverage, 1.0);
  EXPECT_DOUBLE_EQ(selection.stations[0].gain, 0.5);
  EXPECT_DOUBLE_EQ(selection.stations[1].coverage, 1.0);
  EXPECT_GE(selection.improvement_moves, 1u);
  // Each target is first covered by the station of its room.
  const std::int32_t rank_a = selection.stations[0].candidate == 1 ? 1 : 2;
  EXPECT_EQ(selection.first_rank[10], rank_a);
  EXPECT_EQ(selection.first_rank[110], 3 - rank_a);
  // Nothing is left to gain; the doorway alone sees 60 %.
  for (double g : selection.gain_left) EXPECT_EQ(g, 0.0);
  EXPECT_DOUBLE_EQ(selection.coverage_alone[0], 0.6);
  // No single station sees more than 60 %, so at least two are needed.
  EXPECT_EQ(selection.fewest_stations_bound, 2u);
  EXPECT_NE(selection.guarantee.find("Wolsey"), std::string::npos) << selection.guarantee;
}

TEST(StationSelection, WithoutTheImprovementPassGreedyStaysAtThree) {
  SelectionOptions options;
  options.target_coverage = 0.99;
  options.improve = false;
  const StationSelection selection = select_stations(doorway_matrix(), options);
  EXPECT_EQ(selection.stations.size(), 3u);
  EXPECT_EQ(selection.improvement_moves, 0u);
}

TEST(StationSelection, TwoStationsAreReplacedByOneWhenNoSingleDropKeepsTheTarget) {
  // Targets 0-11; the best pair is P = {0..5}, Q = {6..11}. Greedy takes G
  // (7 targets), then H (4 new), then P (1 new); dropping any one of the
  // three loses targets, but Q replaces G and H.
  const std::vector<std::vector<std::size_t>> seen = {
      {0, 1, 2, 6, 7, 8, 9}, {3, 4, 10, 11}, range(0, 6), range(6, 12)};
  SelectionOptions options;
  options.target_coverage = 1.0;
  const StationSelection selection = select_stations(matrix_of(seen, 12), options);
  ASSERT_EQ(selection.greedy.size(), 3u);
  EXPECT_EQ(selection.greedy[0].candidate, 0u);
  EXPECT_EQ(selection.greedy[1].candidate, 1u);
  const auto chosen = new_stations(selection);
  EXPECT_EQ(std::set<std::size_t>(chosen.begin(), chosen.end()), (std::set<std::size_t>{2, 3}));
  EXPECT_DOUBLE_EQ(selection.coverage, 1.0);
}

TEST(StationSelection, KModeSwapsAStationForOneThatCoversMore) {
  // Greedy takes the doorway first (60 %), then a room (+20 %): 80 %. One
  // station per room covers 100 %, which the swap finds.
  SelectionOptions options;
  options.stations = 2;
  const StationSelection selection = select_stations(doorway_matrix(), options);
  EXPECT_DOUBLE_EQ(selection.greedy_coverage, 0.8);
  EXPECT_DOUBLE_EQ(selection.coverage, 1.0);
  const auto chosen = new_stations(selection);
  EXPECT_EQ(std::set<std::size_t>(chosen.begin(), chosen.end()), (std::set<std::size_t>{1, 2}));
  EXPECT_NE(selection.guarantee.find("1 - 1/e"), std::string::npos) << selection.guarantee;
}

// Small random matrices (seeded): greedy against every pair and triple.
TEST(StationSelection, GreedyIsWithinOneMinusOneOverEOfTheBestPairAndTriple) {
  const double factor = 1.0 - 1.0 / std::exp(1.0);
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    Rng rng(seed);
    const std::size_t candidates = 6 + static_cast<std::size_t>(rng.uniform() * 7);
    const std::size_t targets = 30 + static_cast<std::size_t>(rng.uniform() * 100);
    std::vector<double> weight(targets);
    for (auto& w : weight) w = 0.1 + rng.uniform();
    CoverageMatrix matrix(candidates, weight);
    const double density = 0.1 + 0.5 * rng.uniform();
    for (std::size_t c = 0; c < candidates; ++c) {
      for (std::size_t t = 0; t < targets; ++t) {
        if (rng.uniform() < density) matrix.set_seen(c, t);
      }
    }
    double best_pair = 0.0, best_triple = 0.0;
    for (std::size_t a = 0; a < candidates; ++a) {
      for (std::size_t b = a + 1; b < candidates; ++b) {
        best_pair = std::max(best_pair, union_weight(matrix, {a, b}));
        for (std::size_t c = b + 1; c < candidates; ++c) {
          best_triple = std::max(best_triple, union_weight(matrix, {a, b, c}));
        }
      }
    }
    const double total = matrix.total_weight();
    for (const auto& [k, best] : {std::pair{2u, best_pair}, std::pair{3u, best_triple}}) {
      SelectionOptions options;
      options.stations = k;
      const StationSelection selection = select_stations(matrix, options);
      SCOPED_TRACE("seed " + std::to_string(seed) + ", K " + std::to_string(k));
      ASSERT_EQ(selection.greedy.size(), k);
      // Greedy's figures are the brute-force union of its stations.
      std::vector<std::size_t> greedy_set;
      for (const auto& s : selection.greedy) greedy_set.push_back(s.candidate);
      EXPECT_NEAR(selection.greedy_coverage * total, union_weight(matrix, greedy_set), 1e-9);
      EXPECT_GE(selection.greedy_coverage * total, factor * best - 1e-9);
      // The pass only raises coverage, never above the best; the bound is above it.
      EXPECT_GE(selection.coverage, selection.greedy_coverage - 1e-12);
      EXPECT_LE(selection.coverage * total, best + 1e-9);
      EXPECT_NEAR(selection.coverage * total, union_weight(matrix, new_stations(selection)), 1e-9);
      EXPECT_GE(selection.optimum_coverage_bound * total, best - 1e-9);
      // Lazy greedy computes no more gains than plain greedy.
      EXPECT_LE(selection.greedy_evaluations, selection.plain_greedy_evaluations);
    }
  }
}

TEST(StationSelection, TargetModeReachesTheTargetWithNoMoreThanGreedyAndAtLeastTheBound) {
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    Rng rng(seed, 7);
    const std::size_t candidates = 8;
    const std::size_t targets = 64;
    CoverageMatrix matrix(candidates, std::vector<double>(targets, 1.0));
    for (std::size_t c = 0; c < candidates; ++c) {
      for (std::size_t t = 0; t < targets; ++t) {
        if (rng.uniform() < 0.35) matrix.set_seen(c, t);
      }
    }
    // The fewest stations by brute force over all subsets.
    const double all = union_weight(matrix, range(0, candidates));
    const double target = 0.9 * all / matrix.total_weight();
    std::size_t fewest = candidates;
    for (unsigned mask = 1; mask < (1u << candidates); ++mask) {
      std::vector<std::size_t> set;
      for (std::size_t c = 0; c < candidates; ++c) {
        if (mask & (1u << c)) set.push_back(c);
      }
      if (union_weight(matrix, set) >= 0.9 * all - 1e-9) fewest = std::min(fewest, set.size());
    }
    SelectionOptions options;
    options.target_coverage = target;
    const StationSelection selection = select_stations(matrix, options);
    SCOPED_TRACE("seed " + std::to_string(seed));
    EXPECT_TRUE(selection.target_reached);
    EXPECT_GE(selection.coverage, target - 1e-12);
    EXPECT_LE(selection.stations.size(), selection.greedy.size());
    EXPECT_GE(selection.stations.size(), fewest);
    EXPECT_LE(selection.fewest_stations_bound, fewest);
    EXPECT_GE(selection.fewest_stations_bound, 1u);
  }
}

TEST(StationSelection, PlacedStationsAreKeptFirstAndCountedAsCovering) {
  SelectionOptions options;
  options.target_coverage = 0.99;
  options.placed = {1};  // room A's station is there already
  const StationSelection selection = select_stations(doorway_matrix(), options);
  ASSERT_EQ(selection.stations.size(), 2u);
  EXPECT_EQ(selection.stations[0].candidate, 1u);
  EXPECT_TRUE(selection.stations[0].existing);
  EXPECT_DOUBLE_EQ(selection.stations[0].coverage, 0.5);
  EXPECT_EQ(selection.stations[1].candidate, 2u);
  EXPECT_FALSE(selection.stations[1].existing);
  EXPECT_DOUBLE_EQ(selection.stations[1].gain, 0.5);

  // K mode: K new stations besides the placed one; it is never swapped out.
  SelectionOptions k_mode;
  k_mode.stations = 1;
  k_mode.placed = {0};  // the doorway
  const StationSelection k = select_stations(doorway_matrix(), k_mode);
  ASSERT_EQ(k.stations.size(), 2u);
  EXPECT_EQ(k.stations[0].candidate, 0u);
  EXPECT_TRUE(k.stations[0].existing);
  EXPECT_DOUBLE_EQ(k.coverage, 0.8);
}

TEST(StationSelection, AnUnreachableTargetAimsAtTheMostThatCanBeReached) {
  // No candidate sees targets 180-199: at most 90 % can be covered; candidate
  // 3 adds the last 5 % (170-179) that the others miss.
  const auto matrix =
      matrix_of({range(40, 160), range(0, 100), range(100, 170), range(170, 180)}, 200);
  SelectionOptions options;
  options.target_coverage = 0.95;
  const StationSelection selection = select_stations(matrix, options);
  EXPECT_FALSE(selection.target_reached);
  EXPECT_DOUBLE_EQ(selection.reachable_coverage, 0.9);
  // Asked 95 %: the most that can be reached, 90 %, not 95 % of it.
  EXPECT_DOUBLE_EQ(selection.aimed_coverage, 0.9);
  EXPECT_DOUBLE_EQ(selection.coverage, 0.9);
  EXPECT_EQ(new_stations(selection), (std::vector<std::size_t>{1, 2, 3}));
  EXPECT_EQ(selection.first_rank[190], -1);
  // The other choice in figures: the first two reach 85 %, short of 95 % of
  // 90 % (85.5 %); all three are needed for it too.
  EXPECT_EQ(selection.share_stations, 3u);
  EXPECT_DOUBLE_EQ(selection.share_coverage, 0.9);
  EXPECT_NE(selection.guarantee.find("cannot be reached"), std::string::npos)
      << selection.guarantee;
  EXPECT_NE(selection.guarantee.find("all of that"), std::string::npos) << selection.guarantee;
}

TEST(StationSelection, AnUnreachableTargetsShareTakesFewerStationsWhenAsked) {
  const auto matrix =
      matrix_of({range(40, 160), range(0, 100), range(100, 170), range(170, 180)}, 200);
  SelectionOptions options;
  options.target_coverage = 0.92;
  options.out_of_reach = OutOfReach::kShare;
  const StationSelection selection = select_stations(matrix, options);
  EXPECT_FALSE(selection.target_reached);
  // 92 % of the reachable 90 %: 82.8 %, which candidates 1 and 2 pass at 85 %.
  EXPECT_DOUBLE_EQ(selection.aimed_coverage, 0.92 * 0.9);
  EXPECT_DOUBLE_EQ(selection.coverage, 0.85);
  EXPECT_EQ(new_stations(selection), (std::vector<std::size_t>{1, 2}));
  EXPECT_EQ(selection.share_stations, 2u);
  // All of the reachable takes a third: candidate 3's last 5 %.
  EXPECT_EQ(selection.most_stations, 3u);
  EXPECT_NE(selection.guarantee.find("out_of_reach share"), std::string::npos)
      << selection.guarantee;
  // The same with the most asked: a third station for the last 5 %.
  options.out_of_reach = OutOfReach::kMost;
  const StationSelection most = select_stations(matrix, options);
  EXPECT_EQ(new_stations(most), (std::vector<std::size_t>{1, 2, 3}));
  EXPECT_EQ(most.share_stations, 2u);
  EXPECT_EQ(most.most_stations, 3u);
  EXPECT_DOUBLE_EQ(most.share_coverage, 0.85);
}

TEST(StationSelection, ConsecutiveStationsSeeEachOtherWhenAsked) {
  // Rooms A and B do not see each other; each sees the doorway.
  std::vector<std::uint8_t> sees = {1, 1, 1, 0, 0,  //
                                    1, 1, 0, 1, 0,  //
                                    1, 0, 1, 0, 1,  //
                                    0, 1, 0, 1, 0,  //
                                    0, 0, 1, 0, 1};
  SelectionOptions options;
  options.target_coverage = 0.99;
  options.intervisible = intervisibility_from_matrix(sees, 5);
  const StationSelection selection = select_stations(doorway_matrix(), options);
  // One per room alone would break the chain: the doorway stays between them.
  ASSERT_EQ(selection.stations.size(), 3u);
  for (std::size_t i = 1; i < selection.stations.size(); ++i) {
    EXPECT_TRUE(sees[selection.stations[i - 1].candidate * 5 + selection.stations[i].candidate]);
  }
  EXPECT_DOUBLE_EQ(selection.coverage, 1.0);
  EXPECT_NE(selection.guarantee.find("no approximation guarantee"), std::string::npos)
      << selection.guarantee;
  EXPECT_THROW(intervisibility_from_matrix(sees, 4), std::invalid_argument);
}

TEST(StationSelection, TheSameInputGivesTheSameOutput) {
  Rng rng(99);
  CoverageMatrix matrix(20, std::vector<double>(300, 1.0));
  for (std::size_t c = 0; c < 20; ++c) {
    for (std::size_t t = 0; t < 300; ++t) {
      // Many ties: every candidate sees one of few patterns.
      if ((t + c % 4) % 3 == 0 || rng.uniform() < 0.05) matrix.set_seen(c, t);
    }
  }
  SelectionOptions options;
  options.stations = 4;
  const StationSelection a = select_stations(matrix, options);
  const StationSelection b = select_stations(matrix, options);
  ASSERT_EQ(a.stations.size(), b.stations.size());
  for (std::size_t i = 0; i < a.stations.size(); ++i) {
    EXPECT_EQ(a.stations[i].candidate, b.stations[i].candidate);
    EXPECT_EQ(a.stations[i].coverage, b.stations[i].coverage);
  }
  EXPECT_EQ(a.first_rank, b.first_rank);
  EXPECT_EQ(a.guarantee, b.guarantee);
}

// Greedy reads every row three times before its first step (each
// candidate's coverage alone, what all see, each one's first gain): on a
// large matrix seconds with no report, and a report is where Python polls
// Ctrl-C (issue 44, 2.10). 1,000 rows of 4,096 words, 32 MB a pass, are
// reported on while they are read, and a cancel in such a report stops it.
TEST(StationSelection, ALargeMatrixIsReportedOnWhileItsRowsAreRead) {
  const std::size_t candidates = 1000, targets = 4096 * 64;
  CoverageMatrix matrix(candidates, std::vector<double>(targets, 1.0));
  for (std::size_t c = 0; c < candidates; ++c) matrix.set_seen(c, c);
  SelectionOptions options;
  options.stations = 1;
  options.improve = false;
  std::size_t reported = 0;
  Progress progress;
  progress.report = [&](const std::string& stage, double) {
    EXPECT_EQ(stage, "selecting");
    ++reported;
  };
  const StationSelection selection = select_stations(matrix, options, progress);
  ASSERT_EQ(selection.stations.size(), 1u);
  // The start, at least twice while 96 MB of rows are read (a report every
  // 32 MB or less), and greedy's step: it was the step alone.
  EXPECT_GE(reported, 4u);
  std::atomic<bool> cancel{false};
  int reports = 0;
  progress.cancel = &cancel;
  progress.report = [&](const std::string&, double) {
    if (++reports == 2) cancel = true;
  };
  EXPECT_THROW(select_stations(matrix, options, progress), Cancelled);
  EXPECT_EQ(reports, 2) << "read on after the cancel";
}

TEST(StationSelection, RefusesAmbiguousOrInvalidOptions) {
  const CoverageMatrix matrix = doorway_matrix();
  SelectionOptions neither;
  EXPECT_THROW(select_stations(matrix, neither), std::invalid_argument);
  SelectionOptions both;
  both.stations = 2;
  both.target_coverage = 0.5;
  EXPECT_THROW(select_stations(matrix, both), std::invalid_argument);
  SelectionOptions too_much;
  too_much.target_coverage = 1.5;
  EXPECT_THROW(select_stations(matrix, too_much), std::invalid_argument);
  SelectionOptions out_of_range;
  out_of_range.stations = 1;
  out_of_range.placed = {5};
  EXPECT_THROW(select_stations(matrix, out_of_range), std::invalid_argument);
  SelectionOptions twice;
  twice.stations = 1;
  twice.placed = {1, 1};
  EXPECT_THROW(select_stations(matrix, twice), std::invalid_argument);
  SelectionOptions fine;
  fine.stations = 1;
  EXPECT_THROW(select_stations(CoverageMatrix(2, {0.0, 0.0}), fine), std::invalid_argument);
}

}  // namespace
}  // namespace occlusion
