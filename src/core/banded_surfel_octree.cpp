#include "occlusion/core/banded_surfel_octree.hpp"

#include "octree_impl.hpp"

namespace occlusion {

template class Octree<BandedSurfel>;

}  // namespace occlusion
