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
#include "occlusion/core/large_buffer.hpp"
#include "occlusion/core/ray.hpp"
#include "occlusion/core/ray_lanes.hpp"

namespace occlusion {

struct Sphere {
  Eigen::Vector3f center{0.0f, 0.0f, 0.0f};
  float radius = 0.0f;

  Aabb bounds() const;
  Eigen::Vector3f centroid() const { return center; }
};

// The sphere octree's leaf test, for one ray (Num = float) or a packet
// (ray_lanes.hpp): `active` says which rays to test; returns those that hit,
// with their hit parameter in `t_hit` (unspecified for the others).
//
// Written around the closest-approach parameter t_c = -(o - c).d / d.d rather
// than the textbook quadratic: b^2 - 4ac cancels catastrophically for a small
// sphere far from the origin, while r^2 - |o + t_c d - c|^2 subtracts two
// quantities of the sphere's own size. Inline: it runs once per leaf primitive.
template <class Num, class Mask>
inline Mask sphere_hit(const RayComponents<Num>& ray, const Sphere& sphere, Mask active,
                       Num& t_hit) {
  // Unqualified below: a lane type brings its own through argument lookup.
  using lane_math::abs, lane_math::dot3, lane_math::select, lane_math::sign_of, lane_math::sqrt;
  // Also rejects a NaN radius; a zero direction fails below through NaN.
  if (!(sphere.radius > 0.0f)) return active & false;
  const Num offset_x = ray.origin_x - sphere.center.x();
  const Num offset_y = ray.origin_y - sphere.center.y();
  const Num offset_z = ray.origin_z - sphere.center.z();
  const Num t_closest =
      -dot3(offset_x, offset_y, offset_z, ray.direction_x, ray.direction_y, ray.direction_z) /
      ray.length_squared;
  const Num closest_x = offset_x + t_closest * ray.direction_x;
  const Num closest_y = offset_y + t_closest * ray.direction_y;
  const Num closest_z = offset_z + t_closest * ray.direction_z;
  const Num discriminant = sphere.radius * sphere.radius -
                           dot3(closest_x, closest_y, closest_z, closest_x, closest_y, closest_z);
  active = active & (discriminant >= 0.0f);
  if (!active) return active;
  const Num half_chord = sqrt(discriminant) / ray.length;
  const Num t_near = t_closest - half_chord;
  // The entry point, or the exit point when the entry lies before t_min.
  t_hit = select(t_near >= ray.t_min, t_near, t_closest + half_chord);
  return active & (t_hit >= ray.t_min) & (t_hit <= ray.t_max);
}

inline std::optional<float> intersect_sphere(const RayComponents<float>& ray,
                                             const Sphere& sphere) {
  float t = 0.0f;
  if (sphere_hit(ray, sphere, true, t)) return t;
  return std::nullopt;
}

inline std::optional<float> intersect_sphere(const Ray& ray, const Sphere& sphere) {
  return intersect_sphere(ray_components(ray), sphere);
}

// One sphere of `radius` per centre, in order, so that a sphere's primitive id
// is its point's index. Throws std::invalid_argument for a radius that is not
// finite and positive, or a centre that is not finite. In a LargeVector, which
// the octree builds from: huge pages for big clouds (16 bytes a point).
LargeVector<Sphere> make_spheres(const std::vector<Eigen::Vector3f>& centers, float radius);

}  // namespace occlusion
