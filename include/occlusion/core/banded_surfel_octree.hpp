#pragma once
// The octree over banded surfels (banded_surfel.hpp): a cloud's discs with
// the noise of their surfaces, as -fscan traces them. A hit's primitive id is
// the surfel's index in the construction vector (the point's index).

#include "occlusion/core/banded_surfel.hpp"
#include "occlusion/core/octree.hpp"

namespace occlusion {

template <class Num, class Mask>
inline Mask shape_hit(const RayComponents<Num>& ray, const BandedSurfel& banded, Mask active,
                      Num& t_hit) {
  return banded_surfel_hit(ray, banded, active, t_hit);
}

using BandedSurfelOctree = Octree<BandedSurfel>;
extern template class Octree<BandedSurfel>;

}  // namespace occlusion
