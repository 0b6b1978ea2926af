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
    case OctreeTraversal::kPacketAvx2Wide:
      return __builtin_cpu_supports("avx2");
    default:
      return true;
  }
#else
  return traversal == OctreeTraversal::kAuto || traversal == OctreeTraversal::kSingle;
#endif
}

namespace octree_detail {

// SSE2 packets are not chosen: four lanes per instruction test a child box
// for eight rays in two steps, which costs more than the single-ray test of
// all eight children (bench_moc-like shadow rays, one thread: 3.2 against 3.5 M
// rays/s; AVX2 5.1, AVX-512 6.1).
OctreeTraversal best_packet_traversal() {
  static const OctreeTraversal best = [] {
    for (const OctreeTraversal widest :
         {OctreeTraversal::kPacketAvx512, OctreeTraversal::kPacketAvx2}) {
      if (cpu_supports(widest)) return widest;
    }
    return OctreeTraversal::kSingle;
  }();
  return best;
}

}  // namespace octree_detail
}  // namespace occlusion
