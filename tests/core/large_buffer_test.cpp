#include "occlusion/core/large_buffer.hpp"

#include <gtest/gtest.h>

#include <cstdint>

#include "occlusion/core/octree.hpp"

namespace occlusion {
namespace {

std::uintptr_t address_of(const void* p) {
  return reinterpret_cast<std::uintptr_t>(p);
}

// Octree nodes are read with aligned vector loads and sized to whole cache
// lines: a small tree's nodes once came from plain malloc (16-byte aligned),
// which crashed AVX loads and spread each node over five lines.
TEST(LargeBuffer, SmallBuffersAreAlignedAsTheirTypeAsks) {
  static_assert(alignof(OctreeNode) == 64, "nodes are cache-line aligned");
  for (const std::size_t count : {1u, 2u, 3u, 7u, 100u, 5591u}) {
    LargeVector<OctreeNode> nodes(count);
    EXPECT_EQ(address_of(nodes.data()) % alignof(OctreeNode), 0u) << count << " nodes";
  }
  // Growing reallocates: every buffer along the way is aligned.
  LargeVector<OctreeNode> grown;
  for (int i = 0; i < 1000; ++i) {
    grown.emplace_back();
    ASSERT_EQ(address_of(grown.data()) % alignof(OctreeNode), 0u) << grown.size() << " nodes";
  }
}

TEST(LargeBuffer, LargeBuffersStartOnAHugePage) {
  // 16 MiB: above the threshold for huge-page alignment.
  LargeVector<float> big(std::size_t{4} << 20);
  EXPECT_EQ(address_of(big.data()) % (std::size_t{2} << 20), 0u);
  LargeVector<char> odd(1);  // not a multiple of any alignment
  EXPECT_NE(odd.data(), nullptr);
}

}  // namespace
}  // namespace occlusion
