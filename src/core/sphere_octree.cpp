#include "occlusion/core/sphere_octree.hpp"

#include "octree_impl.hpp"

namespace occlusion {

template class Octree<Sphere>;

}  // namespace occlusion
