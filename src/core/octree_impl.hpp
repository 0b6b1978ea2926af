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
#include "octree_build.hpp"
#include "octree_packet.hpp"
#include "octree_single_ray.hpp"
#include "octree_slab.hpp"
#include "ray_order.hpp"

namespace occlusion {

template <class Shape>
Octree<Shape>::Octree(std::vector<Shape> shapes, const OctreeOptions& options,
                      const Progress& progress) {
  build(shapes, options, progress);
}

template <class Shape>
Octree<Shape>::Octree(LargeVector<Shape>&& shapes, const OctreeOptions& options,
                      const Progress& progress) {
  build(shapes, options, progress);
}

template <class Shape>
Octree<Shape>::Octree(const LargeVector<Shape>& shapes, const OctreeOptions& options,
                      const Progress& progress) {
  build(shapes, options, progress);
}

template <class Shape>
template <class Shapes>
void Octree<Shape>::build(Shapes& shapes, const OctreeOptions& options, const Progress& progress) {
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
  coherent_traversal_ =
      options.traversal == OctreeTraversal::kAuto && traversal_ == OctreeTraversal::kPacketAvx2
          ? OctreeTraversal::kPacketAvx2Wide
          : traversal_;
  progress.check_cancel();
  const auto start = std::chrono::steady_clock::now();
  stats_ = OctreeStats{};
  stats_.primitives = shapes.size();
  for (const Shape& shape : shapes) bounds_.extend(shape.bounds());
  if (!shapes.empty()) {
    const Aabb padded = pad_box(bounds_);
    magnitude_ = std::max(padded.lo.cwiseAbs().maxCoeff(), padded.hi.cwiseAbs().maxCoeff());
  }

  if (!shapes.empty()) {
    // Room for the usual tree (about one node per max_leaf_size / 2 shapes)
    // up front: growing copies the nodes and touches their pages twice, and
    // reserved pages never written cost nothing.
    nodes_.reserve(std::min(shapes.size(), 2 * shapes.size() / options.max_leaf_size + 64));
    octree_detail::MortonBuilder<Shape> builder(options, nodes_, stats_, progress);
    const octree_detail::BuiltChild top = builder.build(shapes, shapes_, ids_);
    if (top.count > 0) {
      // The whole scene is one leaf: give it a root node to live in.
      nodes_.emplace_back();
      octree_detail::fill_node(nodes_[0], &top, 1);
    }
    position_of_.resize(ids_.size());
    for (std::uint32_t position = 0; position < ids_.size(); ++position) {
      position_of_[ids_[position]] = position;
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
  return octree_detail::trace_single_ray<Shape, kAnyHit>(
      view(), ray_components(query), safe_inverse(query.direction), ignore_id, 0, std::nullopt);
}

template <class Shape>
octree_detail::TreeView<Shape> Octree<Shape>::view() const {
  if (nodes_.empty()) return {};
  return {nodes_.data(), shapes_.data(), ids_.data(), magnitude_};
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
// Rays per parallel chunk: one sort window.
inline constexpr std::size_t kBatchGrain = kOrderWindow;
}  // namespace octree_detail

template <class Shape>
template <bool kAnyHit>
void Octree<Shape>::trace_batch(const Ray* rays, std::size_t count, const PrimitiveId* ignore_ids,
                                std::optional<Hit>* hits, std::uint8_t* occluded_out,
                                unsigned threads, BatchOrder ray_order) const {
  const auto single = [&](std::size_t i) {
    const std::optional<Hit> hit =
        traverse<kAnyHit>(rays[i], ignore_ids ? ignore_ids[i] : kNoPrimitive);
    if constexpr (kAnyHit) {
      occluded_out[i] = hit ? 1 : 0;
    } else {
      hits[i] = hit;
    }
  };
  const OctreeTraversal traversal =
      ray_order == BatchOrder::kAsGiven ? coherent_traversal_ : traversal_;
  if (traversal == OctreeTraversal::kSingle) {
    parallel_for(count, octree_detail::kBatchGrain, threads, [&](std::size_t b, std::size_t e) {
      for (std::size_t i = b; i < e; ++i) single(i);
    });
    return;
  }
#if OCCLUSION_PACKETS
  const octree_detail::TreeView<Shape> tree = view();
  const octree_detail::PacketQuery query{rays, ignore_ids, hits, occluded_out};
  parallel_for(count, octree_detail::kBatchGrain, threads, [&](std::size_t b, std::size_t e) {
    thread_local std::vector<std::uint32_t> order, scratch;
    for (std::size_t window = b; window < e; window += kOrderWindow) {
      const std::size_t window_end = std::min(e, window + kOrderWindow);
      const std::size_t n = window_end - window;
      order.resize(n);
      if (ray_order == BatchOrder::kAsGiven) {
        for (std::size_t k = 0; k < n; ++k) order[k] = static_cast<std::uint32_t>(window + k);
      } else {
        order_by_direction(rays, window, window_end, order.data(), scratch);
      }
      switch (traversal) {
        case OctreeTraversal::kPacketAvx512:
          octree_detail::packet_avx512::trace_packets<Shape, kAnyHit>(tree, query, order.data(), n);
          break;
        case OctreeTraversal::kPacketAvx2:
          octree_detail::packet_avx2::trace_packets<Shape, kAnyHit>(tree, query, order.data(), n);
          break;
        case OctreeTraversal::kPacketAvx2Wide:
          octree_detail::packet_avx2_wide::trace_packets<Shape, kAnyHit>(tree, query, order.data(),
                                                                         n);
          break;
        default:
          octree_detail::packet_sse2::trace_packets<Shape, kAnyHit>(tree, query, order.data(), n);
          break;
      }
    }
  });
#endif
}

template <class Shape>
void Octree<Shape>::intersect_batch(const Ray* rays, std::size_t count,
                                    const PrimitiveId* ignore_ids, std::optional<Hit>* hits,
                                    unsigned threads, BatchOrder order) const {
  trace_batch<false>(rays, count, ignore_ids, hits, nullptr, threads, order);
}

template <class Shape>
void Octree<Shape>::occluded_batch(const Ray* rays, std::size_t count,
                                   const PrimitiveId* ignore_ids, std::uint8_t* occluded_out,
                                   unsigned threads, BatchOrder order) const {
  trace_batch<true>(rays, count, ignore_ids, nullptr, occluded_out, threads, order);
}

}  // namespace occlusion
