#pragma once
// Banded surfels: a surfel (surfel.hpp) that stands for a measured surface
// whose points scatter about it by the sensor's noise. A shadow ray from a
// viewpoint to a point P (P at t = 1) is hidden by such a disc only where P
// lies off the disc's plane by more than its band: a point that lies within
// the band is on the same noisy surface, and the disc standing in front of it
// along the ray is its own surface's noise, not an occluder. A wall hides
// what lies behind it by more than its band. A sibling of surfel.hpp.
//
// Rules: those of surfel.hpp, and
// - a crossing counts only if |n . (o + d - c)| > band, the ray's end off the
//   plane (so the band is read on rays whose t = 1 is the point they ask
//   about: shadow rays);
// - band 0 hides as a surfel does, except a ray ending exactly in the plane;
// - an unoriented surfel (a sphere) has no plane and ignores its band.

#include "occlusion/core/surfel.hpp"

namespace occlusion {

struct BandedSurfel {
  Surfel surfel;
  // How far off the plane a point still belongs to the surface (>= 0).
  float band = 0.0f;

  Aabb bounds() const { return surfel.bounds(); }
  Eigen::Vector3f centroid() const { return surfel.center; }
};

template <class Num, class Mask>
inline Mask banded_surfel_hit(const RayComponents<Num>& ray, const BandedSurfel& banded,
                              Mask active, Num& t_hit) {
  return disc_hit(ray, banded.surfel, banded.band, active, t_hit);
}

}  // namespace occlusion
