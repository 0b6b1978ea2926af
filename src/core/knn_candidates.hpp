#pragma once
// The two passes of one k-nearest query over its leaf's gathered candidates
// (morton_knn.cpp): every candidate's squared distance, counting those within
// a first bound; then the (squared distance, index) keys of those within the
// bound chosen, packed. They were half of the search's time in scalar code;
// with AVX2, where the CPU has it, eight candidates go through each
// instruction. Both forms take the same float operations in the same order as
// knn_squared_distance, so the same bits: the answer does not depend on the CPU.

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>

namespace occlusion::knn_detail {

// Candidates are stored in structure-of-arrays form padded to a multiple of
// kLanes entries; a padding entry has NaN coordinates, so its squared
// distance is NaN and never within any bound.
inline constexpr std::size_t kLanes = 8;

inline std::size_t padded(std::size_t count) {
  return (count + kLanes - 1) / kLanes * kLanes;
}

// A squared distance and an index as one key: squared distances are never
// negative, so their bits order as they do, and sorting keys sorts by
// distance, then index.
inline std::uint64_t key_bits(std::uint32_t distance_bits, std::uint32_t id) {
  return std::uint64_t{distance_bits} << 32 | id;
}

// d2[c] = the squared distance from `query` to candidate c, for c below
// padded(count) (d2 has room for them); returns how many of the first
// `count` are <= `within`.
std::size_t squared_distances(const float* x, const float* y, const float* z, std::size_t count,
                              const Eigen::Vector3f& query, float within, float* d2);

// keys[0..n) = the keys of the candidates c < padded(count) with
// d2[c] <= bound, in some order; returns n. `keys` has room for
// padded(count) + kLanes keys (whole registers are stored).
std::size_t keys_within(const float* d2, const std::uint32_t* ids, std::size_t count, float bound,
                        std::uint64_t* keys);

}  // namespace occlusion::knn_detail
