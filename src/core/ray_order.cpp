#include "ray_order.hpp"

#include <array>
#include <cmath>

namespace occlusion {

namespace {

// 10 bits per coordinate of the octahedral map: about 0.1 degree cells.
constexpr int kDirectionBits = 10;
constexpr int kKeyBits = 3 + 2 * kDirectionBits;
constexpr int kRadixBits = 8;

std::uint32_t spread_bits(std::uint32_t x) {
  x &= 0x3ff;
  x = (x | (x << 8)) & 0x00ff00ff;
  x = (x | (x << 4)) & 0x0f0f0f0f;
  x = (x | (x << 2)) & 0x33333333;
  x = (x | (x << 1)) & 0x55555555;
  return x;
}

std::uint32_t direction_key(const Eigen::Vector3f& d) {
  const std::uint32_t octant =
      (d.x() < 0.0f ? 1u : 0u) | (d.y() < 0.0f ? 2u : 0u) | (d.z() < 0.0f ? 4u : 0u);
  const float sum = std::abs(d.x()) + std::abs(d.y()) + std::abs(d.z());
  std::uint32_t u = 0, v = 0;
  // Zero, infinite or NaN directions keep key 0 within their octant: any order
  // is correct, this one only makes it deterministic.
  if (sum > 0.0f && std::isfinite(sum)) {
    constexpr float kScale = static_cast<float>((1 << kDirectionBits) - 1);
    u = static_cast<std::uint32_t>(std::abs(d.x()) / sum * kScale);
    v = static_cast<std::uint32_t>(std::abs(d.y()) / sum * kScale);
  }
  return (octant << (2 * kDirectionBits)) | (spread_bits(u) << 1) | spread_bits(v);
}

}  // namespace

void order_by_direction(const Ray* rays, std::size_t begin, std::size_t end, std::uint32_t* order,
                        std::vector<std::uint32_t>& scratch) {
  const std::size_t count = end - begin;
  // scratch: keys in input order, then a second index buffer.
  scratch.resize(2 * count);
  std::uint32_t* keys = scratch.data();
  std::uint32_t* other = scratch.data() + count;
  for (std::size_t i = 0; i < count; ++i) {
    keys[i] = direction_key(rays[begin + i].direction);
    order[i] = static_cast<std::uint32_t>(i);
  }
  // LSD radix sort of the local indices by key: stable, linear.
  std::uint32_t* from = order;
  std::uint32_t* to = other;
  for (int shift = 0; shift < kKeyBits; shift += kRadixBits) {
    std::array<std::uint32_t, (1 << kRadixBits) + 1> starts{};
    for (std::size_t i = 0; i < count; ++i) ++starts[((keys[from[i]] >> shift) & 0xff) + 1];
    for (std::size_t b = 1; b < starts.size(); ++b) starts[b] += starts[b - 1];
    for (std::size_t i = 0; i < count; ++i) to[starts[(keys[from[i]] >> shift) & 0xff]++] = from[i];
    std::swap(from, to);
  }
  for (std::size_t i = 0; i < count; ++i) {
    order[i] = static_cast<std::uint32_t>(begin) + from[i];
  }
}

}  // namespace occlusion
