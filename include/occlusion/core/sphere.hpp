#pragma once
// Spheres: each point of a cloud is a sphere of radius point_radius.
//
// Rules (the same spirit as triangle.hpp):
// - Interval: a hit counts iff t_min <= t <= t_max (closed).
// - The hit parameter is the smallest root of |o + t d - c| = r that lies in the
//   interval: the entry point, or the exit point when the entry lies before
//   t_min (a ray starting inside the sphere hits where it leaves).
// - A tangent ray (one double root) hits.
// - A sphere of radius 0 is never hit.

#include <Eigen/Core>
#include <cmath>
#include <optional>

#include "occlusion/core/aabb.hpp"
#include "occlusion/core/ray.hpp"

namespace occlusion {

struct Sphere {
  Eigen::Vector3f center{0.0f, 0.0f, 0.0f};
  float radius = 0.0f;

  Aabb bounds() const;
  Eigen::Vector3f centroid() const { return center; }
};

// The sphere octree's leaf test. `direction_length` is
// ray.direction.norm(), computed once per ray by the caller.
std::optional<float> intersect_sphere(const Ray& ray, float direction_length,
                                      const Sphere& sphere);

}  // namespace occlusion
