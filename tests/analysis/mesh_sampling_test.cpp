#include "occlusion/analysis/mesh_sampling.hpp"

#include <gtest/gtest.h>

#include <atomic>

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

// One face of a coarse mesh can hold millions of samples (a 20 m^2 floor
// triangle at 1e5 per m^2): a cancel stops it within a block of samples, not
// at the next face. The cancel comes in the first progress report; the
// sampling must throw before it reports again.
TEST(MeshSampling, CancelStopsWithinALargeFace) {
  TriangleMesh one_face;
  one_face.vertices = {{0, 0, 0}, {10, 0, 0}, {0, 4, 0}};
  one_face.faces = {{0, 1, 2}};
  one_face.face_group = {0};
  one_face.group_names = {"floor"};
  std::atomic<bool> cancel{false};
  int reports = 0;
  double fraction_at_cancel = -1.0;
  Progress progress;
  progress.cancel = &cancel;
  progress.report = [&](const std::string& stage, double fraction) {
    EXPECT_EQ(stage, "sampling");
    ++reports;
    fraction_at_cancel = fraction;
    cancel = true;
  };
  EXPECT_THROW(sample_mesh(one_face, 1e5, 1, progress), Cancelled);
  EXPECT_EQ(reports, 1);
  EXPECT_GT(fraction_at_cancel, 0.0);
  EXPECT_LT(fraction_at_cancel, 0.1);  // 2e6 samples, checked every 65,536
  // Not cancelled, the same face is sampled whole.
  cancel = false;
  progress.report = nullptr;
  EXPECT_EQ(sample_mesh(one_face, 1e5, 1, progress).size(), 2'000'000u);
}

TEST(MeshSampling, RejectsNonPositiveDensity) {
  TriangleMesh mesh;
  testing::add_quad(mesh, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, "q");
  EXPECT_THROW(sample_mesh(mesh, 0, 0), std::invalid_argument);
  EXPECT_THROW(sample_mesh(mesh, -1, 0), std::invalid_argument);
  EXPECT_THROW(sample_mesh(mesh, NAN, 0), std::invalid_argument);
}

// A 10 cm box at 100 samples per square metre: one sample per face, a level
// that is rounding. The budget raises the density until the box gets at
// least min_samples, and no further.
TEST(MeshSampling, DensityIsRaisedToTheMinimumCount) {
  TriangleMesh box;
  testing::add_box(box, {0, 0, 0}, {0.1, 0.1, 0.1}, "box", 1);  // 12 faces, 0.06 m^2
  EXPECT_EQ(total_samples(box, 100), 12u);
  const double density = density_for_min_samples(box, 100, 6000);
  EXPECT_GE(total_samples(box, density), 6000u);
  EXPECT_LT(total_samples(box, density * (1 - 1e-6)), 6000u);  // the smallest such density
  // 12 half-squares of 0.005 m^2 need 500 samples each.
  EXPECT_NEAR(density, 99900, 100);  // round(0.005 d) >= 500 from d = 99,900
  EXPECT_EQ(total_samples(box, density), 6000u);

  // A density that already gives enough samples, or no minimum, is kept.
  EXPECT_EQ(density_for_min_samples(box, 2e6, 6000), 2e6);
  EXPECT_EQ(density_for_min_samples(box, 100, 0), 100);
  EXPECT_THROW(density_for_min_samples(box, 0, 10), std::invalid_argument);
}

}  // namespace
}  // namespace occlusion
