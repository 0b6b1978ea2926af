#pragma once
// Sorting Morton codes with their ids, on all cores: the octree's builder and
// morton_order both sort so.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "occlusion/core/large_buffer.hpp"
#include "occlusion/core/morton.hpp"
#include "occlusion/core/parallel.hpp"
#include "occlusion/core/progress.hpp"

namespace occlusion::octree_detail {

// Stable LSD radix sort of (codes[i], ids[i]) by code, on all cores: each
// pass counts digits per part in parallel, then scatters each part to its own
// offsets. Passes whose digit is the same for every code are skipped.
inline void radix_sort_codes(LargeVector<std::uint64_t>& codes, LargeVector<std::uint32_t>& ids,
                             const Progress& progress, unsigned threads = 0) {
  constexpr int kDigitBits = 11;
  constexpr std::size_t kBuckets = std::size_t{1} << kDigitBits;
  const std::size_t n = codes.size();
  const unsigned parts = std::max(
      1u, std::min<unsigned>(resolve_thread_count(threads), static_cast<unsigned>(n / 65536 + 1)));
  LargeVector<std::uint64_t> codes_out(n);
  LargeVector<std::uint32_t> ids_out(n);
  std::vector<std::array<std::size_t, kBuckets>> counts(parts);
  const auto part_begin = [&](unsigned p) { return n * p / parts; };
  for (int shift = 0; shift < 3 * kMortonLevels; shift += kDigitBits) {
    progress.check_cancel();
    parallel_for(parts, 1, parts, [&](std::size_t first, std::size_t last) {
      for (std::size_t p = first; p < last; ++p) {
        counts[p].fill(0);
        for (std::size_t i = part_begin(static_cast<unsigned>(p));
             i < part_begin(static_cast<unsigned>(p + 1)); ++i) {
          ++counts[p][(codes[i] >> shift) & (kBuckets - 1)];
        }
      }
    });
    // Offsets: bucket by bucket, part by part within a bucket (stable).
    std::size_t total = 0;
    bool one_bucket = false;
    for (std::size_t b = 0; b < kBuckets; ++b) {
      std::size_t in_bucket = 0;
      for (unsigned p = 0; p < parts; ++p) {
        const std::size_t c = counts[p][b];
        counts[p][b] = total;
        total += c;
        in_bucket += c;
      }
      if (in_bucket == n) one_bucket = true;
    }
    if (one_bucket) continue;  // the offsets are unused: nothing moves
    parallel_for(parts, 1, parts, [&](std::size_t first, std::size_t last) {
      for (std::size_t p = first; p < last; ++p) {
        auto& offset = counts[p];
        for (std::size_t i = part_begin(static_cast<unsigned>(p));
             i < part_begin(static_cast<unsigned>(p + 1)); ++i) {
          const std::size_t to = offset[(codes[i] >> shift) & (kBuckets - 1)]++;
          codes_out[to] = codes[i];
          ids_out[to] = ids[i];
        }
      }
    });
    codes.swap(codes_out);
    ids.swap(ids_out);
  }
}

}  // namespace occlusion::octree_detail
