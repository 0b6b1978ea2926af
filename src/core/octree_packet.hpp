#pragma once
// Packet traversal for the octree's batch queries: rays are put in a coherent
// order (ray_order.hpp), then traced 8 at a time with SSE2 or AVX2, or 16 at a
// time with AVX-512, whichever the CPU has; rays coherent as given go 32 at a
// time with AVX2. See octree_packet_body.inc for how a packet goes down.

#include <cstddef>
#include <cstdint>
#include <optional>

#include "occlusion/core/octree.hpp"
#include "occlusion/core/ray_lanes.hpp"
#include "octree_packet_interval.hpp"
#include "octree_single_ray.hpp"
#include "octree_slab.hpp"

// Packets need GCC's per-function target pragmas; clang ignores them, so a
// clang build (the libFuzzer targets) traces single rays only.
#if defined(__x86_64__) && defined(__SSE2__) && defined(__GNUC__) && !defined(__clang__)
#define OCCLUSION_PACKETS 1
#include "octree_packet_lanes.hpp"
#else
#define OCCLUSION_PACKETS 0
#endif

namespace occlusion::octree_detail {

// A batch query: inputs, and one of the two outputs.
struct PacketQuery {
  const Ray* rays = nullptr;
  const PrimitiveId* ignore_ids = nullptr;  // may be null
  std::optional<Hit>* hits = nullptr;       // closest hit
  std::uint8_t* occluded = nullptr;         // any hit
};

#if OCCLUSION_PACKETS

namespace packet_sse2 {
#include "octree_packet_body.inc"
}  // namespace packet_sse2

#pragma GCC push_options
#pragma GCC target("avx2")
namespace packet_avx2 {
#include "octree_packet_body.inc"
}  // namespace packet_avx2
#pragma GCC pop_options

#pragma GCC push_options
#pragma GCC target("avx2")
namespace packet_avx2_wide {
#include "octree_packet_body.inc"
}  // namespace packet_avx2_wide
#pragma GCC pop_options

#pragma GCC push_options
#pragma GCC target("avx512f")
// GCC 12 flags the deliberately undefined pass-through operand of its own
// AVX-512 intrinsics (_mm512_undefined_ps: gathers, square roots) as
// uninitialised.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
namespace packet_avx512 {
#include "octree_packet_body.inc"
}  // namespace packet_avx512
#pragma GCC diagnostic pop
#pragma GCC pop_options

#endif

// What kAuto resolves to on this CPU: the widest packets that pay, else kSingle.
OctreeTraversal best_packet_traversal();

}  // namespace occlusion::octree_detail
