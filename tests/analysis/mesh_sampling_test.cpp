#include "occlusion/analysis/mesh_sampling.hpp"

#include <gtest/gtest.h>

#include "support/scenes.hpp"

namespace occlusion {
namespace {

TEST(MeshSampling, CountsFollowAreaWithAtLeastOne) {
  EXPECT_EQ(samples_for_area(0.0001, 10), 1u);
  EXPECT_EQ(samples_for_area(1.0, 10), 10u);
  EXPECT_EQ(samples_for_area(2.26, 10), 23u);
}

TEST(MeshSampling, SamplesLieOnTheirFaces) {
  TriangleMesh mesh;
  testing::add_box(mesh, {0, 0, 0}, {1, 2, 3}, "box", 3);
  const MeshSamples samples = sample_mesh(mesh, 50, 1);
  ASSERT_EQ(samples.first.size(), mesh.face_count() + 1);
  ASSERT_EQ(samples.size(), samples.first.back());
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    EXPECT_EQ(samples.count_on(f), samples_for_area(mesh.face_area(f), 50));
    const Triangle tri = mesh.triangle(f);
    const Eigen::Vector3d n = (tri.v1 - tri.v0).cross(tri.v2 - tri.v0).cast<double>();
    for (std::size_t s = samples.first[f]; s < samples.first[f + 1]; ++s) {
      ASSERT_EQ(samples.face[s], f);
      // In the face's plane, and inside its bounding box.
      EXPECT_NEAR(n.normalized().dot(samples.points[s] - tri.v0.cast<double>()), 0.0, 1e-9);
      EXPECT_TRUE(tri.bounds().contains(samples.points[s].cast<float>()));
    }
  }
}

TEST(MeshSampling, SeedDecidesEverything) {
  TriangleMesh mesh;
  testing::add_box(mesh, {0, 0, 0}, {1, 1, 1}, "box", 2);
  const MeshSamples a = sample_mesh(mesh, 20, 9), b = sample_mesh(mesh, 20, 9);
  const MeshSamples c = sample_mesh(mesh, 20, 10);
  EXPECT_EQ(a.points, b.points);
  EXPECT_NE(a.points, c.points);
}

TEST(MeshSampling, RejectsNonPositiveDensity) {
  TriangleMesh mesh;
  testing::add_quad(mesh, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, "q");
  EXPECT_THROW(sample_mesh(mesh, 0, 0), std::invalid_argument);
  EXPECT_THROW(sample_mesh(mesh, -1, 0), std::invalid_argument);
  EXPECT_THROW(sample_mesh(mesh, NAN, 0), std::invalid_argument);
}

}  // namespace
}  // namespace occlusion
