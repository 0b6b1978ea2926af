#include "occlusion/analysis/coverage_matrix.hpp"

#include <cmath>
#include <stdexcept>

namespace occlusion {

namespace {

double weight_of_bits(std::uint64_t bits, std::size_t first_target,
                      const std::vector<double>& target_weight) {
  double sum = 0.0;
  while (bits != 0) {
    const int bit = __builtin_ctzll(bits);
    sum += target_weight[first_target + static_cast<std::size_t>(bit)];
    bits &= bits - 1;
  }
  return sum;
}

}  // namespace

CoverageMatrix::CoverageMatrix(std::size_t candidates, std::vector<double> target_weight)
    : candidates_(candidates),
      words_per_row_((target_weight.size() + 63) / 64),
      target_weight_(std::move(target_weight)),
      bits_(candidates * words_per_row_, 0) {
  for (double weight : target_weight_) {
    if (!std::isfinite(weight) || weight < 0.0) {
      throw std::invalid_argument("coverage matrix: a target weight is negative or not finite");
    }
    total_weight_ += weight;
  }
}

double CoverageMatrix::seen_weight(std::size_t candidate) const {
  const std::uint64_t* bits = row(candidate);
  double sum = 0.0;
  for (std::size_t word = 0; word < words_per_row_; ++word) {
    if (bits[word] != 0) sum += weight_of_bits(bits[word], word * 64, target_weight_);
  }
  return sum;
}

double CoverageMatrix::gain(std::size_t candidate,
                            const std::vector<std::uint64_t>& covered) const {
  if (covered.size() != words_per_row_) {
    throw std::invalid_argument("coverage matrix: the covered set has the wrong size");
  }
  const std::uint64_t* bits = row(candidate);
  double sum = 0.0;
  for (std::size_t word = 0; word < words_per_row_; ++word) {
    const std::uint64_t added = bits[word] & ~covered[word];
    if (added != 0) sum += weight_of_bits(added, word * 64, target_weight_);
  }
  return sum;
}

double CoverageMatrix::weight_of(const std::vector<std::uint64_t>& covered) const {
  if (covered.size() != words_per_row_) {
    throw std::invalid_argument("coverage matrix: the covered set has the wrong size");
  }
  double sum = 0.0;
  for (std::size_t word = 0; word < words_per_row_; ++word) {
    if (covered[word] != 0) sum += weight_of_bits(covered[word], word * 64, target_weight_);
  }
  return sum;
}

}  // namespace occlusion
