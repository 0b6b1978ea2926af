// The region-growing keys (-rgoc, extract_polygons, the study's baseline
// segmenter), declared once for RegionGrowingOptions. Defaults: the thesis'
// listing 4.7.

#include "occlusion/app/region_growing_job.hpp"
#include "occlusion/app/shared_keys.hpp"

namespace occlusion {

const Keys<RegionGrowingOptions>& estimation_keys() {
  using R = RegionGrowingOptions;
  static const Keys<R> keys = {
      key("normal_k", &R::normal_k).range(3, 10000).metavar("K").doc("neighbours per normal"),
      key("min_cluster_size", &R::min_cluster_size)
          .range(1, 1e12)
          .metavar("N")
          .doc("smaller regions are dropped"),
      key("max_cluster_size", &R::max_cluster_size)
          .range(1, 1e12)
          .metavar("N")
          .doc("larger regions are dropped (raise it for dense clouds, whose walls and floors "
               "are larger)"),
      key("neighbours", &R::neighbours)
          .range(1, 10000)
          .metavar("N")
          .doc("neighbours region growing compares"),
      key("smoothness_degrees", &R::smoothness_degrees)
          .positive_up_to(180)
          .unit("degrees")
          .metavar("A")
          .doc("largest angle between neighbouring normals"),
      key("curvature_threshold", &R::curvature_threshold)
          .range(0, 1e6)
          .metavar("C")
          .doc("points above it join regions but seed none"),
      key("ransac_distance", &R::ransac_distance)
          .positive_up_to(1e6)
          .unit("scene units")
          .metavar("D")
          .doc("plane inlier distance"),
      key("ransac_iterations", &R::ransac_iterations)
          .range(1, 100'000'000)
          .metavar("N")
          .doc("RANSAC iterations at most (it stops at 99 % confidence)"),
      key("recover_edges", &R::recover_edges)
          .doc("planes take the unclustered points along their edges (false: the thesis' "
               "method as is)"),
  };
  return keys;
}

}  // namespace occlusion
