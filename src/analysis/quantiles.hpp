#pragma once
// Quantiles of a large array without sorting it: the value at rank
// round(q (n - 1)), as one nth_element would give it. Several quantiles of one
// array share its partitions: after the first, each later one searches only
// the part on its side of the ranks already placed, so the median, 10 % and
// 90 % of a million values cost about one full pass, not three.

#include <algorithm>
#include <cstddef>
#include <initializer_list>
#include <iterator>
#include <vector>

namespace occlusion::quantiles {

inline std::size_t rank_of(double q, std::size_t count) {
  return static_cast<std::size_t>(q * static_cast<double>(count - 1) + 0.5);
}

// The quantile q of `values` (reordered); zero when there are none.
template <class Values>
typename Values::value_type at(Values& values, double q) {
  if (values.empty()) return {};
  const std::size_t rank = rank_of(q, values.size());
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(rank),
                   values.end());
  return values[rank];
}

// The values of `values` (reordered; not empty) at `ranks` (each below its
// size), in the order given.
template <class Values>
std::vector<typename Values::value_type> at_ranks(Values& values,
                                                  const std::vector<std::size_t>& ranks) {
  std::vector<typename Values::value_type> out;
  out.reserve(ranks.size());
  // Ranks already placed: every value before one is no larger, after it no smaller.
  std::vector<std::size_t> placed;
  for (const std::size_t rank : ranks) {
    const auto above = std::lower_bound(placed.begin(), placed.end(), rank);
    if (above == placed.end() || *above != rank) {
      const std::size_t lo = above == placed.begin() ? 0 : *std::prev(above) + 1;
      const std::size_t hi = above == placed.end() ? values.size() : *above;
      const auto begin = values.begin();
      std::nth_element(begin + static_cast<std::ptrdiff_t>(lo),
                       begin + static_cast<std::ptrdiff_t>(rank),
                       begin + static_cast<std::ptrdiff_t>(hi));
      placed.insert(above, rank);
    }
    out.push_back(values[rank]);
  }
  return out;
}

// The quantiles qs of `values` (reordered; not empty), in the order given.
template <class Values>
std::vector<typename Values::value_type> in_place(Values& values,
                                                  std::initializer_list<double> qs) {
  std::vector<std::size_t> ranks;
  for (const double q : qs) ranks.push_back(rank_of(q, values.size()));
  return at_ranks(values, ranks);
}

}  // namespace occlusion::quantiles
