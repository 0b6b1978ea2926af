#pragma once
// How sure the occlusion study can be of an association between a measure x
// (an occlusion level) and y (mIoU) when its runs are nested in scenes: each
// scene is scanned from several viewpoint configurations, so runs of one
// scene share its layout and are not independent draws. Pure standard C++.
//
// - Pearson r and Spearman rho over all runs, and the within-scene slope:
//   y and x centred on their scene's means, then least squares through the
//   origin (the change in y per unit of x inside a scene; what differs between
//   scenes cannot bias it).
// - 95 % intervals from a scene-clustered bootstrap: whole scenes are drawn
//   with replacement, each with all of its runs, and the percentile interval
//   of the estimates is reported. Clusters, not runs, are the sampling unit,
//   so the interval is honest about how few scenes there are; with fewer than
//   kMinScenesForInterval scenes a bootstrap over scenes cannot estimate the
//   spread between them, and no interval is given.
// - Two-sided permutation p-values: x is shuffled within each scene (never
//   across scenes), which keeps the scenes as they are and breaks only the
//   within-scene pairing; p = (1 + #{|T*| >= |T|}) / (1 + permutations).
//   Undefined when no scene has two runs with different x (no shuffle can
//   change anything).
// Every draw comes from core/random.hpp's generator: the same seed gives the
// same intervals and p-values on every machine.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace occlusion {

inline constexpr std::size_t kMinScenesForInterval = 5;

struct InferenceOptions {
  std::size_t resamples = 2000;     // bootstrap draws of the scenes
  std::size_t permutations = 2000;  // within-scene shuffles of x
  std::uint64_t seed = 1;
};

struct Interval {
  double lo = 0.0;
  double hi = 0.0;
};

struct ClusteredEstimate {
  std::optional<double> value;         // undefined: see why_undefined
  std::optional<Interval> interval95;  // scene-clustered bootstrap, percentile
  std::optional<double> p_value;       // within-scene permutation, two-sided
  // Of the bootstrap draws, those where the estimate was undefined (a draw of
  // scenes whose x does not vary); they are left out of the interval.
  std::size_t undefined_resamples = 0;
};

struct ClusteredAssociation {
  std::size_t runs = 0;
  std::size_t scenes = 0;
  ClusteredEstimate pearson;
  ClusteredEstimate spearman;
  ClusteredEstimate within_scene_slope;  // y per unit of x
  InferenceOptions options;
};

// x, y and scene (any integer naming each run's scene) per run. Throws
// std::invalid_argument for sizes that differ, a non-finite value, or
// resamples or permutations of 0.
ClusteredAssociation clustered_association(const std::vector<double>& x,
                                           const std::vector<double>& y,
                                           const std::vector<std::size_t>& scene,
                                           const InferenceOptions& options = {});

// Two studies of the same runs (run i of each is the same scene and
// configuration: another segmenter, another sensor) and how their
// within-scene slopes differ. One bootstrap draws the scenes for both (the
// slope's own stream, so each slope's interval is the one
// clustered_association gives on these runs), and each draw's difference
// second - first makes the difference's interval: what the pairing shares
// cancels there. No p-values.
struct PairedSlopes {
  std::size_t runs = 0;
  std::size_t scenes = 0;
  ClusteredEstimate first, second;
  ClusteredEstimate difference;  // second - first
  InferenceOptions options;
};

// Per run: each study's x and y, and the run's scene. Same errors as
// clustered_association.
PairedSlopes paired_slopes(const std::vector<double>& x_first, const std::vector<double>& y_first,
                           const std::vector<double>& x_second, const std::vector<double>& y_second,
                           const std::vector<std::size_t>& scene,
                           const InferenceOptions& options = {});

// The within-scene slope alone (see above); nullopt where x does not vary
// inside any scene. Same errors as correlation.hpp's functions.
std::optional<double> within_scene_slope(const std::vector<double>& x, const std::vector<double>& y,
                                         const std::vector<std::size_t>& scene);

}  // namespace occlusion
