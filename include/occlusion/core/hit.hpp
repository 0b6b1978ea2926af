#pragma once
#include <cstdint>
#include <limits>

namespace occlusion {

using PrimitiveId = std::uint32_t;
// Passed as `ignore_id` when no primitive is to be skipped.
inline constexpr PrimitiveId kNoPrimitive = std::numeric_limits<PrimitiveId>::max();

// The closest intersection found along a ray.
struct Hit {
  float t_hit = std::numeric_limits<float>::infinity();
  PrimitiveId primitive_id = kNoPrimitive;
};

}  // namespace occlusion
