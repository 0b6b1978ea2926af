#pragma once
// What a -poc occlusion level counts, in one sentence every door shows (the
// CLI's text, the report's `level_counts`, the viewer's card, Python's
// report), so a reader can add it up: the occlusion rays over the rays inside
// the view, what became of the other rays inside it, and the rays outside
// the view, which are not counted, and why.

#include <cstddef>
#include <string>

#include "occlusion/analysis/cloud_occlusion.hpp"

namespace occlusion {

struct RayCounts {
  std::size_t rays = 0, hits = 0, through_openings = 0, occlusion_rays = 0, outside_view_rays = 0;
  double occlusion_level = 0.0;

  std::size_t rays_in_view() const { return rays - outside_view_rays; }
};

RayCounts ray_counts(const CloudOcclusionResult& result);
RayCounts ray_counts(const ViewpointRays& viewpoint);

// E.g. "0.5966 = 2482 occlusion rays / 4160 rays inside the view (the other
// 1678 hit a point, 0 left through openings); 25840 of the 30000 rays are
// outside station 'S''s field of view (...): directions it never measured,
// not counted". `outside_why` is what the rays outside the view are outside
// of, and why (empty: the cloud has no field of view; every ray counts).
std::string level_counts_text(const RayCounts& counts, const std::string& outside_why);

}  // namespace occlusion
