#pragma once
// Every point's `width` nearest neighbours, in their order, in about half the
// memory of 32-bit indices (1M points x 40 neighbours: ~90 MB, not 160 MB).
//
// The points get ranks in Morton order of their positions, so a point's
// neighbours have ranks close to its own: each neighbour is stored as the
// 16-bit difference of the ranks. A list with a difference beyond 16 bits
// (a point beside a cut of the Morton curve, a few % of them) is marked as
// such and kept whole, as 32-bit indices, on the side.
//
// Standard library and Eigen only; internal to analysis/.

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace occlusion::mesh_estimation {

class NeighbourLists {
 public:
  NeighbourLists() = default;
  // `count` points; point i's x, y, z are the floats at xyz + i * stride_bytes.
  NeighbourLists(const float* xyz, std::size_t stride_bytes, std::size_t count, std::size_t width);

  std::size_t width() const { return width_; }
  std::size_t size() const { return rank_.size(); }

  // Stores point's list (width indices) if its differences fit, and says so;
  // any thread, one call per point.
  bool try_set(std::size_t point, const std::int32_t* neighbours);
  // The lists try_set refused, in increasing point order, from one thread.
  void set_whole(std::size_t point, const std::int32_t* neighbours);

  // Calls visit(neighbour index) for each of point's neighbours, in order.
  template <class Visit>
  void for_each(std::size_t point, Visit&& visit) const {
    const std::int16_t* slots = slots_.data() + point * width_;
    if (width_ == 0) return;
    if (slots[0] == kWhole) {
      const std::int32_t* whole = whole_list(point);
      for (std::size_t n = 0; n < width_; ++n) visit(whole[n]);
      return;
    }
    const std::int64_t rank = rank_[point];
    for (std::size_t n = 0; n < width_; ++n) {
      visit(static_cast<std::int32_t>(point_at_[static_cast<std::size_t>(rank + slots[n])]));
    }
  }

  // Lists kept whole (for tests and figures).
  std::size_t whole_lists() const { return whole_points_.size(); }
  // Frees everything.
  void clear() { *this = NeighbourLists(); }

 private:
  static constexpr std::int16_t kWhole = INT16_MIN;
  const std::int32_t* whole_list(std::size_t point) const;

  std::size_t width_ = 0;
  std::vector<std::uint32_t> rank_;          // point -> its Morton rank
  std::vector<std::uint32_t> point_at_;      // rank -> point
  std::vector<std::int16_t> slots_;          // point i's: [i * width, (i + 1) * width)
  std::vector<std::uint32_t> whole_points_;  // increasing
  std::vector<std::int32_t> whole_;          // their lists, in that order
};

}  // namespace occlusion::mesh_estimation
