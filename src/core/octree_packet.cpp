#include "octree_packet.hpp"

namespace occlusion {

// __builtin_cpu_supports also checks that the OS saves the wide registers
// (libgcc reads XCR0), so a "yes" means the instructions can run.
bool cpu_supports(OctreeTraversal traversal) {
#if OCCLUSION_PACKETS
  switch (traversal) {
    case OctreeTraversal::kPacketAvx512:
      return __builtin_cpu_supports("avx512f");
    case OctreeTraversal::kPacketAvx2:
      return __builtin_cpu_supports("avx2");
    default:
      return true;
  }
#else
  return traversal == OctreeTraversal::kAuto || traversal == OctreeTraversal::kSingle;
#endif
}

namespace octree_detail {

OctreeTraversal best_packet_traversal() {
  static const OctreeTraversal best = [] {
    for (const OctreeTraversal widest :
         {OctreeTraversal::kPacketAvx512, OctreeTraversal::kPacketAvx2,
          OctreeTraversal::kPacketSse2}) {
      if (cpu_supports(widest)) return widest;
    }
    return OctreeTraversal::kSingle;
  }();
  return best;
}

}  // namespace octree_detail
}  // namespace occlusion
