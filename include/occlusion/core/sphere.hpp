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
// - The direction need not be unit: t is in units of the given direction.

#include <Eigen/Core>
#include <cmath>
#include <optional>
#include <vector>

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
//
// Written around the closest-approach parameter t_c = -(o - c).d / d.d rather
// than the textbook quadratic: b^2 - 4ac cancels catastrophically for a small
// sphere far from the origin, while r^2 - |o + t_c d - c|^2 subtracts two
// quantities of the sphere's own size. Inline: it runs once per leaf primitive.
inline std::optional<float> intersect_sphere(const Ray& ray, float direction_length,
                                             const Sphere& sphere) {
  // Also rejects a NaN radius; a zero direction fails below through NaN.
  if (!(sphere.radius > 0.0f)) return std::nullopt;
  const Eigen::Vector3f offset = ray.origin - sphere.center;
  const float t_closest = -offset.dot(ray.direction) / ray.direction.squaredNorm();
  const Eigen::Vector3f closest = offset + t_closest * ray.direction;
  const float discriminant = sphere.radius * sphere.radius - closest.squaredNorm();
  if (!(discriminant >= 0.0f)) return std::nullopt;
  const float half_chord = std::sqrt(discriminant) / direction_length;
  const float t_near = t_closest - half_chord;
  if (t_near >= ray.t_min) {
    if (t_near <= ray.t_max) return t_near;
    return std::nullopt;
  }
  const float t_far = t_closest + half_chord;
  if (t_far >= ray.t_min && t_far <= ray.t_max) return t_far;
  return std::nullopt;
}

inline std::optional<float> intersect_sphere(const Ray& ray, const Sphere& sphere) {
  return intersect_sphere(ray, ray.direction.norm(), sphere);
}

// One sphere of `radius` per centre, in order, so that a sphere's primitive id
// is its point's index. Throws std::invalid_argument for a radius that is not
// finite and positive, or a centre that is not finite.
std::vector<Sphere> make_spheres(const std::vector<Eigen::Vector3f>& centers, float radius);

}  // namespace occlusion
