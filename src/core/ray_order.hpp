#pragma once
// A coherent visiting order for a run of rays: grouped by the signs of their
// directions, then along a Morton curve over the direction (an octahedral map
// of each octant), so that neighbours in the order point the same way. Rays
// that also share an endpoint (all rays of one viewpoint) then follow nearly
// the same path through a tree, which is what packet traversal needs; callers
// keep each viewpoint's rays together for that reason.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "occlusion/core/ray.hpp"

namespace occlusion {

// Writes begin .. end - 1 to order[0 .. end - begin), sorted by direction as
// above; equal keys keep their input order (deterministic). `scratch` is reused
// between calls to avoid allocations.
void order_by_direction(const Ray* rays, std::size_t begin, std::size_t end, std::uint32_t* order,
                        std::vector<std::uint32_t>& scratch);

}  // namespace occlusion
