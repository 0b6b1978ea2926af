#include "knn_candidates.hpp"

#include <array>
#include <cstring>

#include "occlusion/core/morton_knn.hpp"

// GCC's per-function target pragmas; clang ignores them, so a clang build (the
// sanitized one) runs the scalar form.
#if defined(__x86_64__) && defined(__SSE2__) && defined(__GNUC__) && !defined(__clang__)
#define OCCLUSION_KNN_AVX2 1
#include <immintrin.h>
#else
#define OCCLUSION_KNN_AVX2 0
#endif

namespace occlusion::knn_detail {

namespace {

std::size_t scalar_squared_distances(const float* x, const float* y, const float* z,
                                     std::size_t count, const Eigen::Vector3f& query, float within,
                                     float* d2) {
  const std::size_t end = padded(count);
  for (std::size_t c = 0; c < end; ++c) {
    d2[c] = knn_squared_distance(query, Eigen::Vector3f(x[c], y[c], z[c]));
  }
  std::size_t inside = 0;
  for (std::size_t c = 0; c < count; ++c) inside += d2[c] <= within ? 1 : 0;
  return inside;
}

std::size_t scalar_keys_within(const float* d2, const std::uint32_t* ids, std::size_t count,
                               float bound, std::uint64_t* keys) {
  std::size_t kept = 0;
  for (std::size_t c = 0; c < count; ++c) {
    std::uint32_t bits;
    std::memcpy(&bits, &d2[c], sizeof bits);
    keys[kept] = key_bits(bits, ids[c]);
    kept += d2[c] <= bound ? 1 : 0;
  }
  return kept;
}

#if OCCLUSION_KNN_AVX2

// For each 8-bit mask, the lanes whose bit is set, first, in order: the
// permutation that packs them to the front of a register.
constexpr std::array<std::uint64_t, 256> make_pack_table() {
  std::array<std::uint64_t, 256> table{};
  for (unsigned mask = 0; mask < 256; ++mask) {
    std::uint64_t lanes = 0;
    unsigned at = 0;
    for (unsigned lane = 0; lane < 8; ++lane) {
      if (mask >> lane & 1u) lanes |= std::uint64_t{lane} << (8 * at++);
    }
    table[mask] = lanes;
  }
  return table;
}
constexpr std::array<std::uint64_t, 256> kPackTable = make_pack_table();

#pragma GCC push_options
#pragma GCC target("avx2,popcnt")

std::size_t avx2_squared_distances(const float* x, const float* y, const float* z,
                                   std::size_t count, const Eigen::Vector3f& query, float within,
                                   float* d2) {
  const __m256 qx = _mm256_set1_ps(query.x());
  const __m256 qy = _mm256_set1_ps(query.y());
  const __m256 qz = _mm256_set1_ps(query.z());
  const __m256 bound = _mm256_set1_ps(within);
  const std::size_t end = padded(count);
  std::size_t inside = 0;
  for (std::size_t c = 0; c < end; c += kLanes) {
    const __m256 dx = _mm256_sub_ps(qx, _mm256_loadu_ps(x + c));
    const __m256 dy = _mm256_sub_ps(qy, _mm256_loadu_ps(y + c));
    const __m256 dz = _mm256_sub_ps(qz, _mm256_loadu_ps(z + c));
    __m256 sum = _mm256_mul_ps(dx, dx);
    sum = _mm256_add_ps(sum, _mm256_mul_ps(dy, dy));
    sum = _mm256_add_ps(sum, _mm256_mul_ps(dz, dz));
    _mm256_storeu_ps(d2 + c, sum);
    // Padding is NaN: ordered comparisons leave it out.
    inside += static_cast<std::size_t>(
        __builtin_popcount(_mm256_movemask_ps(_mm256_cmp_ps(sum, bound, _CMP_LE_OQ))));
  }
  return inside;
}

std::size_t avx2_keys_within(const float* d2, const std::uint32_t* ids, std::size_t count,
                             float bound, std::uint64_t* keys) {
  const __m256 limit = _mm256_set1_ps(bound);
  const std::size_t end = padded(count);
  std::size_t kept = 0;
  for (std::size_t c = 0; c < end; c += kLanes) {
    const __m256 distances = _mm256_loadu_ps(d2 + c);
    const int mask = _mm256_movemask_ps(_mm256_cmp_ps(distances, limit, _CMP_LE_OQ));
    const __m256i pack = _mm256_cvtepu8_epi32(
        _mm_cvtsi64_si128(static_cast<long long>(kPackTable[static_cast<std::size_t>(mask)])));
    // The kept lanes first, then their 64-bit keys: unpacking interleaves
    // within 128-bit halves, so the quarters go in as 0, 2, 1, 3 to come out
    // as keys 0-3 and 4-7.
    const __m256i bits = _mm256_permute4x64_epi64(
        _mm256_permutevar8x32_epi32(_mm256_castps_si256(distances), pack), 0xD8);
    const __m256i index = _mm256_permute4x64_epi64(
        _mm256_permutevar8x32_epi32(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(ids + c)),
                                    pack),
        0xD8);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(keys + kept),
                        _mm256_unpacklo_epi32(index, bits));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(keys + kept + 4),
                        _mm256_unpackhi_epi32(index, bits));
    kept += static_cast<std::size_t>(__builtin_popcount(mask));
  }
  return kept;
}

#pragma GCC pop_options

// __builtin_cpu_supports also checks that the OS saves the wide registers.
bool use_avx2() {
  static const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("popcnt");
  return avx2;
}

#endif

}  // namespace

std::size_t squared_distances(const float* x, const float* y, const float* z, std::size_t count,
                              const Eigen::Vector3f& query, float within, float* d2) {
#if OCCLUSION_KNN_AVX2
  if (use_avx2()) return avx2_squared_distances(x, y, z, count, query, within, d2);
#endif
  return scalar_squared_distances(x, y, z, count, query, within, d2);
}

std::size_t keys_within(const float* d2, const std::uint32_t* ids, std::size_t count, float bound,
                        std::uint64_t* keys) {
#if OCCLUSION_KNN_AVX2
  if (use_avx2()) return avx2_keys_within(d2, ids, count, bound, keys);
#endif
  return scalar_keys_within(d2, ids, count, bound, keys);
}

}  // namespace occlusion::knn_detail
