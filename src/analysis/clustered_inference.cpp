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

void bootstrap(const std::vector<double>& x, const std::vector<double>& y,
               const std::vector<std::vector<std::size_t>>& groups, const Statistic& statistic,
               const InferenceOptions& options, std::uint64_t stream, ClusteredEstimate& estimate) {
  Rng random(options.seed, stream);
  std::vector<double> draws;
  std::vector<double> xb, yb;
  std::vector<std::size_t> sb;
  for (std::size_t b = 0; b < options.resamples; ++b) {
    xb.clear();
    yb.clear();
    sb.clear();
    for (std::size_t k = 0; k < groups.size(); ++k) {
      // A scene drawn twice is two scenes: its copies are centred separately.
      for (const std::size_t run : groups[draw_below(random, groups.size())]) {
        xb.push_back(x[run]);
        yb.push_back(y[run]);
        sb.push_back(k);
      }
    }
    if (const auto value = statistic(xb, yb, sb)) {
      draws.push_back(*value);
    } else {
      ++estimate.undefined_resamples;
    }
  }
  // Draws left out would bias the interval towards the scenes that define
  // the estimate; past a few, there is no honest interval.
  const bool enough_defined = static_cast<double>(estimate.undefined_resamples) <=
                              0.05 * static_cast<double>(options.resamples);
  if (groups.size() < kMinScenesForInterval || !enough_defined || draws.empty()) return;
  std::sort(draws.begin(), draws.end());
  estimate.interval95 = Interval{percentile(draws, 0.025), percentile(draws, 0.975)};
}

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
  bootstrap(x, y, groups, slope, options, 2, result.within_scene_slope);
  permutation_test(x, y, scene, groups, pearson, options, 3, result.pearson);
  permutation_test(average_ranks(x), average_ranks(y), scene, groups, pearson_of_ranks, options, 4,
                   result.spearman);
  permutation_test(x, y, scene, groups, slope, options, 5, result.within_scene_slope);
  return result;
}

}  // namespace occlusion
