#pragma once
// Morton (Z-order) codes: three 21-bit cell coordinates interleaved into one
// 64-bit key, so that sorting by the key visits cells octant by octant. The
// octree's build sorts primitives by it; mesh estimation ranks points by it.

#include <cstdint>

namespace occlusion {

// Levels of octants a code holds: 3 bits each in a 64-bit key.
inline constexpr int kMortonLevels = 21;
// The largest cell coordinate along an axis.
inline constexpr std::uint32_t kMortonLastCell = (1u << kMortonLevels) - 1;

// The 21 low bits of x moved to every third bit.
inline std::uint64_t spread_by_three(std::uint32_t x) {
  std::uint64_t v = x & kMortonLastCell;
  v = (v | (v << 32)) & 0x1f00000000ffffull;
  v = (v | (v << 16)) & 0x1f0000ff0000ffull;
  v = (v | (v << 8)) & 0x100f00f00f00f00full;
  v = (v | (v << 4)) & 0x10c30c30c30c30c3ull;
  v = (v | (v << 2)) & 0x1249249249249249ull;
  return v;
}

}  // namespace occlusion
