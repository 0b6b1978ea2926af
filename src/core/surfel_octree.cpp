#include "occlusion/core/surfel_octree.hpp"

#include "octree_impl.hpp"

namespace occlusion {

template class Octree<Surfel>;

}  // namespace occlusion
