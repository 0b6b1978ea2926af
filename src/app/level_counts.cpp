#include "occlusion/app/level_counts.hpp"

#include <cstdio>

namespace occlusion {

namespace {

template <class Rays>
RayCounts counts_of(const Rays& r) {
  return {r.rays,           r.hits, r.through_openings, r.occlusion_rays, r.outside_view_rays,
          r.occlusion_level};
}

}  // namespace

RayCounts ray_counts(const CloudOcclusionResult& result) {
  return counts_of(result);
}
RayCounts ray_counts(const ViewpointRays& viewpoint) {
  return counts_of(viewpoint);
}

std::string level_counts_text(const RayCounts& c, const std::string& outside_why) {
  char level[32];
  std::snprintf(level, sizeof level, "%.4f", c.occlusion_level);
  const bool outside = c.outside_view_rays > 0 || !outside_why.empty();
  std::string text = std::string(level) + " = " + std::to_string(c.occlusion_rays) +
                     " occlusion rays / " + std::to_string(c.rays_in_view()) +
                     (outside ? " rays inside the view" : " rays") + " (the other " +
                     std::to_string(c.hits) + " hit a point, " +
                     std::to_string(c.through_openings) + " left through openings)";
  if (outside) {
    text += "; " + std::to_string(c.outside_view_rays) + " of the " + std::to_string(c.rays) +
            " rays are " + outside_why + ", not counted";
  }
  return text;
}

}  // namespace occlusion
