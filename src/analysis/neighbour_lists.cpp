#include "neighbour_lists.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "occlusion/core/morton.hpp"

namespace occlusion::mesh_estimation {

NeighbourLists::NeighbourLists(const float* xyz, std::size_t stride_bytes, std::size_t count,
                               std::size_t width)
    : width_(width) {
  if (count > UINT32_MAX) throw std::invalid_argument("neighbour lists: too many points");
  const auto at = [&](std::size_t i) {
    return reinterpret_cast<const float*>(reinterpret_cast<const char*>(xyz) + i * stride_bytes);
  };
  float lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (std::size_t i = 0; i < count; ++i) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = i == 0 ? at(i)[a] : std::min(lo[a], at(i)[a]);
      hi[a] = i == 0 ? at(i)[a] : std::max(hi[a], at(i)[a]);
    }
  }
  double scale[3];
  for (int a = 0; a < 3; ++a) {
    const double extent = static_cast<double>(hi[a]) - static_cast<double>(lo[a]);
    scale[a] =
        extent > 0.0 && std::isfinite(extent) ? static_cast<double>(kMortonLastCell) / extent : 0.0;
  }
  {
    std::vector<std::pair<std::uint64_t, std::uint32_t>> order(count);
    for (std::size_t i = 0; i < count; ++i) {
      std::uint64_t code = 0;
      for (int a = 0; a < 3; ++a) {
        const double cell = (static_cast<double>(at(i)[a]) - lo[a]) * scale[a];
        const auto q =
            static_cast<std::uint32_t>(std::clamp(cell, 0.0, static_cast<double>(kMortonLastCell)));
        code |= spread_by_three(q) << a;
      }
      order[i] = {code, static_cast<std::uint32_t>(i)};
    }
    std::sort(order.begin(), order.end());
    point_at_.resize(count);
    rank_.resize(count);
    for (std::size_t r = 0; r < count; ++r) {
      point_at_[r] = order[r].second;
      rank_[order[r].second] = static_cast<std::uint32_t>(r);
    }
  }
  slots_.resize(count * width);
}

bool NeighbourLists::try_set(std::size_t point, const std::int32_t* neighbours) {
  std::int16_t* slots = slots_.data() + point * width_;
  const std::int64_t rank = rank_[point];
  for (std::size_t n = 0; n < width_; ++n) {
    const std::int64_t difference = rank_[static_cast<std::size_t>(neighbours[n])] - rank;
    if (difference <= kWhole || difference > INT16_MAX) {
      if (width_ > 0) slots[0] = kWhole;
      return false;
    }
    slots[n] = static_cast<std::int16_t>(difference);
  }
  return true;
}

void NeighbourLists::set_whole(std::size_t point, const std::int32_t* neighbours) {
  if (!whole_points_.empty() && whole_points_.back() >= point) {
    throw std::logic_error("neighbour lists: whole lists out of order");
  }
  slots_[point * width_] = kWhole;
  whole_points_.push_back(static_cast<std::uint32_t>(point));
  whole_.insert(whole_.end(), neighbours, neighbours + width_);
}

const std::int32_t* NeighbourLists::whole_list(std::size_t point) const {
  const auto it = std::lower_bound(whole_points_.begin(), whole_points_.end(),
                                   static_cast<std::uint32_t>(point));
  return whole_.data() + static_cast<std::size_t>(it - whole_points_.begin()) * width_;
}

}  // namespace occlusion::mesh_estimation
