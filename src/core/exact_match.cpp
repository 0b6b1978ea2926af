#include "occlusion/core/exact_match.hpp"

#include <algorithm>

namespace occlusion {

namespace {

bool coordinates_less(const Eigen::Vector3f& a, const Eigen::Vector3f& b) {
  if (a.x() != b.x()) return a.x() < b.x();
  if (a.y() != b.y()) return a.y() < b.y();
  return a.z() < b.z();
}

// Indices of `points` sorted by coordinates; equal points keep their order,
// which is what pairs duplicates in order of appearance. Points with a
// non-finite coordinate are left out: NaN equals nothing (not even itself),
// and in the comparison it would seem equal to every point, pairing at random.
std::vector<std::size_t> sorted_indices(const std::vector<Eigen::Vector3f>& points) {
  std::vector<std::size_t> order;
  order.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (points[i].allFinite()) order.push_back(i);
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return coordinates_less(points[a], points[b]);
  });
  return order;
}

}  // namespace

ExactMatch match_exact_points(const std::vector<Eigen::Vector3f>& source,
                              const std::vector<Eigen::Vector3f>& target) {
  ExactMatch match;
  match.source_of.assign(target.size(), ExactMatch::kNone);
  const std::vector<std::size_t> from = sorted_indices(source);
  const std::vector<std::size_t> to = sorted_indices(target);
  std::size_t s = 0;
  std::size_t t = 0;
  while (s < from.size() && t < to.size()) {
    const Eigen::Vector3f& a = source[from[s]];
    const Eigen::Vector3f& b = target[to[t]];
    if (coordinates_less(a, b)) {
      ++match.unmatched_sources;
      ++s;
    } else if (coordinates_less(b, a)) {
      ++t;
    } else {
      match.source_of[to[t]] = from[s];
      ++s;
      ++t;
    }
  }
  match.unmatched_sources += from.size() - s + (source.size() - from.size());
  for (std::size_t i = 0; i < target.size(); ++i) {
    if (match.source_of[i] != ExactMatch::kNone) continue;
    if (match.unmatched_targets == 0) match.first_unmatched_target = i;
    ++match.unmatched_targets;
  }
  return match;
}

}  // namespace occlusion
