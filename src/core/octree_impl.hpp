#pragma once
// The octree's template definitions. Included only by the .cpp files that
// instantiate Octree for a shape type, so users of octree.hpp don't compile it.

#include <algorithm>
#include <array>
#include <chrono>
#include <stdexcept>
#include <string>

#include "occlusion/core/octree.hpp"
#include "occlusion/core/parallel.hpp"
#include "octree_packet.hpp"
#include "octree_slab.hpp"
#include "ray_order.hpp"

namespace occlusion {

namespace octree_detail {

// A child under construction: a leaf range of shapes or an inner node.
struct BuiltChild {
  int octant = 0;  // slot in the parent node
  std::uint32_t index = 0;
  std::uint32_t count = 0;  // 0 = inner node
  Aabb box;
};

template <class Shape>
class Builder {
 public:
  Builder(const std::vector<Shape>& shapes, const OctreeOptions& options,
          std::vector<OctreeNode>& nodes, std::vector<std::uint32_t>& order, OctreeStats& stats,
          const Progress& progress)
      : shapes_(shapes),
        options_(options),
        nodes_(nodes),
        order_(order),
        stats_(stats),
        progress_(progress) {
    boxes_.reserve(shapes.size());
    centroids_.reserve(shapes.size());
    for (const Shape& shape : shapes) {
      boxes_.push_back(shape.bounds());
      centroids_.push_back(shape.centroid());
    }
    scratch_.resize(shapes.size());
  }

  BuiltChild build_root() {
    Aabb centroid_box;
    for (const auto& c : centroids_) centroid_box.extend(c);
    const float half = 0.5f * centroid_box.extent().maxCoeff();
    return build(0, static_cast<std::uint32_t>(order_.size()), centroid_box.center(), half, 0);
  }

 private:
  bool is_leaf(std::uint32_t count, float half, int depth) const {
    return !options_.enable_acceleration || count <= options_.max_leaf_size ||
           depth >= options_.max_depth || 2.0f * half <= options_.min_cell_size || half <= 0.0f;
  }

  BuiltChild make_leaf(std::uint32_t begin, std::uint32_t end, int depth) {
    BuiltChild leaf;
    leaf.index = begin;
    leaf.count = end - begin;
    for (std::uint32_t i = begin; i < end; ++i) leaf.box.extend(boxes_[order_[i]]);
    ++stats_.leaves;
    stats_.depth = std::max(stats_.depth, depth);
    stats_.largest_leaf = std::max<std::size_t>(stats_.largest_leaf, leaf.count);
    return leaf;
  }

  static int octant_of(const Eigen::Vector3f& p, const Eigen::Vector3f& centre) {
    return (p.x() >= centre.x() ? 1 : 0) | (p.y() >= centre.y() ? 2 : 0) |
           (p.z() >= centre.z() ? 4 : 0);
  }

  static Eigen::Vector3f octant_centre(int octant, const Eigen::Vector3f& centre, float half) {
    const float q = 0.5f * half;
    return centre +
           Eigen::Vector3f((octant & 1) ? q : -q, (octant & 2) ? q : -q, (octant & 4) ? q : -q);
  }

  // Sorts order_[begin, end) by octant (a stable counting sort) and returns the
  // start of each octant's run; starts[8] == end.
  std::array<std::uint32_t, 9> partition(std::uint32_t begin, std::uint32_t end,
                                         const Eigen::Vector3f& centre) {
    std::array<std::uint32_t, 9> starts{};
    for (std::uint32_t i = begin; i < end; ++i) {
      ++starts[octant_of(centroids_[order_[i]], centre) + 1];
    }
    starts[0] = begin;
    for (int k = 1; k <= 8; ++k) starts[k] += starts[k - 1];
    std::array<std::uint32_t, 8> cursor;
    std::copy(starts.begin(), starts.begin() + 8, cursor.begin());
    for (std::uint32_t i = begin; i < end; ++i) {
      const std::uint32_t id = order_[i];
      scratch_[cursor[octant_of(centroids_[id], centre)]++] = id;
    }
    std::copy(scratch_.begin() + begin, scratch_.begin() + end, order_.begin() + begin);
    return starts;
  }

  BuiltChild build(std::uint32_t begin, std::uint32_t end, Eigen::Vector3f centre, float half,
                   int depth) {
    std::array<std::uint32_t, 9> starts;
    int cell_level = depth;
    for (;;) {
      if (is_leaf(end - begin, half, cell_level)) return make_leaf(begin, end, depth);
      starts = partition(begin, end, centre);
      int occupied = 0, last = 0;
      for (int k = 0; k < 8; ++k) {
        if (starts[k + 1] > starts[k]) {
          ++occupied;
          last = k;
        }
      }
      if (occupied > 1) break;
      // One occupied octant: descend into it without making a node.
      centre = octant_centre(last, centre, half);
      half *= 0.5f;
      ++cell_level;
    }

    // A relaxed load per inner node (a node costs a partition of its
    // shapes): a cancelled build stops within a few nodes.
    progress_.check_cancel();
    const auto node_index = static_cast<std::uint32_t>(nodes_.size());
    nodes_.emplace_back();
    ++stats_.inner_nodes;
    std::array<BuiltChild, 8> children;
    std::uint32_t child_count = 0;
    for (int k = 0; k < 8; ++k) {
      if (starts[k + 1] == starts[k]) continue;
      children[child_count] =
          build(starts[k], starts[k + 1], octant_centre(k, centre, half), 0.5f * half, depth + 1);
      children[child_count++].octant = k;
    }
    // Fill after recursion: nodes_ may have reallocated meanwhile.
    OctreeNode& node = nodes_[node_index];
    fill_node(node, children.data(), child_count);
    BuiltChild self;
    self.index = node_index;
    for (std::uint32_t k = 0; k < child_count; ++k) self.box.extend(children[k].box);
    return self;
  }

 public:
  static void fill_node(OctreeNode& node, const BuiltChild* children, std::uint32_t child_count) {
    node = OctreeNode{};
    // Unused slots hold a zero box; traversal masks them with `occupied`.
    std::fill(std::begin(node.lo_x), std::end(node.lo_x), 0.0f);
    std::fill(std::begin(node.lo_y), std::end(node.lo_y), 0.0f);
    std::fill(std::begin(node.lo_z), std::end(node.lo_z), 0.0f);
    std::fill(std::begin(node.hi_x), std::end(node.hi_x), 0.0f);
    std::fill(std::begin(node.hi_y), std::end(node.hi_y), 0.0f);
    std::fill(std::begin(node.hi_z), std::end(node.hi_z), 0.0f);
    std::fill(std::begin(node.index), std::end(node.index), 0u);
    std::fill(std::begin(node.count), std::end(node.count), 0u);
    for (std::uint32_t c = 0; c < child_count; ++c) {
      const int k = children[c].octant;
      node.occupied |= 1u << k;
      // Padded: the traversal's branch-free slab test relies on it (aabb.hpp).
      const Aabb box = pad_box(children[c].box);
      node.lo_x[k] = box.lo.x();
      node.lo_y[k] = box.lo.y();
      node.lo_z[k] = box.lo.z();
      node.hi_x[k] = box.hi.x();
      node.hi_y[k] = box.hi.y();
      node.hi_z[k] = box.hi.z();
      node.index[k] = children[c].index;
      node.count[k] = children[c].count;
    }
  }

 private:
  const std::vector<Shape>& shapes_;
  const OctreeOptions& options_;
  std::vector<OctreeNode>& nodes_;
  std::vector<std::uint32_t>& order_;
  OctreeStats& stats_;
  const Progress& progress_;
  std::vector<Aabb> boxes_;
  std::vector<Eigen::Vector3f> centroids_;
  std::vector<std::uint32_t> scratch_;
};

}  // namespace octree_detail

template <class Shape>
Octree<Shape>::Octree(std::vector<Shape> shapes, const OctreeOptions& options,
                      const Progress& progress) {
  if (options.max_leaf_size == 0) {
    throw std::invalid_argument("octree: max_leaf_size must be at least 1");
  }
  if (options.max_depth < 0 || options.max_depth > octree_detail::kMaxDepthLimit) {
    throw std::invalid_argument("octree: max_depth must be in [0, " +
                                std::to_string(octree_detail::kMaxDepthLimit) + "]");
  }
  if (!(options.min_cell_size >= 0.0f)) {
    throw std::invalid_argument("octree: octree_resolution must be >= 0");
  }
  if (shapes.size() >= kNoPrimitive) {
    throw std::invalid_argument("octree: too many primitives");
  }
  traversal_ = options.traversal;
  if (traversal_ == OctreeTraversal::kAuto) traversal_ = octree_detail::best_packet_traversal();
  if (!cpu_supports(traversal_)) {
    throw std::invalid_argument("octree: this build or CPU cannot run the traversal asked for");
  }
  progress.check_cancel();
  const auto start = std::chrono::steady_clock::now();
  stats_ = OctreeStats{};
  stats_.primitives = shapes.size();
  for (const Shape& shape : shapes) bounds_.extend(shape.bounds());

  if (!shapes.empty()) {
    std::vector<std::uint32_t> order(shapes.size());
    for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    octree_detail::Builder<Shape> builder(shapes, options, nodes_, order, stats_, progress);
    const octree_detail::BuiltChild top = builder.build_root();
    if (top.count > 0) {
      // The whole scene is one leaf: give it a root node to live in.
      nodes_.emplace_back();
      octree_detail::Builder<Shape>::fill_node(nodes_[0], &top, 1);
    }
    shapes_.reserve(shapes.size());
    ids_ = order;
    position_of_.resize(order.size());
    for (std::uint32_t position = 0; position < order.size(); ++position) {
      shapes_.push_back(shapes[order[position]]);
      position_of_[order[position]] = position;
    }
  }
  stats_.memory_bytes = nodes_.size() * sizeof(OctreeNode) + shapes_.size() * sizeof(Shape) +
                        (ids_.size() + position_of_.size()) * sizeof(std::uint32_t);
  stats_.build_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

template <class Shape>
template <bool kAnyHit>
std::optional<Hit> Octree<Shape>::traverse(const Ray& query, PrimitiveId ignore_id) const {
  if (nodes_.empty() || !(query.t_min <= query.t_max)) return std::nullopt;
  Ray ray = query;  // t_max shrinks as closer hits are found
  const Eigen::Vector3f inv = safe_inverse(ray.direction);
  const float direction_length = ray.direction.norm();
  octree_detail::SlabRay slab(ray.origin, inv, ray.t_min, ray.t_max);
  // The octant a ray enters first: lower half along an axis it travels up.
  const int near_octant = (ray.direction.x() < 0.0f ? 1 : 0) | (ray.direction.y() < 0.0f ? 2 : 0) |
                          (ray.direction.z() < 0.0f ? 4 : 0);

  struct Entry {
    std::uint32_t index;
    std::uint32_t count;  // 0 = inner node
    float t_enter;
  };
  Entry stack[octree_detail::kStackSize];
  std::size_t top = 0;
  stack[top++] = {0, 0, ray.t_min};
  std::optional<Hit> best;

  while (top > 0) {
    const Entry entry = stack[--top];
    // Only a closest-hit query shrinks t_max below what a child was pushed with.
    if (!kAnyHit && entry.t_enter > ray.t_max) continue;
    if (entry.count > 0) {
      const std::uint32_t end = entry.index + entry.count;
      for (std::uint32_t i = entry.index; i < end; ++i) {
        const PrimitiveId id = ids_[i];
        if (id == ignore_id) continue;
        const std::optional<float> t = intersect_shape(ray, direction_length, shapes_[i]);
        if (!t) continue;
        if constexpr (kAnyHit) {
          return Hit{*t, id};
        } else {
          // t <= t_max == best->t_hit here, so this takes a closer hit, and on a tie
          // the lower id: the answer does not depend on traversal order.
          if (!best || *t < best->t_hit || id < best->primitive_id) {
            best = Hit{*t, id};
            ray.t_max = *t;
            slab.set_t_max(*t);
          }
        }
      }
      continue;
    }

    const OctreeNode& node = nodes_[entry.index];
    // All eight slots in one fixed-length loop the compiler can vectorise;
    // empty slots are masked out with `occupied` below.
    float t_near[8];
    std::uint32_t hit_mask = octree_detail::slab_test_8(node, slab, t_near);
    hit_mask &= node.occupied;
    // Push farthest first so that the nearest is popped next: relabel slot k as
    // k ^ near_octant (front-to-back rank) and push from the highest rank down.
    std::uint32_t ranked = octree_detail::kRankedMask[near_octant][hit_mask];
    while (ranked != 0) {
      const int rank = 31 - __builtin_clz(ranked);
      ranked &= ~(1u << rank);
      const int k = rank ^ near_octant;
      stack[top++] = Entry{node.index[k], node.count[k], t_near[k]};
    }
  }
  return best;
}

template <class Shape>
std::optional<Hit> Octree<Shape>::intersect(const Ray& ray, PrimitiveId ignore_id) const {
  return traverse<false>(ray, ignore_id);
}

template <class Shape>
bool Octree<Shape>::occluded(const Ray& ray, PrimitiveId ignore_id) const {
  return traverse<true>(ray, ignore_id).has_value();
}

namespace octree_detail {
// Rays sorted by direction together. Callers pass rays in a spatially coherent
// order (a viewpoint's rays together, neighbouring samples together); sorting
// a window refines that order into packets without mixing far-apart rays that
// happen to point the same way. bench_moc-like shadow rays, AVX-512, one
// thread: windows of 64 / 1,024 / 4,096 / 16,384 / 65,536 rays gave 5.6 / 5.6 /
// 6.0 / 5.4 / 4.6 M rays/s (single rays: 3.5).
inline constexpr std::size_t kSortWindow = 4096;
// Rays per parallel chunk: one window.
inline constexpr std::size_t kBatchGrain = kSortWindow;
}  // namespace octree_detail

template <class Shape>
template <bool kAnyHit>
void Octree<Shape>::trace_batch(const Ray* rays, std::size_t count, const PrimitiveId* ignore_ids,
                                std::optional<Hit>* hits, std::uint8_t* occluded_out,
                                unsigned threads) const {
  const auto single = [&](std::size_t i) {
    const std::optional<Hit> hit =
        traverse<kAnyHit>(rays[i], ignore_ids ? ignore_ids[i] : kNoPrimitive);
    if constexpr (kAnyHit) {
      occluded_out[i] = hit ? 1 : 0;
    } else {
      hits[i] = hit;
    }
  };
  if (traversal_ == OctreeTraversal::kSingle) {
    parallel_for(count, octree_detail::kBatchGrain, threads, [&](std::size_t b, std::size_t e) {
      for (std::size_t i = b; i < e; ++i) single(i);
    });
    return;
  }
#if OCCLUSION_PACKETS
  octree_detail::TreeView<Shape> view;
  if (!nodes_.empty()) view = {nodes_.data(), shapes_.data(), ids_.data()};
  const octree_detail::PacketQuery query{rays, ignore_ids, hits, occluded_out};
  parallel_for(count, octree_detail::kBatchGrain, threads, [&](std::size_t b, std::size_t e) {
    thread_local std::vector<std::uint32_t> order, scratch;
    for (std::size_t window = b; window < e; window += octree_detail::kSortWindow) {
      const std::size_t window_end = std::min(e, window + octree_detail::kSortWindow);
      const std::size_t n = window_end - window;
      order.resize(n);
      order_by_direction(rays, window, window_end, order.data(), scratch);
      switch (traversal_) {
        case OctreeTraversal::kPacketAvx512:
          octree_detail::packet_avx512::trace_packets<Shape, kAnyHit>(view, query, order.data(), n);
          break;
        case OctreeTraversal::kPacketAvx2:
          octree_detail::packet_avx2::trace_packets<Shape, kAnyHit>(view, query, order.data(), n);
          break;
        default:
          octree_detail::packet_sse2::trace_packets<Shape, kAnyHit>(view, query, order.data(), n);
          break;
      }
    }
  });
#endif
}

template <class Shape>
void Octree<Shape>::intersect_batch(const Ray* rays, std::size_t count,
                                    const PrimitiveId* ignore_ids, std::optional<Hit>* hits,
                                    unsigned threads) const {
  trace_batch<false>(rays, count, ignore_ids, hits, nullptr, threads);
}

template <class Shape>
void Octree<Shape>::occluded_batch(const Ray* rays, std::size_t count,
                                   const PrimitiveId* ignore_ids, std::uint8_t* occluded_out,
                                   unsigned threads) const {
  trace_batch<true>(rays, count, ignore_ids, nullptr, occluded_out, threads);
}

}  // namespace occlusion
