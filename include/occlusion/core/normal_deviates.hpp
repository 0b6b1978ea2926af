#pragma once
// Standard normal deviates, fast and fully specified, one stream per work
// item (a scanner's beam): the ziggurat of Marsaglia and Tsang ("The
// Ziggurat Method for Generating Random Variables", J. Stat. Softw. 5(8),
// 2000) with 256 layers. 98.5 % of deviates cost one 64-bit word, a multiply
// and a compare: the layer comes from the word's low 8 bits and the value
// from its high 53, so the two are independent (Doornik, "An Improved
// Ziggurat Method to Generate Normal Random Samples", 2005, on the original's
// shared bits); the wedges take an exp, the tail (|x| > 3.654, 1 in 3,900)
// two logs. Box-Muller takes a log, a square root and a cosine for every one.
//
// The words are SplitMix64's (mix64 of a Weyl sequence) from a start mixed
// from (seed, stream) as Rng mixes its state, so a stream costs two mixes
// where Rng's state costs six: a beam's noise depends on its key only, not
// on the thread that draws it.

#include <cstdint>

#include "occlusion/core/random.hpp"

namespace occlusion {

class NormalDeviates {
 public:
  NormalDeviates(std::uint64_t seed, std::uint64_t stream)
      : state_(mix64(seed) ^ mix64(stream * 0xd1342543de82ef95ULL + 1)) {}
  // The next N(0, 1) deviate.
  double next();

 private:
  std::uint64_t word() {
    const std::uint64_t out = mix64(state_);
    state_ += 0x9e3779b97f4a7c15ULL;
    return out;
  }
  // Uniform in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(word() >> 11) * 0x1.0p-53; }
  double tail(bool negative);

  std::uint64_t state_;
};

}  // namespace occlusion
