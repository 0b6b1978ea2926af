#pragma once
// A hand-built octree over primitives: triangle_octree.hpp and sphere_octree.hpp
// plug their shapes in.
//
// Construction: the root cell is the cube around all primitive centroids. A
// cell is split at its centre into eight octants and each primitive goes to the
// octant holding its centroid, so every primitive lives in exactly one leaf and
// nothing is duplicated. Each child then gets TIGHT bounds: the union of its
// primitives' boxes, which may overlap the siblings' (primitives straddling an
// octant boundary). Chains of cells with a single non-empty octant are collapsed,
// and a node takes the octants of its largest inner children in their place
// while they fit in its eight slots (as wide BVHs are collapsed).
// The tree is flattened into one contiguous array of 8-wide nodes whose child
// boxes are stored as structure-of-arrays, so one loop tests all children.
//
// Queries (the interval and edge rules are those of triangle.hpp):
// - intersect: closest hit in [t_min, t_max], front-to-back, shrinking t_max.
// - occluded:  any hit in [t_min, t_max], returns at the first one found.
// `ignore_id` skips one primitive (a sample's own triangle). Primitive ids are
// the indices of the vector the tree was built from.
// Batch versions run on `threads` threads (0 = all cores) and return exactly
// what the single-ray calls return for each ray. They sort each chunk of rays
// by direction and trace them in packets (OctreeTraversal), so they are
// fastest when rays that share an endpoint (a viewpoint) are passed together.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "occlusion/core/aabb.hpp"
#include "occlusion/core/hit.hpp"
#include "occlusion/core/large_buffer.hpp"
#include "occlusion/core/progress.hpp"
#include "occlusion/core/ray.hpp"

namespace occlusion {

namespace octree_detail {
template <class Shape>
struct TreeView;
}  // namespace octree_detail

// How the batch queries trace. All give the same answers; they differ in speed.
enum class OctreeTraversal {
  kAuto,            // packets with AVX-512 or AVX2 if the CPU has them, else single rays
  kSingle,          // one ray at a time (the reference for the packet paths)
  kPacketSse2,      // eight rays at a time, SSE2 (x86-64 baseline; slower than kSingle)
  kPacketAvx2,      // eight rays at a time, AVX2
  kPacketAvx512,    // sixteen rays at a time, AVX-512F
  kPacketAvx2Wide,  // 32 rays at a time, AVX2: for coherent rays (BatchOrder::kAsGiven)
};
// Whether this build and CPU can run `traversal` (the octree refuses one it can't).
bool cpu_supports(OctreeTraversal traversal);

struct OctreeOptions {
  // Stop subdividing a cell that holds at most this many primitives.
  std::size_t max_leaf_size = 8;
  // Stop at this depth whatever the count (guards against coincident centroids).
  int max_depth = 24;
  // The config's `octree_resolution`: smallest cell edge length, in scene units.
  // A cell whose edge is at most this is not split. 0 means no limit.
  float min_cell_size = 0.0f;
  // The config's `enable_acceleration`: false puts every primitive in one leaf,
  // which makes every query a brute-force loop (a reference and a fallback).
  bool enable_acceleration = true;
  OctreeTraversal traversal = OctreeTraversal::kAuto;
};

// How a batch query forms its packets. kAsGiven is for rays that are
// coherent already: one viewpoint's rays to targets in Morton order point
// nearly the same way in runs, and a plan's candidates skip the sort's cost
// (9 % of a matrix, bench_plan). Such rays stay together down the tree, so
// where kAuto chose AVX2 they go 32 at a time (kPacketAvx2Wide).
enum class BatchOrder { kSortByDirection, kAsGiven };

struct OctreeStats {
  std::size_t primitives = 0;
  std::size_t inner_nodes = 0;
  std::size_t leaves = 0;
  int depth = 0;  // deepest leaf, root = 0
  std::size_t largest_leaf = 0;
  double build_seconds = 0.0;
  std::size_t memory_bytes = 0;
};

// count == 0: the inner node at nodes[index].
// count == kEmptySlot: no child in this slot.
// otherwise: a leaf, shapes[index .. index + count) (the octree holds fewer
// than kNoPrimitive shapes, so a leaf never has kEmptySlot of them).
struct OctreeChild {
  static constexpr std::uint32_t kEmptySlot = 0xffffffffu;
  std::uint32_t index;
  std::uint32_t count;
};

// One flattened 8-wide node: the boxes of up to eight children and where each
// lives, in exactly four cache lines (which slots are used is read off
// `child`, not kept beside it: a fifth line per node visit cost more than
// deriving it). Child k sits in slot k = its octant (bit 0: upper x, bit 1:
// upper y, bit 2: upper z), so a ray visits slots front to back in the order
// k ^ s, where s holds the signs of its direction: no sorting during traversal.
struct alignas(64) OctreeNode {
  float lo_x[8], lo_y[8], lo_z[8];
  float hi_x[8], hi_y[8], hi_z[8];
  // Where child k lives. Copied whole onto the traversal stacks: one 8-byte
  // store that the pop's 8-byte load forwards from, where two 4-byte stores
  // would make it wait.
  OctreeChild child[8];
};
static_assert(sizeof(OctreeNode) == 256, "an octree node is four cache lines");

// Shape must provide bounds() -> Aabb and centroid() -> Eigen::Vector3f, and a
// free function template shape_hit(const RayComponents<Num>&, const Shape&,
// Mask active, Num& t_hit) -> Mask following the rules above, for one ray
// (Num = float) and for packets (ray_lanes.hpp).
template <class Shape>
class Octree {
 public:
  Octree() = default;
  // Throws Cancelled when progress.cancel is set, before or during the build
  // (checked at every inner node, so a build of millions of shapes stops within
  // milliseconds).
  explicit Octree(std::vector<Shape> shapes, const OctreeOptions& options = {},
                  const Progress& progress = {});
  // The same from shapes in a LargeVector, whose pages are huge pages when
  // it is big (large_buffer.hpp): on a virtual machine a cold build of 100k
  // triangles spent more time faulting in fresh 4 KiB pages than building.
  // The tree takes the buffer and puts the shapes in leaf order in place,
  // with no second copy of them (octree_build.hpp, permute_in_place).
  explicit Octree(LargeVector<Shape>&& shapes, const OctreeOptions& options = {},
                  const Progress& progress = {});
  // From shapes the caller keeps (a cloud's surfels): the tree's sorted copy
  // is gathered from them directly, with no second copy to move from.
  explicit Octree(const LargeVector<Shape>& shapes, const OctreeOptions& options = {},
                  const Progress& progress = {});

  std::optional<Hit> intersect(const Ray& ray, PrimitiveId ignore_id = kNoPrimitive) const;
  bool occluded(const Ray& ray, PrimitiveId ignore_id = kNoPrimitive) const;

  // rays[i] -> hits[i] / occluded[i] (1 or 0). ignore_ids may be null (ignore nothing)
  // or point to `count` ids. `order` says whether the rays are grouped into
  // packets as given or sorted by direction first (ray_order.hpp); the answers
  // are the same either way.
  void intersect_batch(const Ray* rays, std::size_t count, const PrimitiveId* ignore_ids,
                       std::optional<Hit>* hits, unsigned threads = 0,
                       BatchOrder order = BatchOrder::kSortByDirection) const;
  void occluded_batch(const Ray* rays, std::size_t count, const PrimitiveId* ignore_ids,
                      std::uint8_t* occluded, unsigned threads = 0,
                      BatchOrder order = BatchOrder::kSortByDirection) const;

  std::size_t size() const { return shapes_.size(); }
  const Aabb& bounds() const { return bounds_; }
  const OctreeStats& stats() const { return stats_; }
  // The shape that was at index `id` of the construction vector.
  const Shape& shape(PrimitiveId id) const { return shapes_[position_of_[id]]; }
  // The same, to be made smaller in place: the tree's boxes are not refitted,
  // so it must stay within the bounds it had (a disc or a sphere given a
  // smaller radius), and no query may run meanwhile.
  Shape& shape_to_shrink(PrimitiveId id) { return shapes_[position_of_[id]]; }

 private:
  template <bool kAnyHit>
  std::optional<Hit> traverse(const Ray& ray, PrimitiveId ignore_id) const;
  // The flattened tree as the traversals read it.
  octree_detail::TreeView<Shape> view() const;
  // Both constructors: builds from `shapes` (a std::vector or a LargeVector), emptying it.
  template <class Shapes>
  void build(Shapes& shapes, const OctreeOptions& options, const Progress& progress);
  template <bool kAnyHit>
  void trace_batch(const Ray* rays, std::size_t count, const PrimitiveId* ignore_ids,
                   std::optional<Hit>* hits, std::uint8_t* occluded, unsigned threads,
                   BatchOrder order) const;

  LargeVector<OctreeNode> nodes_;           // nodes_[0] is the root
  LargeVector<Shape> shapes_;               // in leaf order
  LargeVector<PrimitiveId> ids_;            // ids_[leaf position] = original index
  LargeVector<std::uint32_t> position_of_;  // inverse of ids_
  Aabb bounds_;
  float magnitude_ = 0.0f;  // largest coordinate magnitude of the padded bounds (TreeView)
  OctreeStats stats_;
  OctreeTraversal traversal_ = OctreeTraversal::kAuto;  // resolved: never kAuto
  // What BatchOrder::kAsGiven batches use: traversal_, or wider packets where kAuto chose AVX2.
  OctreeTraversal coherent_traversal_ = OctreeTraversal::kAuto;
};

}  // namespace occlusion
