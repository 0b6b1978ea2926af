#pragma once
// A ray with its own parametric interval, in the style of Embree's RTCRay.
//
// Points on the ray are origin + t * direction. The direction need NOT be unit
// length: shadow rays use direction = target - origin so that t = 1 is the target.
// A primitive is hit when its hit parameter t satisfies t_min <= t <= t_max
// (a closed interval: a hit exactly at t_max counts).
// Single precision throughout, like Embree; callers convert from double.

#include <Eigen/Core>
#include <limits>

namespace occlusion {

struct Ray {
  Eigen::Vector3f origin{0.0f, 0.0f, 0.0f};
  Eigen::Vector3f direction{0.0f, 0.0f, 1.0f};
  float t_min = 0.0f;
  float t_max = std::numeric_limits<float>::infinity();

  Eigen::Vector3f at(float t) const { return origin + t * direction; }
};

}  // namespace occlusion
