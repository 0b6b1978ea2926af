// Scenes far from the origin (UTM coordinates) and viewpoints far from the
// scene give the levels they give near it: rays are traced around the scene's
// centre and never longer than the scene can block.

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "occlusion/analysis/cloud_occlusion.hpp"
#include "occlusion/analysis/mesh_occlusion.hpp"
#include "occlusion/analysis/scan.hpp"
#include "support/scenes.hpp"

namespace occlusion {
namespace {

// A room with a wardrobe inside, all shifted by `shift`.
TriangleMesh room_at(const Eigen::Vector3d& shift) {
  TriangleMesh mesh;
  testing::add_box(mesh, shift, shift + Eigen::Vector3d(4, 3.5, 2.5), "room");
  testing::add_box(mesh, shift + Eigen::Vector3d(3.2, 0.5, 0.2),
                   shift + Eigen::Vector3d(3.7, 3.0, 2.0), "wardrobe");
  return mesh;
}

TEST(FarCoordinates, ShiftedSceneGivesTheSameLevels) {
  MeshOcclusionOptions options;
  options.samples_per_unit_area = 400.0;
  const std::vector<Eigen::Vector3d> viewpoints = {{1.0, 1.75, 1.5}, {2.5, 0.6, 1.0}};
  const MeshOcclusionResult here = compute_mesh_occlusion(room_at({0, 0, 0}), viewpoints, options);
  ASSERT_GT(here.occlusion_level, 0.05);  // the wardrobe hides a good part of the room

  const Eigen::Vector3d shift(5e6, -5e6, 1e3);  // a UTM northing and easting
  std::vector<Eigen::Vector3d> shifted_viewpoints;
  for (const auto& v : viewpoints) shifted_viewpoints.push_back(v + shift);
  const MeshOcclusionResult there =
      compute_mesh_occlusion(room_at(shift), shifted_viewpoints, options);
  EXPECT_NEAR(there.occlusion_level, here.occlusion_level, 1e-9);
  ASSERT_EQ(there.groups.size(), here.groups.size());
  for (std::size_t g = 0; g < here.groups.size(); ++g) {
    EXPECT_NEAR(there.groups[g].occlusion_level, here.groups[g].occlusion_level, 1e-9);
  }
  EXPECT_EQ(there.face_visible_fraction, here.face_visible_fraction);
}

// A closed unit cube seen from far along (+x, +y, +z): the three faces that
// look that way are visible, the three behind them are not, as far as float
// can trace from at this sampling (2^23 sample spacings, 1.9e5 here).
TEST(FarCoordinates, DistantViewpointDoesNotSeeThroughWalls) {
  TriangleMesh cube;
  testing::add_box(cube, {0, 0, 0}, {1, 1, 1}, "cube");
  MeshOcclusionOptions options;
  options.samples_per_unit_area = 2000.0;
  const Eigen::Vector3d direction(1.0, 0.7, 0.4);
  for (const double distance : {10.0, 1e5}) {
    const MeshOcclusionResult result =
        compute_mesh_occlusion(cube, {direction * distance}, options);
    EXPECT_NEAR(result.occlusion_level, 0.5, 2e-3) << "viewpoint at " << distance;
  }
}

// Farther, rays that graze a face hit or miss by rounding: the unit cube
// seen from (1e10, 0.3, 0.7) answered 0.805 where 5/6 of it is hidden. Mesh
// occlusion refuses such viewpoints by the rule the cloud analyses use.
TEST(FarCoordinates, MeshOcclusionRefusesViewpointsBeyondFloatsReach) {
  TriangleMesh cube;
  testing::add_box(cube, {0, 0, 0}, {1, 1, 1}, "cube");
  MeshOcclusionOptions options;
  options.samples_per_unit_area = 100.0;
  EXPECT_NEAR(compute_mesh_occlusion(cube, {{10, 0.3, 0.7}}, options).occlusion_level, 5.0 / 6.0,
              1e-3);
  for (const double distance : {1e7, 1e10, 1e20, 1e30}) {
    try {
      compute_mesh_occlusion(cube, {{distance, 0.3, 0.7}}, options);
      ADD_FAILURE() << "no error for a viewpoint at " << distance;
    } catch (const std::invalid_argument& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find("mesh occlusion: a viewpoint lies"), std::string::npos) << message;
      EXPECT_NE(message.find("the mesh's centre"), std::string::npos) << message;
    }
  }
  // Far from the origin, the distance counts from the mesh: a box 5e6 out
  // and a viewpoint beside it are fine.
  TriangleMesh shifted;
  testing::add_box(shifted, {5e6, 0, 0}, {5e6 + 1, 1, 1}, "cube");
  EXPECT_NEAR(compute_mesh_occlusion(shifted, {{5e6 + 10, 0.3, 0.7}}, options).occlusion_level,
              5.0 / 6.0, 1e-3);
}

// From far away, rays that graze the faces lying along them hit or miss by
// rounding within distance x 2^-23 of those faces' edges: a 5 x 5 x 3 box
// seen from x = 1e7 answered another level than from x = 10 (0.8771 against
// 0.8837 in issue 44), well inside the reach above. Refused wherever that band
// is wider than the samples are apart; nearer, the level moves by a sample or
// so, as sampling itself does.
TEST(FarCoordinates, MeshOcclusionRefusesWhereRoundingWouldMoveTheLevelMoreThanSampling) {
  TriangleMesh box;
  testing::add_box(box, {0, 0, 0}, {5, 5, 3}, "box");
  MeshOcclusionOptions options;
  options.samples_per_unit_area = 100.0;  // samples 0.1 apart: refused beyond 2^23 x 0.1
  const double near = compute_mesh_occlusion(box, {{10, 1.7, 1.1}}, options).occlusion_level;
  // Within the reach, the level moves by no more than a sample or two of 11,000.
  EXPECT_NEAR(compute_mesh_occlusion(box, {{1e5, 1.7, 1.1}}, options).occlusion_level, near,
              2.0 / 11000);
  for (const double distance : {1e6, 1e7}) {
    try {
      const double level =
          compute_mesh_occlusion(box, {{distance, 1.7, 1.1}}, options).occlusion_level;
      ADD_FAILURE() << "no error for a viewpoint at " << distance << ": " << level << " against "
                    << near;
    } catch (const std::invalid_argument& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find("mesh occlusion: a viewpoint lies"), std::string::npos) << message;
      EXPECT_NE(message.find("more than the samples are apart"), std::string::npos) << message;
      EXPECT_NE(message.find("lower samples_per_unit_area"), std::string::npos) << message;
    }
  }
  // Sampling that resolves less is answered from farther.
  options.samples_per_unit_area = 1.0;
  const double coarse = compute_mesh_occlusion(box, {{10, 1.7, 1.1}}, options).occlusion_level;
  EXPECT_NEAR(compute_mesh_occlusion(box, {{1e6, 1.7, 1.1}}, options).occlusion_level, coarse,
              2.0 / 110);
}

// Clouds are traced in float where they lie: where float cannot resolve a
// point's sphere, the analyses refuse instead of answering wrongly.
TEST(FarCoordinates, CloudAnalysesRefuseWherePrecisionCannotHold) {
  PointCloud cloud;
  for (int i = 0; i < 10; ++i) cloud.positions.push_back(Eigen::Vector3f(0.1f * i, 0, 0));
  CloudOcclusionOptions occlusion;
  occlusion.num_rays_per_vp = 100;
  ScanOptions scan;
  const std::vector<Eigen::Vector3d> near = {{0.5, 1, 0}};
  EXPECT_NO_THROW(compute_cloud_occlusion(cloud, near, {}, occlusion));
  EXPECT_NO_THROW(scan_cloud(cloud, near, scan));
  const std::vector<Eigen::Vector3d> far = {{1e20, 0, 0}};
  EXPECT_THROW(compute_cloud_occlusion(cloud, far, {}, occlusion), std::invalid_argument);
  EXPECT_THROW(scan_cloud(cloud, far, scan), std::invalid_argument);

  PointCloud shifted = cloud;
  for (auto& p : shifted.positions) p.y() += 5e6f;  // 0.5 units apart there
  const std::vector<Eigen::Vector3d> shifted_near = {{0.5, 5e6 + 1, 0}};
  EXPECT_THROW(compute_cloud_occlusion(shifted, shifted_near, {}, occlusion),
               std::invalid_argument);
}

}  // namespace
}  // namespace occlusion
