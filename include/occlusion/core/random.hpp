#pragma once
// A small, fully specified random generator. std::uniform_real_distribution is
// not specified bit-for-bit across standard libraries, and results must be
// reproducible from a seed everywhere, so we define our own.

#include <cstdint>

namespace occlusion {

// SplitMix64 finaliser: a good 64-bit mix, used to derive independent streams.
std::uint64_t mix64(std::uint64_t x);

// xoshiro256** seeded from (seed, stream) through SplitMix64. One stream per
// work item (triangle, viewpoint) makes results independent of thread count.
class Rng {
 public:
  explicit Rng(std::uint64_t seed, std::uint64_t stream = 0);
  std::uint64_t next();
  // Uniform in [0, 1) with 53 random bits.
  double uniform();

 private:
  std::uint64_t s_[4];
};

}  // namespace occlusion
