#pragma once
// Building the octree in time linear in the primitives.
//
// Splitting a cell at its centre into octants, again and again, sorts the
// primitives by the Morton code of their centroid in the root cube: the three
// bits of level L of the code say which octant of its level-L cell a centroid
// falls in. So the builder computes each centroid's code (21 levels), radix
// sorts the primitives by it, and reads the tree off the sorted codes: a cell
// is a run of codes with a common prefix, its octants are sub-runs found by
// binary search, and levels where a run does not split are skipped without a
// node (the chains of single octants the recursive builder used to collapse).
// Leaves are contiguous runs of the sorted primitives, so their boxes are read
// sequentially. Coding and sorting run on all cores.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "occlusion/core/large_buffer.hpp"
#include "occlusion/core/morton.hpp"
#include "occlusion/core/octree.hpp"
#include "occlusion/core/parallel.hpp"
#include "occlusion/core/progress.hpp"

namespace occlusion::octree_detail {

// A child under construction: a leaf range of shapes or an inner node.
struct BuiltChild {
  int octant = 0;  // slot in the parent node
  std::uint32_t index = 0;
  std::uint32_t count = 0;  // 0 = inner node
  Aabb box;
};

inline void fill_node(OctreeNode& node, const BuiltChild* children, std::uint32_t child_count) {
  node = OctreeNode{};
  // Unused slots hold a zero box; traversal masks them with `occupied`.
  std::fill(std::begin(node.lo_x), std::end(node.lo_x), 0.0f);
  std::fill(std::begin(node.lo_y), std::end(node.lo_y), 0.0f);
  std::fill(std::begin(node.lo_z), std::end(node.lo_z), 0.0f);
  std::fill(std::begin(node.hi_x), std::end(node.hi_x), 0.0f);
  std::fill(std::begin(node.hi_y), std::end(node.hi_y), 0.0f);
  std::fill(std::begin(node.hi_z), std::end(node.hi_z), 0.0f);
  std::fill(std::begin(node.child), std::end(node.child), OctreeChild{0, 0});
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
    node.child[k] = OctreeChild{children[c].index, children[c].count};
  }
}

// Stable LSD radix sort of (codes[i], ids[i]) by code, on all cores: each
// pass counts digits per part in parallel, then scatters each part to its own
// offsets. Passes whose digit is the same for every code are skipped.
inline void radix_sort_codes(LargeVector<std::uint64_t>& codes, LargeVector<std::uint32_t>& ids,
                             const Progress& progress) {
  constexpr int kDigitBits = 11;
  constexpr std::size_t kBuckets = std::size_t{1} << kDigitBits;
  const std::size_t n = codes.size();
  const unsigned parts = std::max(
      1u, std::min<unsigned>(resolve_thread_count(0), static_cast<unsigned>(n / 65536 + 1)));
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

template <class Shape>
class MortonBuilder {
 public:
  MortonBuilder(const OctreeOptions& options, LargeVector<OctreeNode>& nodes, OctreeStats& stats,
                const Progress& progress)
      : options_(options), nodes_(nodes), stats_(stats), progress_(progress) {}

  // Moves `shapes` in leaf order into `sorted` (ids[position] = index in
  // `shapes`), builds the nodes, and returns the root: an inner node, or a
  // leaf when the whole scene is one. `shapes` is emptied once sorted, so the
  // two copies never live beside the nodes (16 bytes a sphere at the peak).
  BuiltChild build(std::vector<Shape>& shapes, LargeVector<Shape>& sorted,
                   LargeVector<PrimitiveId>& ids) {
    const std::size_t n = shapes.size();
    Aabb centroid_box;
    for (const Shape& shape : shapes) centroid_box.extend(shape.centroid());
    root_half_ = 0.5f * centroid_box.extent().maxCoeff();

    codes_.resize(n);
    ids.resize(n);
    const Eigen::Vector3d centre = centroid_box.center().cast<double>();
    const double half = root_half_;
    const double scale = half > 0.0 ? std::ldexp(1.0, kMortonLevels) / (2.0 * half) : 0.0;
    constexpr double kLastCell = kMortonLastCell;
    parallel_for(n, std::size_t{1} << 16, 0, [&](std::size_t first, std::size_t last) {
      progress_.check_cancel();
      for (std::size_t i = first; i < last; ++i) {
        const Eigen::Vector3d c = shapes[i].centroid().template cast<double>();
        std::uint64_t code = 0;
        for (int axis = 0; axis < 3; ++axis) {
          const double cell = std::floor((c[axis] - (centre[axis] - half)) * scale);
          const auto q = static_cast<std::uint32_t>(std::clamp(cell, 0.0, kLastCell));
          code |= spread_by_three(q) << axis;
        }
        codes_[i] = code;
        ids[i] = static_cast<PrimitiveId>(i);
      }
    });
    radix_sort_codes(codes_, ids, progress_);

    sorted.resize(n);
    parallel_for(n, std::size_t{1} << 16, 0, [&](std::size_t first, std::size_t last) {
      progress_.check_cancel();
      for (std::size_t i = first; i < last; ++i) sorted[i] = shapes[ids[i]];
    });
    std::vector<Shape>().swap(shapes);
    sorted_ = &sorted;
    BuiltChild root = build_range(0, static_cast<std::uint32_t>(n), 0);
    LargeVector<std::uint64_t>().swap(codes_);
    return root;
  }

 private:
  // Whether a cell of `count` primitives at geometric level `level` stays a leaf.
  bool is_leaf(std::uint32_t count, int level) const {
    const float half = std::ldexp(root_half_, -level);
    return !options_.enable_acceleration || count <= options_.max_leaf_size ||
           level >= options_.max_depth || 2.0f * half <= options_.min_cell_size || half <= 0.0f;
  }

  int octant_at(std::uint32_t i, int level) const {
    return static_cast<int>((codes_[i] >> (3 * (kMortonLevels - 1 - level))) & 7u);
  }

  BuiltChild make_leaf(std::uint32_t begin, std::uint32_t end, int depth) {
    BuiltChild leaf;
    leaf.index = begin;
    leaf.count = end - begin;
    for (std::uint32_t i = begin; i < end; ++i) leaf.box.extend((*sorted_)[i].bounds());
    ++stats_.leaves;
    stats_.depth = std::max(stats_.depth, depth);
    stats_.largest_leaf = std::max<std::size_t>(stats_.largest_leaf, leaf.count);
    return leaf;
  }

  // The cell holding sorted primitives [begin, end): the smallest cell whose
  // code prefix they share.
  BuiltChild build_range(std::uint32_t begin, std::uint32_t end, int depth) {
    const std::uint64_t differ = codes_[begin] ^ codes_[end - 1];
    // The first level at which the run splits; levels before it hold one octant.
    const int split =
        differ == 0 ? kMortonLevels : kMortonLevels - 1 - (63 - __builtin_clzll(differ)) / 3;
    // is_leaf only grows more true with the level, so checking `split` covers the
    // skipped levels too.
    if (split == kMortonLevels || is_leaf(end - begin, split)) return make_leaf(begin, end, depth);

    // A relaxed load per inner node: a cancelled build stops within a few nodes.
    progress_.check_cancel();
    const auto node_index = static_cast<std::uint32_t>(nodes_.size());
    nodes_.emplace_back();
    ++stats_.inner_nodes;
    std::array<BuiltChild, 8> children;
    std::uint32_t child_count = 0;
    std::uint32_t child_begin = begin;
    while (child_begin < end) {
      const int k = octant_at(child_begin, split);
      // Codes are sorted and share the bits above `split`: octant k's run ends
      // at the first code with a higher octant.
      std::uint32_t lo = child_begin, hi = end;
      while (lo < hi) {
        const std::uint32_t mid = lo + (hi - lo) / 2;
        if (octant_at(mid, split) <= k) {
          lo = mid + 1;
        } else {
          hi = mid;
        }
      }
      children[child_count] = build_range(child_begin, lo, depth + 1);
      children[child_count++].octant = k;
      child_begin = lo;
    }
    // Fill after recursion: nodes_ may have reallocated meanwhile.
    fill_node(nodes_[node_index], children.data(), child_count);
    BuiltChild self;
    self.index = node_index;
    for (std::uint32_t c = 0; c < child_count; ++c) self.box.extend(children[c].box);
    return self;
  }

  const OctreeOptions& options_;
  LargeVector<OctreeNode>& nodes_;
  OctreeStats& stats_;
  const Progress& progress_;
  const LargeVector<Shape>* sorted_ = nullptr;
  LargeVector<std::uint64_t> codes_;
  float root_half_ = 0.0f;
};

}  // namespace occlusion::octree_detail
