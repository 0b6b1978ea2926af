#pragma once
// Surfels: each point of a cloud is a flat disc lying in its surface (centre,
// unit normal, radius), or, where no orientation can be trusted, a sphere of
// the same radius. A sibling of sphere.hpp and triangle.hpp.
//
// Why discs: a surface sampled at density rho is closed by discs of radius r
// up to a share exp(-rho pi r^2) (coverage of a Boolean model), so r can be as
// large as closing it needs, while a ray leaving the surface at any positive
// elevation passes over its neighbours' discs. Spheres large enough to close a
// surface hide it from itself at grazing angles (analysis/surfel_estimation.hpp
// chooses the normals and radii).
//
// Rules (the same spirit as triangle.hpp):
// - Interval: a hit counts iff t_min <= t <= t_max (closed).
// - A disc is two-sided and closed: a ray crossing its plane at distance
//   <= radius from the centre hits, at the crossing.
// - A ray parallel to the disc's plane (|d.n| <= 1e-7 |d|) misses it, as a ray
//   in a triangle's plane misses the triangle.
// - A surfel of radius 0 (or NaN) is never hit.
// - An unoriented surfel (normal zero) follows sphere.hpp exactly.
// - The direction need not be unit: t is in units of the given direction.

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "occlusion/core/aabb.hpp"
#include "occlusion/core/large_buffer.hpp"
#include "occlusion/core/ray.hpp"
#include "occlusion/core/ray_lanes.hpp"
#include "occlusion/core/sphere.hpp"

namespace occlusion {

struct Surfel {
  Eigen::Vector3f center{0.0f, 0.0f, 0.0f};
  float radius = 0.0f;
  // Unit, or zero for a point whose orientation is unknown (a sphere).
  Eigen::Vector3f normal{0.0f, 0.0f, 0.0f};

  bool oriented() const { return normal.x() != 0.0f || normal.y() != 0.0f || normal.z() != 0.0f; }
  Aabb bounds() const;
  Eigen::Vector3f centroid() const { return center; }
};

// Rays closer to parallel than this (|d.n| / |d|, n unit) miss a disc.
inline constexpr float kDiscParallel = 1e-7f;

// The disc test shared by surfels and banded surfels (banded_surfel.hpp):
// with `band` >= 0 a crossing also needs the ray's end (t = 1) to lie more
// than `band` from the disc's plane; a negative band asks nothing more.
//
// The crossing is measured from the disc's centre (t d - (c - o)), so the
// in-radius test subtracts quantities of the ray's length, never squares of
// far coordinates.
template <class Num, class Mask>
inline Mask disc_hit(const RayComponents<Num>& ray, const Surfel& surfel, float band, Mask active,
                     Num& t_hit) {
  using lane_math::abs, lane_math::dot3;
  if (!(surfel.radius > 0.0f)) return active & false;
  if (!surfel.oriented()) {
    return sphere_hit(ray, Sphere{surfel.center, surfel.radius}, active, t_hit);
  }
  const Num to_center_x = Num(surfel.center.x()) - ray.origin_x;
  const Num to_center_y = Num(surfel.center.y()) - ray.origin_y;
  const Num to_center_z = Num(surfel.center.z()) - ray.origin_z;
  const Num normal_x(surfel.normal.x()), normal_y(surfel.normal.y()), normal_z(surfel.normal.z());
  const Num facing =
      dot3(normal_x, normal_y, normal_z, ray.direction_x, ray.direction_y, ray.direction_z);
  active = active & (abs(facing) > Num(kDiscParallel) * ray.length);
  if (!active) return active;
  const Num height = dot3(normal_x, normal_y, normal_z, to_center_x, to_center_y, to_center_z);
  const Num t = height / facing;
  active = active & (t >= ray.t_min) & (t <= ray.t_max);
  // n . (o + d - c): the ray's end off the plane.
  if (band >= 0.0f) active = active & (abs(facing - height) > Num(band));
  if (!active) return active;
  const Num from_center_x = t * ray.direction_x - to_center_x;
  const Num from_center_y = t * ray.direction_y - to_center_y;
  const Num from_center_z = t * ray.direction_z - to_center_z;
  active = active & (dot3(from_center_x, from_center_y, from_center_z, from_center_x, from_center_y,
                          from_center_z) <= Num(surfel.radius * surfel.radius));
  t_hit = t;
  return active;
}

// The surfel octree's leaf test, for one ray (Num = float) or a packet
// (ray_lanes.hpp): `active` says which rays to test; returns those that hit,
// with their hit parameter in `t_hit` (unspecified for the others).
template <class Num, class Mask>
inline Mask surfel_hit(const RayComponents<Num>& ray, const Surfel& surfel, Mask active,
                       Num& t_hit) {
  return disc_hit(ray, surfel, -1.0f, active, t_hit);
}

inline std::optional<float> intersect_surfel(const RayComponents<float>& ray,
                                             const Surfel& surfel) {
  float t = 0.0f;
  if (surfel_hit(ray, surfel, true, t)) return t;
  return std::nullopt;
}

inline std::optional<float> intersect_surfel(const Ray& ray, const Surfel& surfel) {
  return intersect_surfel(ray_components(ray), surfel);
}

// One surfel: its normal normalised (zero for a sphere). Throws
// std::invalid_argument, naming point `index`, for a centre or normal that is
// not finite or a radius that is not finite and positive.
Surfel make_surfel(const Eigen::Vector3f& center, const Eigen::Vector3f& normal, float radius,
                   std::size_t index);

// One surfel per centre, in order, so that a surfel's primitive id is its
// point's index: normals[i] (normalised here; zero for a sphere) and radii[i].
// Throws std::invalid_argument for sizes that differ, a centre or normal that is
// not finite, or a radius that is not finite and positive. In a LargeVector,
// which the octree builds from: huge pages for big clouds.
LargeVector<Surfel> make_surfels(const std::vector<Eigen::Vector3f>& centers,
                                 const std::vector<Eigen::Vector3f>& normals,
                                 const std::vector<float>& radii);

}  // namespace occlusion
