// The real Cornell box (files/cornell_box, public domain) through the whole
// mesh-occlusion path.

#include <gtest/gtest.h>

#include <algorithm>

#include "occlusion/analysis/mesh_occlusion.hpp"
#include "occlusion/analysis/viewpoints.hpp"
#include "occlusion/io/obj_reader.hpp"

namespace occlusion {
namespace {

const std::string kCornellBox =
    std::string(OCCLUSION_SOURCE_DIR) + "/files/cornell_box/CornellBox-Original.obj";

TEST(CornellBox, SingleViewpointLevelIsStableAcrossSeeds) {
  const TriangleMesh mesh = read_obj(kCornellBox);
  Eigen::Vector3d lo, hi;
  mesh.bounds(lo, hi);
  const auto viewpoints = pattern_viewpoints(1, lo, hi);
  MeshOcclusionOptions options;
  options.samples_per_unit_area = 2000;  // ~53,000 samples
  std::vector<double> levels;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    options.seed = seed;
    levels.push_back(compute_mesh_occlusion(mesh, viewpoints, options).occlusion_level);
  }
  const auto [min, max] = std::minmax_element(levels.begin(), levels.end());
  // A binomial sigma is at most sqrt(0.25 / 53,000) ~ 0.0022 per run.
  EXPECT_LT(*max - *min, 0.012);
  EXPECT_GT(*min, 0.0);
  EXPECT_LT(*max, 1.0);
  // The box is open at the front, the lamp hangs inside: a real mix of lit and hidden.
  EXPECT_GT(*min, 0.2);
  EXPECT_LT(*max, 0.8);
}

TEST(CornellBox, AllThreeViewpointsSeeMoreThanAnyOne) {
  const TriangleMesh mesh = read_obj(kCornellBox);
  Eigen::Vector3d lo, hi;
  mesh.bounds(lo, hi);
  MeshOcclusionOptions options;
  options.samples_per_unit_area = 500;
  const auto all = compute_mesh_occlusion(mesh, pattern_viewpoints(7, lo, hi), options);
  for (int single = 1; single <= 3; ++single) {
    const auto one = compute_mesh_occlusion(mesh, pattern_viewpoints(single, lo, hi), options);
    EXPECT_LE(all.occlusion_level, one.occlusion_level) << "pattern " << single;
  }
}

}  // namespace
}  // namespace occlusion
