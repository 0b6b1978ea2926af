#pragma once
// The -fscan rule's shadow ray to a disc (scan.hpp, scan_surfel_ray), for one
// surfel or for many from one viewpoint. A plan fills its coverage matrix
// with hundreds of millions of these rays, so the many-surfel form makes four
// at a time in SSE2 registers; the one-surfel form does the very same float
// operations in the same order, so a point gets the same ray bit for bit
// whichever form makes it (surfel_ray_rule_test.cpp holds them together).

#include <Eigen/Core>
#include <cstddef>

#include "occlusion/analysis/scan_tracer.hpp"
#include "occlusion/core/ray.hpp"
#include "occlusion/core/surfel.hpp"

namespace occlusion::surfel_ray_rule {

// The shortest reach of a point's own surface, as a share of its radius: its
// neighbours' discs overlap it, and where the surface is noisy (a depth
// camera's steps) they stand a little in front of it, up to about one radius
// along the ray (on the real Kinect frame, with normals from the nearest
// points in space, 0.1 r kept 86 % of the points from their own sensor, 1 r
// 95 %, 1.5 r 98 %; with the frame's pixel window, 1.5 r keeps 99.3 %; 2 r
// lets a 2 cm board's far side show through from 1.5 cm spacing).
inline constexpr float kMinReachPerRadius = 1.5f;
inline constexpr float kMaxReachPerRadius = 2.0f;
inline constexpr float kThicknessSigmas = 3.0f;
// Below this |cos| between the ray and the normal the thickness term is
// taken at this value (it is clamped to kMaxReachPerRadius anyway).
inline constexpr float kMinSine = 1e-12f;

struct Viewpoint {
  Eigen::Vector3f position;
  float near_viewpoint = 0.0f;  // what the rule ignores next to the viewpoint
  float fixed_reach = -1.0f;    // >= 0: an explicit self_tolerance replaces the rule's reach
};

// A point's disc and its surface's thickness (32 bytes: centre, radius,
// normal, thickness).
using Target = ScanTracer::Target;

Ray ray(const Viewpoint& viewpoint, const Target& target);
// out[k] = ray(viewpoint, targets[k]) for k < count.
void rays(const Viewpoint& viewpoint, const Target* targets, std::size_t count, Ray* out);

}  // namespace occlusion::surfel_ray_rule
