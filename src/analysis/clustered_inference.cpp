#include "occlusion/analysis/clustered_inference.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <stdexcept>

#include "occlusion/analysis/correlation.hpp"
#include "occlusion/core/random.hpp"

namespace occlusion {

namespace {

using Statistic = std::function<std::optional<double>(
    const std::vector<double>&, const std::vector<double>&, const std::vector<std::size_t>&)>;

// Each scene's runs, scenes in the order they first appear (so that draws
// do not depend on how the caller numbered them).
std::vector<std::vector<std::size_t>> runs_by_scene(const std::vector<std::size_t>& scene) {
  std::map<std::size_t, std::size_t> position;
  std::vector<std::vector<std::size_t>> groups;
  for (std::size_t run = 0; run < scene.size(); ++run) {
    const auto [it, added] = position.emplace(scene[run], groups.size());
    if (added) groups.emplace_back();
    groups[it->second].push_back(run);
  }
  return groups;
}

std::size_t draw_below(Rng& random, std::size_t n) {
  return std::min(n - 1, static_cast<std::size_t>(random.uniform() * static_cast<double>(n)));
}

// The percentile (linear between order statistics) of sorted values.
double percentile(const std::vector<double>& sorted, double share) {
  const double at = share * static_cast<double>(sorted.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(at));
  const std::size_t above = std::min(sorted.size() - 1, below + 1);
  return sorted[below] + (at - static_cast<double>(below)) * (sorted[above] - sorted[below]);
}

// The runs of one bootstrap draw: groups.size() scenes drawn with
// replacement, each with all of its runs; `scene` numbers the draws (a scene
// drawn twice is two scenes: its copies are centred separately).
void draw_runs(Rng& random, const std::vector<std::vector<std::size_t>>& groups,
               std::vector<std::size_t>& runs, std::vector<std::size_t>& scene) {
  runs.clear();
  scene.clear();
  for (std::size_t k = 0; k < groups.size(); ++k) {
    for (const std::size_t run : groups[draw_below(random, groups.size())]) {
      runs.push_back(run);
      scene.push_back(k);
    }
  }
}

std::vector<double> pick(const std::vector<double>& values, const std::vector<std::size_t>& runs) {
  std::vector<double> picked;
  picked.reserve(runs.size());
  for (const std::size_t run : runs) picked.push_back(values[run]);
  return picked;
}

// The percentile interval of the defined draws. Draws left out would bias
// the interval towards the scenes that define the estimate; past a few,
// there is no honest interval.
void set_interval(std::vector<double> draws, std::size_t scenes, const InferenceOptions& options,
                  ClusteredEstimate& estimate) {
  const bool enough_defined = static_cast<double>(estimate.undefined_resamples) <=
                              0.05 * static_cast<double>(options.resamples);
  if (scenes < kMinScenesForInterval || !enough_defined || draws.empty()) return;
  std::sort(draws.begin(), draws.end());
  estimate.interval95 = Interval{percentile(draws, 0.025), percentile(draws, 0.975)};
}

void bootstrap(const std::vector<double>& x, const std::vector<double>& y,
               const std::vector<std::vector<std::size_t>>& groups, const Statistic& statistic,
               const InferenceOptions& options, std::uint64_t stream, ClusteredEstimate& estimate) {
  Rng random(options.seed, stream);
  std::vector<double> draws;
  std::vector<std::size_t> runs, sb;
  for (std::size_t b = 0; b < options.resamples; ++b) {
    draw_runs(random, groups, runs, sb);
    if (const auto value = statistic(pick(x, runs), pick(y, runs), sb)) {
      draws.push_back(*value);
    } else {
      ++estimate.undefined_resamples;
    }
  }
  set_interval(std::move(draws), groups.size(), options, estimate);
}

// clustered_association's streams: each statistic's bootstrap and permutations.
constexpr std::uint64_t kSlopeBootstrapStream = 2;

void permutation_test(const std::vector<double>& x, const std::vector<double>& y,
                      const std::vector<std::size_t>& scene,
                      const std::vector<std::vector<std::size_t>>& groups,
                      const Statistic& statistic, const InferenceOptions& options,
                      std::uint64_t stream, ClusteredEstimate& estimate) {
  const bool can_shuffle = std::any_of(groups.begin(), groups.end(), [&](const auto& runs) {
    return std::any_of(runs.begin(), runs.end(),
                       [&](std::size_t run) { return x[run] != x[runs.front()]; });
  });
  if (!estimate.value || !can_shuffle) return;
  const double observed = std::abs(*estimate.value);
  Rng random(options.seed, stream);
  std::vector<double> shuffled = x;
  std::size_t as_extreme = 0;
  for (std::size_t p = 0; p < options.permutations; ++p) {
    for (const auto& runs : groups) {
      // Fisher-Yates over the scene's own runs.
      for (std::size_t i = runs.size(); i > 1; --i) {
        std::swap(shuffled[runs[i - 1]], shuffled[runs[draw_below(random, i)]]);
      }
    }
    const auto value = statistic(shuffled, y, scene);
    // Equal up to rounding counts as extreme: a permutation that only
    // reorders tied values gives the observed statistic back.
    if (value && std::abs(*value) >= observed * (1.0 - 1e-12)) ++as_extreme;
  }
  estimate.p_value =
      static_cast<double>(1 + as_extreme) / static_cast<double>(1 + options.permutations);
}

}  // namespace

std::optional<double> within_scene_slope(const std::vector<double>& x, const std::vector<double>& y,
                                         const std::vector<std::size_t>& scene) {
  if (scene.size() != x.size()) {
    throw std::invalid_argument("within-scene slope: " + std::to_string(scene.size()) +
                                " scenes for " + std::to_string(x.size()) + " runs");
  }
  least_squares_fit(x, y);  // the same checks of x and y
  double sxx = 0.0, sxy = 0.0, scale = 0.0;
  for (const auto& runs : runs_by_scene(scene)) {
    double mean_x = 0.0, mean_y = 0.0;
    for (const std::size_t run : runs) {
      mean_x += x[run];
      mean_y += y[run];
    }
    mean_x /= static_cast<double>(runs.size());
    mean_y /= static_cast<double>(runs.size());
    for (const std::size_t run : runs) {
      const double dx = x[run] - mean_x;
      sxx += dx * dx;
      sxy += dx * (y[run] - mean_y);
      scale = std::max(scale, std::abs(x[run]));
    }
  }
  // Centring equal values can leave rounding noise, which is no variation.
  const double noise = 1e-12 * scale;
  if (sxx <= noise * noise * static_cast<double>(x.size())) return std::nullopt;
  return sxy / sxx;
}

ClusteredAssociation clustered_association(const std::vector<double>& x,
                                           const std::vector<double>& y,
                                           const std::vector<std::size_t>& scene,
                                           const InferenceOptions& options) {
  if (options.resamples == 0 || options.permutations == 0) {
    throw std::invalid_argument("clustered association: resamples and permutations must be > 0");
  }
  ClusteredAssociation result;
  result.options = options;
  result.runs = x.size();
  const std::vector<std::vector<std::size_t>> groups = runs_by_scene(scene);
  result.scenes = groups.size();

  const Statistic pearson = [](const auto& a, const auto& b, const auto&) {
    return pearson_correlation(a, b);
  };
  // Ranks are taken once: shuffling ranks within scenes is ranking shuffled x.
  const Statistic pearson_of_ranks = pearson;
  const Statistic spearman = [](const auto& a, const auto& b, const auto&) {
    return spearman_correlation(a, b);
  };
  const Statistic slope = [](const auto& a, const auto& b, const auto& s) {
    return within_scene_slope(a, b, s);
  };

  result.within_scene_slope.value = within_scene_slope(x, y, scene);
  result.pearson.value = pearson_correlation(x, y);
  result.spearman.value = spearman_correlation(x, y);
  bootstrap(x, y, groups, pearson, options, 0, result.pearson);
  bootstrap(x, y, groups, spearman, options, 1, result.spearman);
  bootstrap(x, y, groups, slope, options, kSlopeBootstrapStream, result.within_scene_slope);
  permutation_test(x, y, scene, groups, pearson, options, 3, result.pearson);
  permutation_test(average_ranks(x), average_ranks(y), scene, groups, pearson_of_ranks, options, 4,
                   result.spearman);
  permutation_test(x, y, scene, groups, slope, options, 5, result.within_scene_slope);
  return result;
}

PairedSlopes paired_slopes(const std::vector<double>& x_first, const std::vector<double>& y_first,
                           const std::vector<double>& x_second, const std::vector<double>& y_second,
                           const std::vector<std::size_t>& scene, const InferenceOptions& options) {
  if (options.resamples == 0) {
    throw std::invalid_argument("paired slopes: resamples must be > 0");
  }
  if (x_second.size() != x_first.size()) {
    throw std::invalid_argument("paired slopes: " + std::to_string(x_first.size()) + " and " +
                                std::to_string(x_second.size()) + " runs do not pair");
  }
  PairedSlopes result;
  result.options = options;
  result.runs = x_first.size();
  const std::vector<std::vector<std::size_t>> groups = runs_by_scene(scene);
  result.scenes = groups.size();
  result.first.value = within_scene_slope(x_first, y_first, scene);
  result.second.value = within_scene_slope(x_second, y_second, scene);
  if (result.first.value && result.second.value) {
    result.difference.value = *result.second.value - *result.first.value;
  }
  Rng random(options.seed, kSlopeBootstrapStream);
  std::vector<double> first_draws, second_draws, difference_draws;
  std::vector<std::size_t> runs, sb;
  for (std::size_t b = 0; b < options.resamples; ++b) {
    draw_runs(random, groups, runs, sb);
    const auto first = within_scene_slope(pick(x_first, runs), pick(y_first, runs), sb);
    const auto second = within_scene_slope(pick(x_second, runs), pick(y_second, runs), sb);
    if (first) first_draws.push_back(*first);
    if (second) second_draws.push_back(*second);
    if (first && second) difference_draws.push_back(*second - *first);
    result.first.undefined_resamples += first ? 0 : 1;
    result.second.undefined_resamples += second ? 0 : 1;
    result.difference.undefined_resamples += first && second ? 0 : 1;
  }
  set_interval(std::move(first_draws), groups.size(), options, result.first);
  set_interval(std::move(second_draws), groups.size(), options, result.second);
  set_interval(std::move(difference_draws), groups.size(), options, result.difference);
  return result;
}

}  // namespace occlusion
