#pragma once
// What each candidate scanner station sees (scan planning, `occlusion plan`):
// one bit per (candidate, target), where a target is a point of a cloud or a
// sample of a mesh's surface, and each target weighs the area it stands for.
// The coverage of a set of stations is the weight of the targets at least one
// of them sees (station_selection.hpp chooses the set).
//
// Bits, not index lists: 1,000 candidates x 200,000 points is 25 MB as bits,
// while a station in a room sees a large share of it, so lists would be ten
// times that.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace occlusion {

// Sums of weights are formed in different orders by different moves (of a
// selection, of a refinement); this much of the total is rounding, not coverage.
inline constexpr double kWeightRounding = 1e-12;

class CoverageMatrix {
 public:
  CoverageMatrix() = default;
  // Throws std::invalid_argument for a negative or non-finite weight.
  CoverageMatrix(std::size_t candidates, std::vector<double> target_weight);

  std::size_t candidates() const { return candidates_; }
  std::size_t targets() const { return target_weight_.size(); }
  std::size_t words_per_row() const { return words_per_row_; }
  const std::vector<double>& target_weight() const { return target_weight_; }
  double total_weight() const { return total_weight_; }

  // Rows are independent: threads may set bits of different candidates at once.
  void set_seen(std::size_t candidate, std::size_t target) {
    row(candidate)[target / 64] |= std::uint64_t{1} << (target % 64);
  }
  bool seen(std::size_t candidate, std::size_t target) const {
    return (row(candidate)[target / 64] >> (target % 64)) & 1u;
  }
  std::uint64_t* row(std::size_t candidate) { return bits_.data() + candidate * words_per_row_; }
  const std::uint64_t* row(std::size_t candidate) const {
    return bits_.data() + candidate * words_per_row_;
  }
  // The weight of the targets `candidate` sees.
  double seen_weight(std::size_t candidate) const;
  // The weight of the targets `candidate` sees that `covered` (a row-sized
  // bit set) does not hold: what it would add.
  double gain(std::size_t candidate, const std::vector<std::uint64_t>& covered) const;
  // The weight of the targets a row-sized bit set holds.
  double weight_of(const std::vector<std::uint64_t>& covered) const;

 private:
  std::size_t candidates_ = 0;
  std::size_t words_per_row_ = 0;
  std::vector<double> target_weight_;
  double total_weight_ = 0.0;
  std::vector<std::uint64_t> bits_;
};

}  // namespace occlusion
