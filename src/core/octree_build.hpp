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
#include <type_traits>
#include <utility>
#include <vector>

#include "occlusion/core/large_buffer.hpp"
#include "occlusion/core/morton.hpp"
#include "occlusion/core/octree.hpp"
#include "occlusion/core/parallel.hpp"
#include "occlusion/core/progress.hpp"
#include "radix_sort_codes.hpp"

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
  // Unused slots hold a zero box and an empty child; traversal masks them out
  // (occupied_slots).
  std::fill(std::begin(node.lo_x), std::end(node.lo_x), 0.0f);
  std::fill(std::begin(node.lo_y), std::end(node.lo_y), 0.0f);
  std::fill(std::begin(node.lo_z), std::end(node.lo_z), 0.0f);
  std::fill(std::begin(node.hi_x), std::end(node.hi_x), 0.0f);
  std::fill(std::begin(node.hi_y), std::end(node.hi_y), 0.0f);
  std::fill(std::begin(node.hi_z), std::end(node.hi_z), 0.0f);
  std::fill(std::begin(node.child), std::end(node.child), OctreeChild{0, OctreeChild::kEmptySlot});
  for (std::uint32_t c = 0; c < child_count; ++c) {
    const int k = children[c].octant;
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

// Puts owned shapes in leaf order in place: shapes[position] = the shape at
// ids[position] before. A gather into a second array (as for shapes the
// caller keeps) would hold two copies of them at once, 28 bytes a point for
// surfels at a big cloud's peak. A permutation followed cycle by cycle would
// do without, but its random reads depend one on the next; instead the
// shapes go in one pass to blocks of kBlock consecutive positions (an
// American flag sort pass: a few thousand blocks, each filled front to back,
// so the writes stream), then each block is put in order in a buffer of its
// own, on all cores.
template <class Shape>
void permute_in_place(LargeVector<Shape>& shapes, const LargeVector<PrimitiveId>& ids,
                      const Progress& progress) {
  const std::size_t n = shapes.size();
  // Blocks of 2^bits positions, at most about 4,096 of them, each at least
  // 1,024 shapes (a block's buffer stays in the core's cache).
  int bits = 10;
  while ((n >> bits) > 4096) ++bits;
  const std::size_t block_count = (n >> bits) + 1;
  LargeVector<std::uint32_t> position(n);  // where shapes[i] goes; moves with it
  parallel_for(n, std::size_t{1} << 16, 0, [&](std::size_t first, std::size_t last) {
    for (std::size_t p = first; p < last; ++p) position[ids[p]] = static_cast<std::uint32_t>(p);
  });
  std::vector<std::size_t> next(block_count);  // the block's first slot not yet filled
  for (std::size_t b = 0; b < block_count; ++b) next[b] = std::min(n, b << bits);
  for (std::size_t b = 0; b < block_count; ++b) {
    progress.check_cancel();
    const std::size_t end = std::min(n, (b + 1) << bits);
    while (next[b] < end) {
      Shape carried = shapes[next[b]];
      std::uint32_t to = position[next[b]];
      // Carry the shape to its block's next slot and take what lay there,
      // until one belongs in block b.
      for (std::size_t home = to >> bits; home != b; home = to >> bits) {
        const std::size_t slot = next[home]++;
        std::swap(carried, shapes[slot]);
        std::swap(to, position[slot]);
      }
      shapes[next[b]] = carried;
      position[next[b]++] = to;
    }
  }
  parallel_for(block_count, 1, 0, [&](std::size_t first, std::size_t last) {
    std::vector<Shape> block(std::size_t{1} << bits);
    for (std::size_t b = first; b < last; ++b) {
      const std::size_t begin = b << bits, end = std::min(n, (b + 1) << bits);
      for (std::size_t i = begin; i < end; ++i) block[position[i] - begin] = shapes[i];
      std::copy(block.begin(), block.begin() + static_cast<std::ptrdiff_t>(end - begin),
                shapes.begin() + static_cast<std::ptrdiff_t>(begin));
    }
  });
}

template <class Shape>
class MortonBuilder {
 public:
  MortonBuilder(const OctreeOptions& options, LargeVector<OctreeNode>& nodes, OctreeStats& stats,
                const Progress& progress)
      : options_(options), nodes_(nodes), stats_(stats), progress_(progress) {}

  // Moves `shapes` in leaf order into `sorted` (ids[position] = index in
  // `shapes`), builds the nodes, and returns the root: an inner node, or a
  // leaf when the whole scene is one. A LargeVector of shapes is put in
  // order in place and becomes `sorted`; other owned shapes are gathered and
  // emptied once sorted, so the two copies never live beside the nodes (16
  // bytes a sphere at the peak); const ones (the caller's) are gathered.
  template <class Shapes>
  BuiltChild build(Shapes& shapes, LargeVector<Shape>& sorted, LargeVector<PrimitiveId>& ids) {
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

    if constexpr (std::is_same_v<Shapes, LargeVector<Shape>>) {
      permute_in_place(shapes, ids, progress_);
      sorted.swap(shapes);
      LargeVector<Shape>().swap(shapes);
    } else {
      sorted.resize(n);
      parallel_for(n, std::size_t{1} << 16, 0, [&](std::size_t first, std::size_t last) {
        progress_.check_cancel();
        for (std::size_t i = first; i < last; ++i) sorted[i] = shapes[ids[i]];
      });
      if constexpr (!std::is_const_v<Shapes>) std::remove_cv_t<Shapes>().swap(shapes);
    }
    sorted_ = &sorted;
    BuiltChild root;
    if (is_leaf_run(0, static_cast<std::uint32_t>(n))) {
      root = make_leaf(0, static_cast<std::uint32_t>(n));
    } else {
      nodes_.emplace_back();  // the root is nodes_[0]
      ++stats_.inner_nodes;
      stats_.depth = build_node(0, 0, static_cast<std::uint32_t>(n), root.box);
      root.index = 0;
    }
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

  BuiltChild make_leaf(std::uint32_t begin, std::uint32_t end) {
    BuiltChild leaf;
    leaf.index = begin;
    leaf.count = end - begin;
    for (std::uint32_t i = begin; i < end; ++i) leaf.box.extend((*sorted_)[i].bounds());
    ++stats_.leaves;
    stats_.largest_leaf = std::max<std::size_t>(stats_.largest_leaf, leaf.count);
    return leaf;
  }

  // The first level at which the run [begin, end) splits (kMortonLevels: it
  // never does); levels before it hold one octant.
  int split_level(std::uint32_t begin, std::uint32_t end) const {
    const std::uint64_t differ = codes_[begin] ^ codes_[end - 1];
    return differ == 0 ? kMortonLevels : kMortonLevels - 1 - (63 - __builtin_clzll(differ)) / 3;
  }
  // is_leaf only grows more true with the level, so checking `split` covers the
  // skipped levels too.
  bool is_leaf_run(std::uint32_t begin, std::uint32_t end) const {
    const int split = split_level(begin, end);
    return split == kMortonLevels || is_leaf(end - begin, split);
  }

  // A run of sorted primitives that is one cell, and where it sits in the
  // node being built.
  struct Run {
    std::uint32_t begin, end;
    int home;    // the octant of the node's cell it lies in
    bool whole;  // it is that whole octant (not a part of an opened one)
    bool leaf;
  };
  // A node's children while it is built: at most eight runs, and the octants
  // of each inner one once looked at (to open it, if they fit).
  struct NodeRuns {
    std::array<Run, 8> run;
    std::array<std::array<Run, 8>, 8> parts;
    std::array<std::uint32_t, 8> part_count{};  // 0: not looked at yet
    std::uint32_t count = 0;
  };

  // The octants of the cell [begin, end) that hold primitives, in order, as
  // runs (home: `home`, or their own octant when home < 0). Returns how many.
  std::uint32_t split_cell(std::uint32_t begin, std::uint32_t end, int home, Run* runs) const {
    const int split = split_level(begin, end);
    std::uint32_t count = 0;
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
      runs[count++] =
          Run{child_begin, lo, home < 0 ? k : home, home < 0, is_leaf_run(child_begin, lo)};
      child_begin = lo;
    }
    return count;
  }

  // Opens the largest inner children into their octants while those fit in
  // the eight slots, as wide BVHs are collapsed from binary ones: an octree
  // cell on a surface holds about four octants, and a node half full costs a
  // ray a whole visit for half the culling (bench_moc's room: 6,555 nodes of
  // 4.7 children became 5,591 of 5.3; bench_poc's cloud: 38,114 of 4.5
  // became 28,439 of 5.7).
  void open_largest(NodeRuns& node) const {
    for (;;) {
      int largest = -1;
      for (std::uint32_t r = 0; r < node.count; ++r) {
        const Run& run = node.run[r];
        if (run.leaf) continue;
        if (node.part_count[r] == 0) {
          node.part_count[r] = split_cell(run.begin, run.end, run.home, node.parts[r].data());
        }
        if (node.count - 1 + node.part_count[r] > 8) continue;
        if (largest < 0 || run.end - run.begin > node.run[largest].end - node.run[largest].begin) {
          largest = static_cast<int>(r);
        }
      }
      if (largest < 0) return;
      const std::array<Run, 8> parts = node.parts[largest];
      const std::uint32_t part_count = node.part_count[largest];
      node.run[largest] = parts[0];
      node.part_count[largest] = 0;
      for (std::uint32_t p = 1; p < part_count; ++p) {
        node.run[node.count] = parts[p];
        node.part_count[node.count++] = 0;
      }
    }
  }

  // The node for the inner cell [begin, end) at nodes_[node_index] (reserved
  // by the caller) and the nodes under it. Returns its height (levels of
  // nodes down to its deepest leaf) and writes its box.
  int build_node(std::uint32_t node_index, std::uint32_t begin, std::uint32_t end, Aabb& box) {
    // A relaxed load per inner node: a cancelled build stops within a few nodes.
    progress_.check_cancel();
    NodeRuns node;
    node.count = split_cell(begin, end, -1, node.run.data());
    open_largest(node);

    // Slots: a whole octant takes its own slot; the parts of opened octants
    // take the free slot nearest theirs, so that visiting slots in the order
    // k ^ near_octant stays roughly front to back (only a traversal's speed
    // depends on its order, never its answers).
    std::array<int, 8> slot;
    std::uint32_t used = 0;
    for (std::uint32_t r = 0; r < node.count; ++r) {
      slot[r] = node.run[r].whole ? node.run[r].home : -1;
      if (slot[r] >= 0) used |= 1u << slot[r];
    }
    for (std::uint32_t r = 0; r < node.count; ++r) {
      if (slot[r] >= 0) continue;
      const int home = node.run[r].home;
      for (int k = 0; k < 8; ++k) {
        if (!(used >> k & 1u) && (slot[r] < 0 || (k ^ home) < (slot[r] ^ home))) slot[r] = k;
      }
      used |= 1u << slot[r];
    }

    std::array<BuiltChild, 8> children;
    int height = 1;
    box = Aabb{};
    for (std::uint32_t r = 0; r < node.count; ++r) {
      const Run& run = node.run[r];
      BuiltChild& child = children[r];
      if (run.leaf) {
        child = make_leaf(run.begin, run.end);
      } else {
        child.index = static_cast<std::uint32_t>(nodes_.size());
        nodes_.emplace_back();
        ++stats_.inner_nodes;
        height = std::max(height, 1 + build_node(child.index, run.begin, run.end, child.box));
      }
      child.octant = slot[r];
      box.extend(child.box);
    }
    // After the recursion: nodes_ may have reallocated meanwhile.
    fill_node(nodes_[node_index], children.data(), node.count);
    return height;
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
